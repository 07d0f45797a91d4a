/* Tokens of the formula language. Numbers are converted without the C
 * locale: the digits are rewritten as an integer mantissa and a decimal
 * exponent ("12345e-3"), which strtod reads the same in every locale. */
#include "expr_internal.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>

#define MAX_SIGNIFICANT 40 /* digits kept; more cannot change a double */

static ic_token lex_number(const char *src, int pos, ic_error *err)
{
    ic_token t = {TOK_NUMBER, pos, 0, 0.0};
    char digits[MAX_SIGNIFICANT + 1];
    int nd = 0, ndigits_seen = 0;
    long exp10 = 0;
    int i = pos;
    for (; isdigit((unsigned char)src[i]); i++, ndigits_seen++) {
        if (nd == 0 && src[i] == '0')
            continue; /* leading zeros */
        if (nd < MAX_SIGNIFICANT)
            digits[nd++] = src[i];
        else
            exp10++;
    }
    if (src[i] == '.') {
        for (i++; isdigit((unsigned char)src[i]); i++, ndigits_seen++) {
            if (nd == 0 && src[i] == '0') {
                exp10--;
                continue;
            }
            if (nd < MAX_SIGNIFICANT) {
                digits[nd++] = src[i];
                exp10--;
            }
        }
    }
    if (ndigits_seen == 0) {
        ic_error_set(err, IC_ERR_PARSE, pos + 1, "malformed number: '.' without digits");
        t.kind = TOK_ERROR;
        return t;
    }
    if (src[i] == 'e' || src[i] == 'E') {
        int j = i + 1, sign = 1;
        if (src[j] == '+' || src[j] == '-')
            sign = src[j++] == '-' ? -1 : 1;
        if (!isdigit((unsigned char)src[j])) {
            ic_error_set(err, IC_ERR_PARSE, pos + 1,
                         "malformed number '%.*s': the exponent has no digits", j - pos,
                         src + pos);
            t.kind = TOK_ERROR;
            return t;
        }
        long e = 0;
        for (; isdigit((unsigned char)src[j]); j++)
            if (e < 100000)
                e = e * 10 + (src[j] - '0');
        exp10 += sign * e;
        i = j;
    }
    if (isalpha((unsigned char)src[i]) || src[i] == '_' || src[i] == '.') {
        ic_error_set(err, IC_ERR_PARSE, pos + 1, "malformed number '%.*s'", i - pos + 1,
                     src + pos);
        t.kind = TOK_ERROR;
        return t;
    }
    t.length = i - pos;
    if (nd == 0) {
        t.value = 0.0;
        return t;
    }
    char buf[MAX_SIGNIFICANT + 32];
    snprintf(buf, sizeof buf, "%.*se%ld", nd, digits, exp10);
    t.value = strtod(buf, NULL);
    return t;
}

ic_token ic_lex(const char *src, int pos, ic_error *err)
{
    while (src[pos] == ' ' || src[pos] == '\t' || src[pos] == '\n' || src[pos] == '\r')
        pos++;
    ic_token t = {TOK_END, pos, 0, 0.0};
    const char c = src[pos];
    if (c == '\0')
        return t;
    if (isdigit((unsigned char)c) || c == '.')
        return lex_number(src, pos, err);
    if (isalpha((unsigned char)c) || c == '_') {
        int i = pos;
        while (isalnum((unsigned char)src[i]) || src[i] == '_')
            i++;
        t.kind = TOK_NAME;
        t.length = i - pos;
        return t;
    }
    t.length = 1;
    switch (c) {
    case '+': t.kind = TOK_PLUS; break;
    case '-': t.kind = TOK_MINUS; break;
    case '*': t.kind = TOK_STAR; break;
    case '/': t.kind = TOK_SLASH; break;
    case '^': t.kind = TOK_CARET; break;
    case '(': t.kind = TOK_LPAREN; break;
    case ')': t.kind = TOK_RPAREN; break;
    case ',': t.kind = TOK_COMMA; break;
    default:
        t.kind = TOK_ERROR;
        if (isprint((unsigned char)c))
            ic_error_set(err, IC_ERR_PARSE, pos + 1, "unexpected character '%c'", c);
        else
            ic_error_set(err, IC_ERR_PARSE, pos + 1, "unexpected byte 0x%02x",
                         (unsigned)(unsigned char)c);
    }
    return t;
}

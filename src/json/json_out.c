/* JSON documents streamed in cJSON_Print's layout (json_out.h). */
#include "json/json_out.h"

#include <math.h>
#include <string.h>

#include "json/json_number.h"

void ic_json_out_start(json_out *j, FILE *f)
{
    j->f = f;
    j->depth = 0;
    j->arrays = j->nonempty = 0;
    j->len = 0;
}

static void flush(json_out *j)
{
    fwrite(j->buf, 1, j->len, j->f);
    j->len = 0;
}

static void put(json_out *j, const char *s, size_t n)
{
    if (j->len + n > sizeof j->buf)
        flush(j);
    if (n > sizeof j->buf) {
        fwrite(s, 1, n, j->f);
        return;
    }
    memcpy(j->buf + j->len, s, n);
    j->len += n;
}

static void put_char(json_out *j, char c)
{
    if (j->len == sizeof j->buf)
        flush(j);
    j->buf[j->len++] = c;
}

static unsigned long level_bit(const json_out *j)
{
    return 1UL << (j->depth < IC_JSON_OUT_MAX_DEPTH ? j->depth : IC_JSON_OUT_MAX_DEPTH - 1);
}

/* Before a value: in an array, ", " after its first item. */
static void before_value(json_out *j)
{
    const unsigned long bit = level_bit(j);
    if (!(j->arrays & bit))
        return;
    if (j->nonempty & bit)
        put(j, ", ", 2);
    j->nonempty |= bit;
}

static void tabs(json_out *j, int n)
{
    for (int i = 0; i < n; i++)
        put_char(j, '\t');
}

/* The escape of character c, or NULL where it stands for itself. */
static const char *escape(unsigned char c, char code[8])
{
    switch (c) {
    case '"': return "\\\"";
    case '\\': return "\\\\";
    case '\b': return "\\b";
    case '\f': return "\\f";
    case '\n': return "\\n";
    case '\r': return "\\r";
    case '\t': return "\\t";
    default:
        if (c >= 32)
            return NULL;
        snprintf(code, 8, "\\u%04x", c);
        return code;
    }
}

/* A string between quotes, escaped. */
static void quoted(json_out *j, const char *s)
{
    put_char(j, '"');
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        char code[8];
        const char *e = escape(*c, code);
        if (e)
            put(j, e, strlen(e));
        else
            put_char(j, (char)*c);
    }
    put_char(j, '"');
}

void ic_json_out_key(json_out *j, const char *key)
{
    const unsigned long bit = level_bit(j);
    if (j->nonempty & bit)
        put(j, ",\n", 2);
    j->nonempty |= bit;
    tabs(j, j->depth);
    quoted(j, key);
    put(j, ":\t", 2);
}

/* Into a new level: an object's or an array's. */
static void open_level(json_out *j, int array)
{
    j->depth++;
    const unsigned long bit = level_bit(j);
    j->nonempty &= ~bit;
    if (array)
        j->arrays |= bit;
    else
        j->arrays &= ~bit;
}

void ic_json_out_object(json_out *j)
{
    before_value(j);
    put(j, "{\n", 2);
    open_level(j, 0);
}

void ic_json_out_end_object(json_out *j)
{
    if (j->nonempty & level_bit(j))
        put_char(j, '\n');
    j->depth--;
    tabs(j, j->depth);
    put_char(j, '}');
}

void ic_json_out_array(json_out *j)
{
    before_value(j);
    put_char(j, '[');
    open_level(j, 1);
}

void ic_json_out_end_array(json_out *j)
{
    j->depth--;
    put_char(j, ']');
}

void ic_json_out_number(json_out *j, double x)
{
    before_value(j);
    if (!isfinite(x)) {
        put(j, "null", 4);
        return;
    }
    char text[IC_JSON_NUMBER_MAX];
    put(j, text, ic_json_number_text(text, x));
}

void ic_json_out_int(json_out *j, int x)
{
    before_value(j);
    char text[16];
    put(j, text, (size_t)snprintf(text, sizeof text, "%d", x));
}

void ic_json_out_string(json_out *j, const char *s)
{
    before_value(j);
    if (s)
        quoted(j, s);
    else
        put(j, "null", 4);
}

void ic_json_out_bool(json_out *j, int b)
{
    before_value(j);
    if (b)
        put(j, "true", 4);
    else
        put(j, "false", 5);
}

void ic_json_out_null(json_out *j)
{
    before_value(j);
    put(j, "null", 4);
}

void ic_json_out_vector(json_out *j, const double *v, int n)
{
    ic_json_out_array(j);
    for (int i = 0; i < n; i++)
        ic_json_out_number(j, v[i]);
    ic_json_out_end_array(j);
}

void ic_json_out_ints(json_out *j, const int *v, int n)
{
    ic_json_out_array(j);
    for (int i = 0; i < n; i++)
        ic_json_out_int(j, v[i]);
    ic_json_out_end_array(j);
}

ic_status ic_json_out_finish(json_out *j, const char *what, ic_error *err)
{
    put_char(j, '\n');
    flush(j);
    if (ferror(j->f))
        return ic_error_set(err, IC_ERR_IO, 0, "writing the %s output failed", what);
    return IC_OK;
}

/* libFuzzer target: a certificate file (docs/output-formats.md, "The
 * certificate file") from arbitrary bytes, replayed against a fixed problem
 * (a sphere cut by a plane in a circle) with a trace document that claims
 * no curve at all. The reader and the replay may refuse the bytes, but with
 * a status and a message; and since the circle is there and untraced, no
 * file whatever may make the check accept: an accepted verdict is a proof
 * that is not one, and aborts. Everything is freed (LeakSanitizer runs). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve/bindings.h"
#include "intercurve/problem.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char PROBLEM[] =
    "{\"surfaces\": [{\"name\": \"sphere\", \"type\": \"implicit\", \"f\": \"x^2 + y^2 + z^2 - 1\"},"
    " {\"name\": \"plane\", \"type\": \"implicit\", \"f\": \"z - 0.3\"}],"
    " \"box\": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]}";

static const char NO_CURVES[] = "{\"curves\": [], \"points\": []}";

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = 0;
    ic_problem *p = NULL;
    ic_error err;
    if (ic_problem_parse(&p, PROBLEM, sizeof PROBLEM - 1, &err) != IC_OK)
        abort();
    ic_trace_certificate c;
    const ic_status st = ic_problem_verify_certificate(p, NO_CURVES, text, &c, &err);
    if (st != IC_OK && (err.code != st || err.message[0] == '\0'))
        abort();
    if (st == IC_OK && c.accepted)
        abort(); /* the circle is not traced: nothing may prove this complete */
    ic_problem_free(p);
    free(text);
    return 0;
}

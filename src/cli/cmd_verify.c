/* intercurve verify: a saved trace checked again without the tracer
 * (docs/tracing.md, "The certificate"; docs/cli.md). */
#include "cli/cli.h"
#include "api/api.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

enum { OPT_TRACE, OPT_CERTIFICATE, NOPTIONS };

static const ic_cli_option VERIFY_OPTIONS[NOPTIONS] = {
    [OPT_TRACE] = {.name = "--trace",
                   .metavar = "TRACE.json",
                   .kind = IC_OPT_TEXT,
                   .need = IC_OPT_REQUIRED,
                   .help = "the trace document to check (intercurve trace PROBLEM.json -o "
                           "TRACE.json)"},
    [OPT_CERTIFICATE] = {.name = "--certificate",
                         .metavar = "CERT.json",
                         .kind = IC_OPT_TEXT,
                         .help = "replays this certificate file's cover (intercurve trace\n"
                                 "--certificate CERT.json) instead of growing one: its splits are\n"
                                 "taken, every leaf is proven again and must be what the file\n"
                                 "says (docs/tracing.md, \"The certificate file\")"},
};

static const ic_cli_command VERIFY = {
    .name = "verify",
    .file = "PROBLEM.json",
    .summary = "Checks a trace document against its problem without the tracer: a cover of\n"
               "the search region by cells proven empty or crossed by known arcs, grown\n"
               "afresh from the surfaces, and every arc traced exactly once by the\n"
               "document's curves (docs/tracing.md, \"The certificate\"). Prints \"proven\" or\n"
               "\"not proven\" with the reason. Exit status 0 proven, 2 not proven, 1 bad input.",
    .options = VERIFY_OPTIONS,
    .noptions = NOPTIONS,
    .notes = "example:\n"
             "  intercurve trace examples/cylinders.json -o cylinders.trace.json\n"
             "  intercurve verify examples/cylinders.json --trace cylinders.trace.json\n"
             "  intercurve trace examples/cylinders.json -o t.json --certificate c.json\n"
             "  intercurve verify examples/cylinders.json --trace t.json --certificate c.json\n",
};

/* The whole file as a string (the caller frees it); NULL after the reason. */
static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "intercurve verify: cannot open %s: %s\n", path, strerror(errno));
        return NULL;
    }
    size_t n = 0, cap = 1 << 16;
    char *s = malloc(cap);
    while (s) {
        n += fread(s + n, 1, cap - 1 - n, f);
        if (n < cap - 1)
            break;
        char *t = realloc(s, cap *= 2);
        if (!t)
            free(s);
        s = t;
    }
    const int bad = ferror(f);
    fclose(f);
    if (!s || bad) {
        fprintf(stderr, "intercurve verify: cannot read %s: %s\n", path,
                s ? "a read error" : "out of memory");
        free(s);
        return NULL;
    }
    s[n] = 0;
    return s;
}

int ic_cmd_verify(int argc, char **argv)
{
    const char *file;
    ic_cli_value v[NOPTIONS];
    int rc = ic_cli_parse(&VERIFY, argc, argv, &file, v);
    if (rc != 0)
        return rc == IC_CLI_HELP ? 0 : rc;
    ic_problem *p = NULL;
    if ((rc = ic_cli_load_problem(&p, file, 0)) != 0)
        return rc;
    const char *cert_path = v[OPT_CERTIFICATE].text;
    char *doc = read_text(v[OPT_TRACE].text);
    char *cert = doc && cert_path ? read_text(cert_path) : NULL;
    if (!doc || (cert_path && !cert)) {
        free(doc);
        ic_problem_free(p);
        return EXIT_INPUT;
    }
    ic_error err;
    ic_error_clear(&err);
    ic_trace_certificate c;
    const ic_status st = ic_api_verify(p, doc, v[OPT_TRACE].text, cert, cert_path, &c, &err);
    free(doc);
    free(cert);
    ic_problem_free(p);
    if (st != IC_OK) {
        fprintf(stderr, "intercurve verify: %s\n", err.message);
        return st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
    }
    printf("%s: %ld cells (%ld empty, %ld outside, %ld diagonal, %ld regular, %ld singular, "
           "%ld tangential), %ld crossings, %ld arcs, boxes at %d poles and %d corners%s%s\n",
           c.accepted ? "proven" : "not proven", c.cells, c.empty, c.outside, c.diagonal,
           c.regular, c.singular, c.tangential, c.crossings, c.arcs, c.poles, c.corners,
           c.accepted ? "" : ": ", c.accepted ? "" : c.reason);
    return c.accepted ? 0 : EXIT_COMPUTE;
}

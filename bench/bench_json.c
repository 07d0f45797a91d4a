/* Benchmark of the trace document's writer (make bench): each example is
 * traced and fitted as `intercurve trace` does (tolerance 1e-11, fit
 * tolerance 1e-9), then ic_trace_write_json writes its document to a memory
 * stream again and again; the row gives the document's size, ms of
 * processor time per document and MB/s (usage: bench_json [EXAMPLES_DIR [EXAMPLE.json...]]). */
#include <stdio.h>
#include <stdlib.h>

#include <math.h>
#include <time.h>

#include "intercurve.h"

/* the command's default truncation tolerance (docs/cli.md, trace), relative */
#define TRACE_TOL 1e-11

/* repetitions per batch, batches (the best one counts) */
#define REPS 20
#define BATCHES 7

typedef struct {
    FILE *f;
    const ic_trace_result *res;
    const ic_pair *pair;
} job;

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* ns of processor time per document, the best batch (the machine may be
 * shared: processor time, not wall time); NaN if a write failed. */
static double ns_per_document(job *j)
{
    double best = INFINITY;
    for (int b = 0; b < BATCHES; b++) {
        const double t0 = cpu_seconds();
        for (int r = 0; r < REPS; r++) {
            rewind(j->f);
            if (ic_trace_write_json(j->f, j->res, j->pair, NULL) != IC_OK)
                return NAN;
        }
        best = fmin(best, (cpu_seconds() - t0) * 1e9 / REPS);
    }
    return best;
}

/* The document's size in bytes, or -1 when it cannot be written. */
static long document_size(const ic_trace_result *res, const ic_pair *pair)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return -1;
    const int ok = ic_trace_write_json(f, res, pair, NULL) == IC_OK;
    fclose(f);
    free(text);
    return ok ? (long)len : -1;
}

/* The writer's time on an example traced and fitted; prints its row. */
static int time_writer(const char *name, const ic_trace_result *res, const ic_pair *pair)
{
    const long size = document_size(res, pair);
    char *buffer = size > 0 ? malloc((size_t)size + 1) : NULL;
    FILE *f = buffer ? fmemopen(buffer, (size_t)size + 1, "w") : NULL;
    int rc = 1;
    if (f) {
        job j = {f, res, pair};
        const double ns = ns_per_document(&j);
        if (ns == ns) { /* not NaN: every write succeeded */
            printf("%-28s %9ld %10.3f %9.1f\n", name, size, ns * 1e-6, size / (ns * 1e-9) / 1e6);
            rc = 0;
        }
        fclose(f);
    }
    free(buffer);
    if (rc)
        fprintf(stderr, "%s: the document could not be written\n", name);
    return rc;
}

static int example(const char *dir, const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *r = NULL;
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.tol = TRACE_TOL;
    int rc = 1;
    if (ic_problem_load(&p, path, &err) != IC_OK) {
        fprintf(stderr, "%s: %s\n", path, err.message);
        return 1;
    }
    opt.has_box = ic_problem_box(p, opt.box);
    const int self = ic_problem_is_self(p);
    if (ic_pair_new(&pair, ic_problem_surface(p, 0), self ? NULL : ic_problem_surface(p, 1),
                    &err) != IC_OK ||
        ic_trace(&r, pair, &opt, &err) != IC_OK || ic_trace_fit(r, pair, IC_TRACE_FIT_TOL_DEFAULT, &err) != IC_OK)
        fprintf(stderr, "%s: %s\n", path, err.message);
    else
        rc = time_writer(name, r, pair);
    ic_trace_result_free(r);
    ic_pair_free(pair);
    ic_problem_free(p);
    return rc;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "examples";
    static const char *const names[] = {"cylinders.json", "viviani-implicit.json",
                                        "torus-sphere.json", "nurbs-patch-sphere.json",
                                        "tacnode.json"};
    printf("ic_trace_write_json to a memory stream (processor time, best of %d x %d)\n",
           BATCHES, REPS);
    printf("%-28s %9s %10s %9s\n", "example", "bytes", "ms/doc", "MB/s");
    int rc = 0;
    if (argc > 2) /* the examples named */
        for (int i = 2; i < argc; i++)
            rc |= example(dir, argv[i]);
    else
        for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
            rc |= example(dir, names[i]);
    return rc;
}

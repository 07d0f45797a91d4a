/* A trace is the same whatever its number of threads (docs/tracing.md,
 * "Threads"): every bundled example, every NURBS problem of tests/data/nurbs,
 * the cheap problems of the torture set and a few deeper searches (where the
 * open cells' refinement dominates) traced in 1, 2, 3 and 8 threads give
 * trace documents identical byte for byte; a time limit still stops a
 * threaded trace, the progress callback is called from the calling thread
 * only, and a thread count out of range is refused. */
#include "harness.h"
#include "intercurve.h"
#include "traced_example.h"

#include <dirent.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const int THREADS[] = {2, 3, 8}; /* each against 1 */
#define NTHREADS (int)(sizeof THREADS / sizeof THREADS[0])

/* torture problems of a few seconds or more in a debug build: their
 * threads are compared by hand (docs/performance.md, "Threads") */
static const char *const SLOW_TORTURE[] = {"eggcrate", "whitney", "overflow", "tangent-",
                                           "near-", "contact-", "seam-", "scale-"};

/* The trace document of a problem file at the options given; NULL after a
 * failed check. */
static char *document(const char *path, ic_trace_options opt)
{
    traced t;
    char *doc = NULL;
    if (trace_file_with(&t, path, opt) == 0) {
        ic_error err;
        CHECK(ic_trace_json_alloc(&doc, NULL, t.res, t.pair, &err) == IC_OK, "%s: %s", path,
              err.message);
    }
    release(&t);
    return doc;
}

/* The file traced in 1 thread and in each of THREADS: the same documents. */
static void compare(const char *path, ic_trace_options opt, const char *how)
{
    opt.threads = 1;
    char *one = document(path, opt);
    for (int k = 0; one && k < NTHREADS; k++) {
        opt.threads = THREADS[k];
        char *many = document(path, opt);
        CHECK(many && strcmp(one, many) == 0, "%s%s: %d threads give another document than 1",
              path, how, THREADS[k]);
        ic_free(many);
    }
    ic_free(one);
}

static int slow(const char *name)
{
    for (size_t i = 0; i < sizeof SLOW_TORTURE / sizeof *SLOW_TORTURE; i++)
        if (strstr(name, SLOW_TORTURE[i]))
            return 1;
    return 0;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every .json of dir whose name starts with prefix (and is not slow) at
 * the default options; how many. */
static int compare_dir(const char *dir, const char *prefix)
{
    DIR *d = opendir(dir);
    CHECK(d != NULL, "cannot open %s", dir);
    if (!d)
        return 0;
    char *names[256];
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) && n < 256;) {
        const size_t len = strlen(e->d_name);
        if (len > 5 && strcmp(e->d_name + len - 5, ".json") == 0 &&
            strncmp(e->d_name, prefix, strlen(prefix)) == 0 && !slow(e->d_name))
            names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, by_name);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    /* the checker runs on one thread after the search, from the curves
     * alone: the same curves give the same verdict (test_certificate*.c
     * prove them), and it is most of the time under the sanitizers */
    opt.certify = 0;
    for (int i = 0; i < n; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        compare(path, opt, "");
        free(names[i]);
    }
    return n;
}

/* Searches where the refinement of open cells and the first search's
 * subtrees are most of the work. */
static void compare_deep(const char *src)
{
    static const struct {
        const char *file;
        int depth, exact;
    } CASES[] = {
        {"examples/torus-sphere.json", 7, 0},
        {"tests/data/nurbs/problem-torus-sphere-tangential.json", 7, 1},
    };
    for (size_t i = 0; i < sizeof CASES / sizeof *CASES; i++) {
        char path[1024], how[64];
        snprintf(path, sizeof path, "%s/%s", src, CASES[i].file);
        snprintf(how, sizeof how, " (depth %d, exact paths %d)", CASES[i].depth, CASES[i].exact);
        ic_trace_options opt;
        ic_trace_defaults(&opt);
        opt.depth = CASES[i].depth;
        opt.exact_paths = CASES[i].exact;
        opt.certify = 0; /* as above */
        compare(path, opt, how);
    }
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct {
    pthread_t caller;
    int calls, elsewhere;
} progress_seen;

static void on_progress(void *user, const char *stage, long done, long total)
{
    (void)stage, (void)done, (void)total;
    progress_seen *p = user;
    p->calls++;
    p->elsewhere += !pthread_equal(pthread_self(), p->caller);
}

/* A deep search in 2 threads under a time limit of 0.3 s: it stops soon
 * after, incomplete, and says why; the progress reports came from the
 * calling thread. */
static void time_limit(const char *src)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/torus-sphere.json", src);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.depth = 9;
    opt.exact_paths = 0;
    opt.threads = 2;
    opt.time_limit = 0.3;
    progress_seen seen = {pthread_self(), 0, 0};
    opt.progress = on_progress;
    opt.progress_user = &seen;
    const double t0 = now();
    traced t;
    if (trace_file_with(&t, path, opt) == 0) {
        const double took = now() - t0;
        const ic_trace_report *rep = ic_trace_result_report(t.res);
        CHECK(took < 10 * opt.time_limit + 2, "a 0.3 s limit took %.2f s in 2 threads", took);
        CHECK(!rep->tracer_complete, "stopped at the time limit, yet complete");
        int said = 0;
        for (int i = 0; i < rep->nfailures; i++)
            said |= strstr(rep->failures[i], "time limit") != NULL;
        CHECK(said, "the report does not say the time limit stopped it");
    }
    CHECK(seen.elsewhere == 0, "%d of %d progress reports from another thread", seen.elsewhere,
          seen.calls);
    release(&t);
}

/* threads outside 0..IC_TRACE_MAX_THREADS: IC_ERR_INVALID naming it. */
static void bad_counts(const char *src)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/viviani.json", src);
    ic_problem *p = NULL;
    ic_error err;
    if (ic_problem_load(&p, path, &err) != IC_OK) {
        CHECK(0, "%s: %s", path, err.message);
        return;
    }
    ic_pair *pair = NULL;
    CHECK(ic_pair_new(&pair, ic_problem_surface(p, 0), ic_problem_surface(p, 1), &err) == IC_OK,
          "pair: %s", err.message);
    const int bad[] = {-1, IC_TRACE_MAX_THREADS + 1};
    for (int k = 0; pair && k < 2; k++) {
        ic_trace_options opt;
        ic_trace_defaults(&opt);
        opt.threads = bad[k];
        ic_trace_result *res = NULL;
        const ic_status st = ic_trace(&res, pair, &opt, &err);
        CHECK(st == IC_ERR_INVALID && !res && strstr(err.message, "threads"),
              "threads %d: status %d (%s)", bad[k], st, err.message);
        ic_trace_result_free(res);
    }
    ic_pair_free(pair);
    ic_problem_free(p);
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/examples", src);
    const int examples = compare_dir(dir, "");
    snprintf(dir, sizeof dir, "%s/tests/data/nurbs", src);
    const int nurbs = compare_dir(dir, "problem-");
    snprintf(dir, sizeof dir, "%s/tests/torture", src);
    const int torture = compare_dir(dir, "");
    CHECK(examples >= 17 && nurbs >= 17 && torture >= 5,
          "only %d examples, %d NURBS problems, %d torture problems compared", examples, nurbs,
          torture);
    compare_deep(src);
    time_limit(src);
    bad_counts(src);
    return harness_finish("test_trace_threads");
}

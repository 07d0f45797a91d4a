/* The library is thread-safe for separate problems (bindings.h, "Threads";
 * docs/python.md): the bundled examples traced (each in threads of its own,
 * threads 0: docs/tracing.md, "Threads") and fitted in pthreads all at
 * once, two copies of each loaded separately, three rounds, give trace documents
 * identical, byte for byte, to the ones traced one after the other in one
 * thread; and points analysed at once equal the single-threaded ones. */
#include "harness.h"
#include "intercurve.h"

#include <pthread.h>
#include <string.h>

#define COPIES 2 /* each problem traced in this many threads at once */
#define ROUNDS 3 /* of all the threads at once: a race shows in some rounds only */
#define FIT_TOL 1e-9 /* relative, --fit-tol's default: the documents carry B-splines */
#define TRACE_TOL 1e-10 /* relative */
#define DEPTH 5

static const char *const EXAMPLES[] = {
    "viviani-implicit.json", "viviani.json", "ellipsoids.json", "cusp.json",
    "tacnode.json", "sphere-cylinder-branch.json", "small-loop.json", "cylinders.json",
};
#define NEXAMPLES (int)(sizeof EXAMPLES / sizeof EXAMPLES[0])

/* One job: a problem file traced (and a point of Viviani's curve analysed
 * on the viviani ones) into documents. */
typedef struct {
    char path[512];
    char *trace_doc;
    char *point_doc;
    ic_status status;
    char message[IC_ERROR_MESSAGE_LEN];
} job;

static void *run_job(void *arg)
{
    job *j = arg;
    ic_error err;
    ic_error_clear(&err);
    ic_problem *p = NULL;
    ic_trace_result *res = NULL;
    ic_pair *pair = NULL;
    ic_status st = ic_problem_load(&p, j->path, &err);
    if (st == IC_OK)
        st = ic_problem_trace(&res, &pair, p, TRACE_TOL, DEPTH, 0, 0, FIT_TOL, &err);
    if (st == IC_OK)
        st = ic_trace_json_alloc(&j->trace_doc, NULL, res, pair, &err);
    if (st == IC_OK && strstr(j->path, "viviani")) {
        const double at[3] = {1.5, 0.8660254037844386, 1};
        st = ic_problem_point_json(&j->point_doc, NULL, p, at, 3, 0, 8, "auto", 1e-6, &err);
    }
    j->status = st;
    snprintf(j->message, sizeof j->message, "%s", err.message);
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_problem_free(p);
    return NULL;
}

static void job_free(job *j)
{
    ic_free(j->trace_doc);
    ic_free(j->point_doc);
}

static void init_job(job *j, const char *src, int e)
{
    memset(j, 0, sizeof *j);
    snprintf(j->path, sizeof j->path, "%s/examples/%s", src, EXAMPLES[e]);
}

/* 1 when both documents are absent or both equal. */
static int same(const char *a, const char *b)
{
    return (!a && !b) || (a && b && strcmp(a, b) == 0);
}

/* Every example COPIES times in threads at once, each compared with its
 * single-threaded documents. */
static void run_parallel(const char *src, const job serial[NEXAMPLES], int round)
{
    static job parallel[NEXAMPLES][COPIES];
    pthread_t threads[NEXAMPLES][COPIES];
    int started[NEXAMPLES][COPIES] = {{0}};
    for (int e = 0; e < NEXAMPLES; e++)
        for (int c = 0; c < COPIES; c++) {
            init_job(&parallel[e][c], src, e);
            started[e][c] = pthread_create(&threads[e][c], NULL, run_job, &parallel[e][c]) == 0;
            CHECK(started[e][c], "%s: thread %d not started", EXAMPLES[e], c);
        }
    for (int e = 0; e < NEXAMPLES; e++)
        for (int c = 0; c < COPIES; c++) {
            if (!started[e][c])
                continue;
            pthread_join(threads[e][c], NULL);
            job *j = &parallel[e][c];
            CHECK(j->status == IC_OK, "%s copy %d: %s", EXAMPLES[e], c, j->message);
            CHECK(same(j->trace_doc, serial[e].trace_doc),
                  "round %d, %s copy %d: the trace differs from the single-threaded one", round,
                  EXAMPLES[e], c);
            CHECK(same(j->point_doc, serial[e].point_doc),
                  "round %d, %s copy %d: the point differs from the single-threaded one", round,
                  EXAMPLES[e], c);
            job_free(j);
        }
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    static job serial[NEXAMPLES];
    for (int e = 0; e < NEXAMPLES; e++) {
        init_job(&serial[e], src, e);
        run_job(&serial[e]);
        CHECK(serial[e].status == IC_OK && serial[e].trace_doc &&
                  strstr(serial[e].trace_doc, "\"curves\""),
              "%s: serial trace: %s", EXAMPLES[e], serial[e].message);
    }
    for (int round = 0; round < ROUNDS; round++)
        run_parallel(src, serial, round);
    CHECK(serial[0].point_doc && strstr(serial[0].point_doc, "\"transversal\""),
          "the point of Viviani's curve analysed");
    for (int e = 0; e < NEXAMPLES; e++)
        job_free(&serial[e]);
    return harness_finish("threads");
}

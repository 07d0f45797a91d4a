/* Benchmark of the torture set (make bench): every case of
 * tests/truth/torture_truth.txt, including the benchmark-only egg crate
 * z = 0.1 sin(100x) sin(100y) against z = 0.05 (7938 loops), traced whole
 * with the defaults and time_limit = 60 s, each run in a child process that
 * is killed after 65 s in case the limit is not honoured. Prints a markdown
 * table: the median time of ic_trace over 5 runs (3 above 0.2 s, 1 above
 * 2 s), curves found / expected, the largest relative length error (when
 * the counts agree), `complete`, and the judgement of tests/test_torture.c.
 *
 * usage: bench_torture [SOURCE_DIR] [CASE...] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../tests/torture/torture_run.h"

#define TIME_LIMIT 60.0
#define KILL_AFTER 65.0

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int wanted(int argc, char **argv, const char *name)
{
    if (argc <= 2)
        return 1;
    for (int i = 2; i < argc; i++)
        if (!strcmp(argv[i], name))
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/truth/torture_truth.txt", dir);
    tt_truth truth;
    if (tt_read_truth(&truth, path) != 0)
        return 1;
    printf("torture set: ic_trace with the defaults, time_limit %.0f s (the child is killed after "
           "%.0f s)\n\n",
           TIME_LIMIT, KILL_AFTER);
    printf("| case | ms | curves found / expected | max rel. length error | complete | judged |\n");
    printf("|---|---|---|---|---|---|\n");
    fflush(stdout);
    for (int i = 0; i < truth.ncases; i++) {
        const tt_case *c = &truth.cases[i];
        if (!wanted(argc, argv, c->name))
            continue;
        snprintf(path, sizeof path, "%s/tests/torture/%s.json", dir, c->name);
        double ms[5];
        int runs = 0, want = 5;
        tt_result r;
        tt_verdict v;
        memset(&r, 0, sizeof r);
        while (runs < want) {
            tt_free_result(&r);
            tt_run(&r, path, TIME_LIMIT, KILL_AFTER);
            if (r.s.stage != TT_OK)
                break;
            ms[runs++] = r.s.ms;
            if (runs == 1)
                want = r.s.ms > 2000 ? 1 : r.s.ms > 200 ? 3 : 5;
        }
        tt_judge(c, &r, &v);
        char t[64], curves[64], err[32], complete[32];
        if (runs) {
            qsort(ms, (size_t)runs, sizeof ms[0], cmp);
            snprintf(t, sizeof t, "%.1f", ms[runs / 2]);
        } else if (r.s.stage == TT_TIMEOUT) {
            snprintf(t, sizeof t, "killed at %.0f s (time_limit not honoured)", KILL_AFTER);
        } else {
            snprintf(t, sizeof t, "-");
        }
        if (r.s.stage == TT_OK) {
            if (c->surface)
                snprintf(curves, sizeof curves, "%d / a surface", r.s.ncurves);
            else
                snprintf(curves, sizeof curves, "%d / %d", r.s.ncurves, c->ncurves);
            snprintf(complete, sizeof complete, "%d", r.s.complete);
        } else {
            snprintf(curves, sizeof curves, "%s",
                     r.s.stage == TT_LOAD_ERROR    ? "load error"
                     : r.s.stage == TT_PAIR_ERROR  ? "pair error"
                     : r.s.stage == TT_TRACE_ERROR ? "trace error"
                     : r.s.stage == TT_TIMEOUT     ? "-"
                                                   : "crashed");
            snprintf(complete, sizeof complete, "-");
        }
        if (isnan(v.max_rel_length_error) || c->ncurves == 0)
            snprintf(err, sizeof err, "-");
        else
            snprintf(err, sizeof err, "%.1e", v.max_rel_length_error);
        printf("| %s | %s | %s | %s | %s | %s |\n", c->name, t, curves, err, complete,
               v.ok ? (c->known_failure ? "XPASS" : "pass")
                    : (c->known_failure ? "XFAIL" : "FAIL"));
        fflush(stdout);
        tt_free_result(&r);
    }
    tt_free_truth(&truth);
    return 0;
}

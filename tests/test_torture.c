/* The torture set (the trust issue): problem files at scales from 1e-6 to
 * 1e6, periodic seams at any offset, tangential curves cut by the box and the
 * domain, many loops, coincident and nearly coincident surfaces, a cone apex,
 * overflowing formulas, boxes and domains, a higher-order contact, the
 * Whitney umbrella and transversal classics at unusual scales and offsets,
 * each traced whole with the defaults (as `intercurve trace` does) and
 * judged against exact truth (tests/truth/gen_torture_truth.py, sympy and
 * mpmath; never from the code): the number of curves and of closed ones,
 * every length to 1e-9 relative (the docs' promise for arc length; see
 * TT_LENGTH_TOL), closed/tangential/shape of each, the singular points within
 * 1e-8 of the problem's size with their types, and the verdict of the report
 * (`complete`; an honest incomplete report or an error where that is
 * acceptable; the loader's rejection of bad input).
 *
 * The truth file gives each case a status: `pass` cases are asserted;
 * `known-failure: REASON` cases are run and printed (XFAIL with what was
 * wrong this time, XPASS when one now passes: then its status should become
 * `pass`) but not counted. Each case runs in a child process, killed after
 * IC_TORTURE_TIMEOUT seconds (default 6, 30 under AddressSanitizer; the
 * trace's own time_limit is half of that),
 * so a hang or a crash is a failure of that case only. The benchmark-only
 * case (7938 loops) runs in bench/bench_torture.c.
 *
 * usage: test_torture SOURCE_DIR */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "torture/torture_run.h"

/* AddressSanitizer (make sanitize) runs the traces several times slower:
 * the limits grow with it, so that a case passing in a normal build does not
 * run into them. */
#ifdef __SANITIZE_ADDRESS__
#define TT_SLOWDOWN 5.0
#else
#define TT_SLOWDOWN 1.0
#endif

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    const char *env = getenv("IC_TORTURE_TIMEOUT");
    const double kill_after = env && atof(env) > 0 ? atof(env) : 6.0 * TT_SLOWDOWN;
    const double time_limit = kill_after * 0.5;
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/truth/torture_truth.txt", dir);
    tt_truth truth;
    if (tt_read_truth(&truth, path) != 0) {
        CHECK(0, "cannot read %s", path);
        return harness_finish("torture");
    }
    int npass = 0, nxfail = 0, nxpass = 0, nfail = 0, nrun = 0;
    const double t0 = tt_now();
    for (int i = 0; i < truth.ncases; i++) {
        const tt_case *c = &truth.cases[i];
        if (c->bench_only)
            continue;
        snprintf(path, sizeof path, "%s/tests/torture/%s.json", dir, c->name);
        /* a case file that cannot be read fails, whatever its verdict (the
         * loader's "cannot open" would pass for an input error) */
        FILE *probe = fopen(path, "rb");
        if (!REQUIRE(probe != NULL, "%s: cannot read %s", c->name, path)) {
            nfail++;
            continue;
        }
        fclose(probe);
        tt_result r;
        const double w0 = tt_now();
        tt_run(&r, path, time_limit, kill_after);
        const double wall = tt_now() - w0;
        tt_verdict v;
        tt_judge(c, &r, &v);
        nrun++;
        /* what a passing case said about itself */
        char detail[400];
        if (r.s.stage == TT_OK)
            snprintf(detail, sizeof detail, "%d curves, complete %d, %d failures%s%s", r.s.ncurves,
                     r.s.complete, r.s.nfailures, r.s.nfailures ? ", the first: " : "", r.s.failure);
        else
            snprintf(detail, sizeof detail, "%s", r.s.message);
        if (c->known_failure) {
            if (v.ok) {
                nxpass++;
                printf("XPASS %s: its status in the truth can become pass (%.2f s; %s)\n",
                       c->name, wall, detail);
            } else {
                nxfail++;
                printf("XFAIL %s: %s (%.2f s)\n", c->name, v.why, wall);
            }
        } else {
            CHECK(v.ok, "%s: %s", c->name, v.why);
            if (v.ok) {
                npass++;
                printf("PASS  %s (%.2f s; %s)\n", c->name, wall, detail);
            } else {
                nfail++;
                printf("FAIL  %s: %s (%.2f s)\n", c->name, v.why, wall);
            }
        }
        tt_free_result(&r);
    }
    printf("torture cases: %d run in %.1f s: %d pass, %d fail, %d known failures (XFAIL), %d XPASS\n",
           nrun, tt_now() - t0, npass, nfail, nxfail, nxpass);
    CHECK(nrun >= 25, "only %d torture cases", nrun);
    tt_free_truth(&truth);
    return harness_finish("torture");
}

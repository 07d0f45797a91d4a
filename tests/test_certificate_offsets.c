/*
 * A saddle far from the origin (issue 23's class: "a saddle
 * z - o = 0.05((x - o)^2 - (y - o)^2) against z = o at o = 3e5 and 1e6,
 * parametric or implicit: a diagonal traced two or three times, a 3e-4
 * gap, spurious approximate branch points"). The intersection is the two
 * lines x - o = +-(y - o) in the plane z = o, crossing at the branch point
 * (o, o, o). Five offsets from 1e3 to 1e6, each posed three ways: both
 * implicit in the box [o - 1, o + 1]^3; the saddle as a parametric sheet
 * over the domain [o - 1, o + 1]^2 against the implicit plane; and the
 * saddle as (o + u, o + v, o + 0.05(u^2 - v^2)) over [-1, 1]^2 against the
 * plane as a parametric sheet over [o - 2, o + 2]^2. Every case must be
 * right and complete, or honestly incomplete; never complete and wrong.
 * At 1e6 a unit feature keeps 6 fewer digits than at 1: the cases that
 * cannot be resolved must say so.
 *
 * Truth in closed form: each line from corner to corner of the square of
 * half width 1, of length 2 sqrt 2; the branch point at (o, o, o).
 *
 * The problem is traced and checked moved near the origin (docs/tracing.md,
 * "Far from the origin"), its result moved back; `verify` moves the saved
 * document the same way: a proven trace is accepted again from its
 * document, grown afresh and from its certificate file, and refused with a
 * curve dropped, a curve doubled, or the branch point moved by 1e-3.
 *
 * Tolerances: lengths relative TIER_LENGTH (the tracer's tol is a fraction
 * of the problem's size, 1 here, whatever the offset; measured 2.3e-10 at
 * o = 3e5); the branch point within TIER_LOCATED of o (the coordinates'
 * own rounding at 1e6 is 1.2e-10), relative to o.
 */
#include <math.h>

#include "certify_harness.h"

static const double OFFSETS[] = {1e3, 1e4, 1e5, 3e5, 1e6};
#define NOFFSETS (int)(sizeof OFFSETS / sizeof OFFSETS[0])

static void problem(double o, int form, char *json, size_t size)
{
    if (form == 0)
        snprintf(json, size,
                 "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"z - %.17g - 0.05*((x - "
                 "%.17g)^2 - (y - %.17g)^2)\"}, {\"type\": \"implicit\", \"f\": \"z - %.17g\"}],"
                 "\"box\": [[%.17g, %.17g], [%.17g, %.17g], [%.17g, %.17g]]}",
                 o, o, o, o, o - 1, o + 1, o - 1, o + 1, o - 1, o + 1);
    else if (form == 1)
        snprintf(json, size,
                 "{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", \"%.17g + "
                 "0.05*((u - %.17g)^2 - (v - %.17g)^2)\"], \"domain\": [[%.17g, %.17g], [%.17g, "
                 "%.17g]]}, {\"type\": \"implicit\", \"f\": \"z - %.17g\"}]}",
                 o, o, o, o - 1, o + 1, o - 1, o + 1, o);
    else
        snprintf(json, size,
                 "{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"%.17g + u\", \"%.17g + "
                 "v\", \"%.17g + 0.05*(u^2 - v^2)\"], \"domain\": [[-1, 1], [-1, 1]]},"
                 "{\"type\": \"parametric\", \"params\": [\"s\", \"t\"], \"xyz\": [\"s\", \"t\", "
                 "\"%.17g\"], \"domain\": [[%.17g, %.17g], [%.17g, %.17g]]}]}",
                 o, o, o, o, o - 2, o + 2, o - 2, o + 2);
}

/* Two open curves of length 2 sqrt 2 and one branch point at (o, o, o). */
static int saddle_right(const ic_trace_result *r, double o)
{
    const double line = 2 * sqrt(2.0);
    if (ic_trace_result_num_curves(r) != 2 || ic_trace_result_num_specials(r) != 1)
        return 0;
    for (int c = 0; c < 2; c++) {
        const ic_trace_curve *cv = ic_trace_result_curve(r, c);
        if (cv->closed || !(fabs(cv->length - line) <= TIER_LENGTH * line))
            return 0;
    }
    const ic_trace_special *s = ic_trace_result_special(r, 0);
    double d = 0.0;
    for (int i = 0; i < 3; i++)
        d = fmax(d, fabs(s->xyz[i] - o));
    return s->type == IC_POINT_BRANCH && !s->approximate && d <= TIER_LOCATED * o;
}

int main(void)
{
    static const char *const FORMS[] = {"implicit", "parametric/implicit",
                                        "parametric/parametric"};
    tally t[3] = {{0}, {0}, {0}};
    for (int i = 0; i < NOFFSETS; i++)
        for (int form = 0; form < 3; form++) {
            char json[1600], name[120];
            problem(OFFSETS[i], form, json, sizeof json);
            snprintf(name, sizeof name, "saddle at %g, %s", OFFSETS[i], FORMS[form]);
            traced tr;
            if (trace_json_keep(&tr, name, json) == 0) {
                judge(&t[form], &tr, name, saddle_right(tr.res, OFFSETS[i]));
                verify_saved(&tr, name);
            }
            release(&tr);
        }
    for (int form = 0; form < 3; form++)
        printf("%s: %d cases, %d proven, %d honestly incomplete, %d right\n", FORMS[form],
               t[form].cases, t[form].proven, t[form].honest, t[form].right);
    /* every case proven: moved to the origin, each is the saddle at 0
     * (before the move the parametric forms from 1e5 on lost the cells
     * beside the branch point to rounding at the offset, and traced the
     * diagonals up to five times) */
    CHECK(t[0].proven == 5 && t[1].proven == 5 && t[2].proven == 5,
          "proven: %d, %d and %d of 5", t[0].proven, t[1].proven, t[2].proven);
    return harness_finish("certificate_offsets");
}

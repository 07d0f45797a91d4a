/*
 * The certificate on narrow strips beside branch points (issue 23): two unit
 * cylinders, A about z and B about y, meet in the ellipses y = +-z through
 * the branch points (+-1, 0, 0); A is cut to a strip 7e-4 (or 1e-4) high in
 * z at, across or 1e-5 to 2e-4 beside the points, B to a strip in y or not
 * at all. Two forms:
 *   - A parametric, (cos u, sin u, v) on u in [-pi, pi] (its seam through
 *     the branch point (-1, 0, 0)) and the strip in v, B implicit (the six
 *     cases where B is whole);
 *   - both implicit, the strips as the box (all eight cases).
 * Every case must be right and proven, or honestly incomplete: never
 * complete and wrong; at least the 7 proven today stay proven. Right: the curves' lengths add up to the total and
 * the branch points are found exactly when the strips hold them.
 *
 * Truth: tests/truth/gen_certificate_strips_truth.py (mpmath, 40 digits,
 * quadrature and incomplete elliptic integrals agreeing to 1e-30) in
 * tests/truth/certificate_strips.txt: the strips and the total length.
 *
 * usage: test_certificate_strips SOURCE_DIR
 */
#include <math.h>

#include "certify_harness.h"

#define NSTRIPS 8
/* the first NWHOLE_B cases leave B whole: those have a parametric form */
#define NWHOLE_B 6

typedef struct {
    double a0, a1, b0, b1, length, arcs; /* arcs: for the reader (a curve may be cut at a point) */
} strip_truth;

/* Each branch point (+-1, 0, 0) found once within TIER_LOCATED when both
 * strips hold z = 0 and y = 0, no singular point otherwise. */
static int branch_points_right(const ic_trace_result *r, const strip_truth *t)
{
    const int want = t->a0 <= 0 && t->a1 >= 0 && t->b0 <= 0 && t->b1 >= 0 ? 2 : 0;
    if (ic_trace_result_num_specials(r) != want)
        return 0;
    int seen[2] = {0, 0};
    for (int k = 0; k < want; k++) {
        const ic_trace_special *s = ic_trace_result_special(r, k);
        const int right = s->xyz[0] > 0;
        seen[right] += s->type == IC_POINT_BRANCH && s->nbranches == 2 &&
                       fabs(fabs(s->xyz[0]) - 1.0) < TIER_LOCATED &&
                       fabs(s->xyz[1]) < TIER_LOCATED && fabs(s->xyz[2]) < TIER_LOCATED;
    }
    return want == 0 || (seen[0] == 1 && seen[1] == 1);
}

/* The lengths add up to the total to TIER_LENGTH (the tracer may cut an
 * arc at a branch point: the sum is what it must get). */
static int lengths_right(const ic_trace_result *r, double want)
{
    double sum = 0.0;
    for (int k = 0; k < ic_trace_result_num_curves(r); k++)
        sum += ic_trace_result_curve(r, k)->length;
    return harness_close(sum, want, TIER_LENGTH, 1);
}

static void problem_json(const strip_truth *t, int parametric, char *json, size_t size)
{
    if (parametric)
        snprintf(json, size,
                 "{\"surfaces\": [{\"type\": \"parametric\", \"params\": [\"u\", \"v\"], "
                 "\"xyz\": [\"cos(u)\", \"sin(u)\", \"v\"], \"domain\": [[\"-pi\", \"pi\"], "
                 "[%.17g, %.17g]], \"periodic\": [true, false]},"
                 "{\"type\": \"implicit\", \"f\": \"x^2 + z^2 - 1\"}]}",
                 t->a0, t->a1);
    else
        snprintf(json, size,
                 "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2 + y^2 - 1\"},"
                 "{\"type\": \"implicit\", \"f\": \"x^2 + z^2 - 1\"}],"
                 "\"box\": [[-1.5, 1.5], [%.17g, %.17g], [%.17g, %.17g]]}",
                 t->b0, t->b1, t->a0, t->a1);
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    double rows[NSTRIPS][6];
    if (read_truth_rows(src, "certificate_strips.txt", 6, NSTRIPS, &rows[0][0]) != 0)
        return harness_finish("test_certificate_strips");
    strip_truth truth[NSTRIPS];
    for (int i = 0; i < NSTRIPS; i++)
        truth[i] = (strip_truth){rows[i][0], rows[i][1], rows[i][2],
                                 rows[i][3], rows[i][4], rows[i][5]};
    tally forms[2] = {{0}, {0}};
    for (int i = 0; i < NSTRIPS; i++)
        for (int parametric = 0; parametric < 2; parametric++) {
            if (parametric && i >= NWHOLE_B)
                continue;
            char json[700], name[120];
            problem_json(&truth[i], parametric, json, sizeof json);
            snprintf(name, sizeof name, "strip z in [%g, %g], y in [%g, %g], %s", truth[i].a0,
                     truth[i].a1, truth[i].b0, truth[i].b1,
                     parametric ? "parametric/implicit" : "implicit in the box");
            traced t;
            if (trace_json(&t, name, json) == 0)
                judge(&forms[parametric], &t, name,
                      branch_points_right(t.res, &truth[i]) &&
                          lengths_right(t.res, truth[i].length));
            release(&t);
        }
    for (int f = 0; f < 2; f++)
        printf("strips, %s: %d cases, %d right, %d proven, %d honestly incomplete\n",
               f ? "parametric/implicit" : "implicit in the box", forms[f].cases, forms[f].right,
               forms[f].proven, forms[f].honest);
    /* what is proven today stays proven (docs/tracing.md: the cover split by
     * lengths in space, Newton's steps measured so, the branch's first point
     * inside the strip, its curve's end at the point): 5 of the implicit
     * form, 2 of the parametric */
    CHECK(forms[0].proven >= 5 && forms[1].proven >= 2,
          "strips: %d implicit and %d parametric proven (want at least 5 and 2)", forms[0].proven,
          forms[1].proven);
    return harness_finish("test_certificate_strips");
}

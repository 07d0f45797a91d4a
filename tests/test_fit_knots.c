/* The knots a fit puts where its curve crosses the nets' knot lines
 * (src/curve/fit.c, docs/bspline.md): on nets recognised as a sphere, a
 * cone and planes the curve in space is smooth there (knots of multiplicity
 * 3, as at every other node) while its pcurves change pieces (multiplicity
 * 5); on a free-form net the curve's curvature jumps there too. */
#include "traced_example.h"

/* The largest multiplicity of an interior knot of b, and how many distinct
 * interior knots have multiplicity 5 (the degree: a joint of two sides). */
static int largest_inner(const ic_bspline *b, int *fives)
{
    const int nk = b->ncontrol + b->degree + 1;
    int largest = 0, first = 0;
    *fives = 0;
    while (first < nk && b->knots[first] == b->knots[0])
        first++;
    for (int i = first; i < nk;) {
        int j = i;
        while (j < nk && b->knots[j] == b->knots[i])
            j++;
        if (j < nk) { /* interior: not the last run of the vector */
            largest = j - i > largest ? j - i : largest;
            *fives += j - i == 5;
        }
        i = j;
    }
    return largest;
}

/* The single curve of a problem file, fitted with the default tolerance:
 * the multiplicities of its curve's and its parametric sheets' knots. */
static void multiplicities(const char *dir, const char *file, int *curve, int *curve_fives,
                           int *pcurve_fives)
{
    char path[600];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    traced t;
    *curve = *curve_fives = *pcurve_fives = -1;
    if (trace_file(&t, path) != 0)
        return;
    ic_error err;
    if (REQUIRE(ic_trace_result_num_curves(t.res) == 1, "%s: %d curves", file,
                ic_trace_result_num_curves(t.res)) &&
        REQUIRE(ic_trace_fit(t.res, t.pair, IC_TRACE_FIT_TOL_DEFAULT, &err) == IC_OK, "%s: %s",
                file, err.message)) {
        const ic_curve_fit *f = ic_trace_result_fit(t.res, 0);
        *curve = largest_inner(&f->curve, curve_fives);
        *pcurve_fives = 0;
        for (int s = 0; s < 2; s++) {
            int fives = 0;
            if (f->pcurves[s].ncontrol)
                largest_inner(&f->pcurves[s], &fives);
            *pcurve_fives += fives;
        }
    }
    release(&t);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    const char *recognised[] = {"tests/data/nurbs/problem-sphere-plane-circle.json",
                                "tests/data/nurbs/problem-cone-plane-circle.json"};
    for (int i = 0; i < 2; i++) {
        int curve, curve_fives, pcurve_fives;
        multiplicities(dir, recognised[i], &curve, &curve_fives, &pcurve_fives);
        CHECK(curve == 3 && curve_fives == 0 && pcurve_fives > 0,
              "%s: curve knots up to multiplicity %d (%d of 5), pcurves %d of 5", recognised[i],
              curve, curve_fives, pcurve_fives);
    }
    /* a free-form net crossed along a knot line: two sides in space too */
    const char *freeform = "tests/data/nurbs/problem-knotline-plane.json";
    int curve, curve_fives, pcurve_fives;
    multiplicities(dir, freeform, &curve, &curve_fives, &pcurve_fives);
    CHECK(curve == 5 && curve_fives > 0 && pcurve_fives > 0,
          "%s: curve knots up to multiplicity %d (%d of 5), pcurves %d of 5", freeform, curve,
          curve_fives, pcurve_fives);
    return harness_finish("fit_knots");
}

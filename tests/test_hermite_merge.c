/* The merging of Hermite stretches (src/curve/hermite.c, ic_hermite_merge;
 * docs/bspline.md, "Merged knots"): nodes of a helix with its exact
 * derivatives and torsion every 0.01 of arc length; the kept nodes' B-spline
 * is checked at every node it skipped against the helix's closed form, for
 * position, c', c'' and torsion, within the tolerances the merge was given.
 * The evaluation is ic_bspline_eval's, not the merge's own. */
#include "harness.h"

#include <math.h>
#include <stdlib.h>

#include "curve/hermite.h"

/* the helix (r cos(s/w), r sin(s/w), c s/w), w = sqrt(r^2 + c^2):
 * kappa = r / w^2, tau = c / w^2 */
#define R 1.0
#define C 0.5
enum { NODES = 600 };
#define STEP 0.01

static void helix(double s, double out[3][3])
{
    const double w = sqrt(R * R + C * C), a = s / w;
    const double x[3][3] = {{R * cos(a), R * sin(a), C * a},
                            {-R * sin(a) / w, R * cos(a) / w, C / w},
                            {-R * cos(a) / (w * w), -R * sin(a) / (w * w), 0}};
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++)
            out[k][j] = x[k][j];
}

/* relative to the tolerances: ic_bspline_eval's rounding on top of the
 * merge's own test of the quintic */
#define SLACK 1.01

static void check(double pos_tol, double deriv_tol, double tau_tol)
{
    ic_hermite_node *nodes = calloc(NODES, sizeof *nodes);
    int *pinned = calloc(NODES, sizeof *pinned), *keep = calloc(NODES, sizeof *keep);
    if (!REQUIRE(nodes && pinned && keep, "memory"))
        goto done;
    const double w2 = R * R + C * C;
    for (int k = 0; k < NODES; k++) {
        double x[3][3];
        nodes[k].s = k * STEP;
        helix(nodes[k].s, x);
        for (int j = 0; j < 3; j++) {
            nodes[k].x[j] = x[0][j];
            nodes[k].d1[j] = nodes[k].d1b[j] = x[1][j];
            nodes[k].d2[j] = nodes[k].d2b[j] = x[2][j];
        }
        nodes[k].tau = C / w2;
    }
    pinned[NODES / 2] = 1;
    const int m = ic_hermite_merge(nodes, pinned, NODES, 3, pos_tol, deriv_tol, tau_tol, keep);
    int has_pinned = 0;
    for (int i = 0; i < m; i++)
        has_pinned += keep[i] == NODES / 2;
    CHECK(m > 2 && m < NODES / 4 && keep[0] == 0 && keep[m - 1] == NODES - 1 && has_pinned,
          "%g/%g/%g: %d of %d nodes kept, the ends and the pinned one among them", pos_tol,
          deriv_tol, tau_tol, m, NODES);
    ic_hermite_node *kept = calloc((size_t)m, sizeof *kept);
    ic_bspline b = {0};
    if (!REQUIRE(kept, "memory"))
        goto done;
    for (int i = 0; i < m; i++)
        kept[i] = nodes[keep[i]];
    if (!REQUIRE(ic_hermite_bspline(&b, kept, m, 3, 0, NULL) == IC_OK, "the B-spline")) {
        free(kept);
        goto done;
    }
    const double kappa = R / w2, tau = C / w2;
    double e0 = 0, e1 = 0, e2 = 0, et = 0;
    for (int k = 0, i = 0; k < NODES; k++) {
        double d[12], x[3][3];
        if (i < m && keep[i] == k) { /* a kept node: the merge says nothing of c''' there */
            i++;
            continue;
        }
        if (ic_bspline_eval(&b, nodes[k].s, 3, d, NULL) != IC_OK) {
            e0 = INFINITY;
            break;
        }
        helix(nodes[k].s, x);
        for (int j = 0; j < 3; j++) {
            e0 = fmax(e0, fabs(d[j] - x[0][j]));
            e1 = fmax(e1, fabs(d[3 + j] - x[1][j]));
            e2 = fmax(e2, fabs(d[6 + j] - x[2][j]) / kappa);
        }
        const double cr[3] = {d[4] * d[8] - d[5] * d[7], d[5] * d[6] - d[3] * d[8],
                              d[3] * d[7] - d[4] * d[6]};
        const double cc = cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2];
        et = fmax(et, fabs((cr[0] * d[9] + cr[1] * d[10] + cr[2] * d[11]) / cc - tau) / kappa);
    }
    CHECK(e0 <= SLACK * pos_tol && e1 <= SLACK * deriv_tol && e2 <= SLACK * deriv_tol &&
              et <= SLACK * tau_tol,
          "%g/%g/%g: at the skipped nodes, position %g, c' %g, c'' %g, torsion %g", pos_tol, deriv_tol,
          tau_tol, e0, e1, e2, et);
    printf("tolerances %g/%g/%g: %d of %d nodes kept; position %.2g, c' %.2g, c'' %.2g, tau %.2g\n",
           pos_tol, deriv_tol, tau_tol, m, NODES, e0, e1, e2, et);
    free(kept);
    free(b.knots);
    free(b.control);
done:
    free(nodes);
    free(pinned);
    free(keep);
}

int main(void)
{
    check(1e-10, 1e-7, 1e-6); /* as the fit uses them, for a tolerance of 1e-9 */
    check(1e-10, 1e-7, 1e-8); /* torsion the binding one */
    check(1e-12, 1e-5, 1e-4); /* position the binding one */
    return harness_finish("hermite_merge");
}

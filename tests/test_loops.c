/* The loop test of the search (the pairings' loop_free, src/pairing/): sound (a cell holding a
 * closed intersection curve is never declared loop-free, in every pairing,
 * for random small loops) and useful (cells crossed by a transversal arc
 * away from tangency are proven loop-free); a loop missed by the search at
 * its depth and found by the finer search of its loop cell; and the report
 * of whole traces. */
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"
#include "trace/trace_internal.h"
#include "pairing/pairing.h"
#include "traced_example.h"

/* A sphere of radius r about c (implicit formula, or primitive when prim). */
static ic_surface *sphere(const double *c, double r, int prim)
{
    ic_surface *s = NULL;
    if (prim) {
        ic_primitive p;
        memset(&p, 0, sizeof p);
        p.kind = IC_PRIM_SPHERE;
        memcpy(p.center, c, sizeof p.center);
        p.radius = r;
        if (ic_surface_new_primitive(&s, &p, IC_IMPLICIT, NULL) != IC_OK)
            return NULL;
        return s;
    }
    char f[256];
    snprintf(f, sizeof f, "(x - %.17g)^2 + (y - %.17g)^2 + (z - %.17g)^2 - %.17g", c[0], c[1], c[2],
             r * r);
    return ic_surface_new_implicit(&s, f, NULL, 0, NULL) == IC_OK ? s : NULL;
}

/* The plane z = h, implicit or as the parametric patch (u, v, h). */
static ic_surface *plane(double h, int parametric)
{
    ic_surface *s = NULL;
    char z[64];
    snprintf(z, sizeof z, "%.17g", h);
    if (parametric) {
        const char *xyz[3] = {"u", "v", z};
        return ic_surface_new_parametric(&s, xyz, NULL, NULL, 0, NULL, NULL) == IC_OK ? s : NULL;
    }
    char f[80];
    snprintf(f, sizeof f, "z - %.17g", h);
    return ic_surface_new_implicit(&s, f, NULL, 0, NULL) == IC_OK ? s : NULL;
}

/* The parametric sphere patch about c (longitude u, latitude v). */
static ic_surface *sphere_patch(const double *c, double r)
{
    char f[3][128];
    snprintf(f[0], sizeof f[0], "%.17g + %.17g*cos(u)*cos(v)", c[0], r);
    snprintf(f[1], sizeof f[1], "%.17g + %.17g*sin(u)*cos(v)", c[1], r);
    snprintf(f[2], sizeof f[2], "%.17g + %.17g*sin(v)", c[2], r);
    const char *xyz[3] = {f[0], f[1], f[2]};
    ic_surface *s = NULL;
    return ic_surface_new_parametric(&s, xyz, NULL, NULL, 0, NULL, NULL) == IC_OK ? s : NULL;
}

/* Random small circles: a sphere of radius r in (1e-4, 1e-2) cut by a plane
 * at height r*(0.9 rand) above its centre. The cell holding the whole circle
 * (with a random margin, in the pairing's coordinates) must not be declared
 * loop-free; the cell beside the circle's rightmost point, crossed by one
 * arc only and away from the tangency, is. */
static void test_soundness(harness_rng *rng)
{
    int trials = 0, useful = 0, tries = 0;
    for (int k = 0; k < 200 * harness_multiplier(); k++) {
        const double c[3] = {harness_uniform(rng, -1, 1), harness_uniform(rng, -1, 1),
                             harness_uniform(rng, -1, 1)};
        const double r = exp(harness_uniform(rng, log(1e-4), log(1e-2)));
        const double dz = r * harness_uniform(rng, -0.9, 0.9);
        const double rho = sqrt(r * r - dz * dz); /* the circle's radius */
        const int pairing = k % 4;                /* implicit, primitive, mixed, parametric pair */
        ic_surface *A = pairing == 3 ? sphere_patch(c, r) : sphere(c, r, pairing == 1);
        ic_surface *B = plane(c[2] + dz, pairing >= 2);
        if (!A || !B) {
            CHECK(0, "surfaces for trial %d", k);
            ic_surface_free(A);
            ic_surface_free(B);
            continue;
        }
        ic_pairing pg;
        if (ic_pairing_init(&pg, A, B, 0, NULL) != IC_OK) {
            CHECK(0, "pairing for trial %d", k);
            ic_surface_free(A);
            ic_surface_free(B);
            continue;
        }
        double lo[4], hi[4];
        const double m = harness_uniform(rng, 1.01, 3.0); /* margin factor */
        if (pairing <= 1) {                               /* the box around the circle */
            for (int i = 0; i < 2; i++)
                lo[i] = c[i] - m * rho, hi[i] = c[i] + m * rho;
            lo[2] = c[2] + dz - (m - 1) * rho - 1e-12, hi[2] = c[2] + dz + (m - 1) * rho + 1e-12;
        } else if (pairing == 2) { /* the plane's (u, v) = (x, y) */
            for (int i = 0; i < 2; i++)
                lo[i] = c[i] - m * rho, hi[i] = c[i] + m * rho;
        } else { /* the sphere's (u, v): all longitudes, latitudes around asin(dz/r) */
            const double lat = asin(dz / r), w = harness_uniform(rng, 0.01, 0.5);
            lo[0] = -3.2, hi[0] = 3.2;
            lo[1] = lat - w, hi[1] = lat + w;
            for (int i = 0; i < 2; i++)
                lo[2 + i] = c[i] - m * rho, hi[2 + i] = c[i] + m * rho;
        }
        trials++;
        CHECK(!pg.kind->loop_free(&pg, lo, hi),
              "pairing %d, trial %d: a cell holding a circle of radius %g declared loop-free",
              pairing, k, rho);
        /* beside the rightmost point (c + rho e_x): a cell of a tenth of rho */
        const double x0 = c[0] + rho, s = 0.05 * rho;
        if (pairing <= 2) {
            const double blo[3] = {x0 - s, c[1] - s, c[2] + dz - s};
            const double bhi[3] = {x0 + s, c[1] + s, c[2] + dz + s};
            tries++;
            useful += pg.kind->loop_free(&pg, blo, bhi);
        } else { /* longitude 0 at the circle's latitude, and the plane beside it */
            const double lat = asin(dz / r);
            const double blo[4] = {-0.05, lat - 0.05, x0 - s, c[1] - s};
            const double bhi[4] = {0.05, lat + 0.05, x0 + s, c[1] + s};
            tries++;
            useful += pg.kind->loop_free(&pg, blo, bhi);
        }
        ic_pairing_release(&pg);
        ic_surface_free(A);
        ic_surface_free(B);
    }
    CHECK(trials >= 200, "trials %d", trials);
    /* the test is a sufficient condition: with cells of a tenth of the
     * radius, every one of these is proven */
    CHECK(useful == tries, "cells beside a transversal arc proven loop-free: %d of %d", useful,
          tries);
    printf("loop test: %d cells holding a loop all flagged; %d of %d cells beside an arc "
           "proven loop-free\n",
           trials, useful, tries);
}

/* A bead of radius 0.01 centred exactly on a leaf cell's centre (depth 6 in
 * [-1, 1]^3): Newton from the centre meets grad f = 0 there and finds
 * nothing, the collinear-normals search finds no point on both surfaces;
 * the cell is a loop cell, searched three levels finer, where the loop is
 * found: the circle of radius sqrt(1e-4 - 0.004^2). */
static void test_refined_loop(void)
{
    ic_surface *A = NULL, *B = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    const double c[3] = {0.296875, 0.203125, 0.109375}; /* -1 + (k + 1/2)/32 */
    A = sphere(c, 0.01, 0);
    CHECK(ic_surface_new_implicit(&B, "z - 0.113375", NULL, 0, NULL) == IC_OK, "plane");
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -1, opt.box[k][1] = 1;
    if (A && B && ic_pair_new(&pair, A, B, NULL) == IC_OK &&
        ic_trace(&res, pair, &opt, NULL) == IC_OK) {
        const ic_trace_report *rep = ic_trace_result_report(res);
        const double L = 2 * 3.14159265358979323846 * sqrt(1e-4 - 0.004 * 0.004);
        const ic_trace_curve *cv = ic_trace_result_curve(res, 0);
        CHECK(ic_trace_result_num_curves(res) == 1 && cv->closed &&
                  fabs(cv->length - L) <= TIER_LENGTH * L,
              "the bead's circle found: %d curves, length %.17g of %.17g",
              ic_trace_result_num_curves(res), cv ? cv->length : 0.0, L);
        CHECK(rep->refined_cells >= 1 && rep->uncovered_cells == 0 && rep->nfailures == 0 &&
                  rep->tracer_complete,
              "refined %d, uncovered %d, failures %d, complete %d", rep->refined_cells,
              rep->uncovered_cells, rep->nfailures, rep->tracer_complete);
        if (cv)
            printf("loop missed at depth 6, found by the finer search: length error %.2g\n",
                   fabs(cv->length - L) / L);
    } else {
        CHECK(0, "trace of the bead");
    }
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
}

/* Whole traces: around the two cylinder loops every leaf cell is excluded or
 * loop-free (no closed curve of extent below a quarter cell can exist
 * besides the traced ones); the small loop's own cell cannot be. */
static void test_reports(const char *dir)
{
    traced t;
    if (trace_example(&t, dir, "cylinders.json") == 0) {
        const ic_trace_report *rep = ic_trace_result_report(t.res);
        CHECK(rep->loop_cells == 0 && rep->loop_free_cells > 0,
              "cylinders: %d loop-free cells, %d not", rep->loop_free_cells, rep->loop_cells);
    }
    release(&t);
    if (trace_example(&t, dir, "small-loop.json") == 0) {
        const ic_trace_report *rep = ic_trace_result_report(t.res);
        CHECK(rep->loop_cells >= 1, "small loop: its cell is a loop cell (%d)", rep->loop_cells);
    }
    release(&t);
}

int main(int argc, char **argv)
{
    harness_rng rng = {0x9E3779B97F4A7C15ull};
    test_soundness(&rng);
    test_refined_loop();
    test_reports(argc > 1 ? argv[1] : ".");
    return harness_finish("test_loops");
}

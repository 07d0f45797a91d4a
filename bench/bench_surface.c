/* Benchmarks of surface evaluation (make bench): ns per point evaluation,
 * per order-2 and order-4 derivative tensor, and per composition with a
 * univariate jet (a curve on the surface) at K = 4, 8, 16. Each figure is
 * the best of 5 batches (bench_timer.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_timer.h"
#include "intercurve.h"

typedef struct {
    ic_surface *s;
    const ic_jet_space *sp;
    double at[3];
    double *out;
    const double *const *in;
} job;

static int run_eval(void *ctx)
{
    job *j = ctx;
    j->at[0] += 1e-12; /* defeat caching of identical inputs */
    return ic_surface_eval(j->s, j->out, j->at, NULL);
}
static int run_taylor(void *ctx)
{
    job *j = ctx;
    j->at[0] += 1e-12;
    return ic_surface_taylor(j->s, j->out, j->at, j->sp, NULL);
}
static int run_compose(void *ctx)
{
    job *j = ctx;
    return ic_surface_compose(j->s, j->out, j->in, j->sp, NULL);
}

typedef struct {
    const char *name;
    ic_surface *s;
    double at[3];
} bench_surface;

int main(void)
{
    bench_surface cases[10];
    int nc = 0;
    ic_primitive torus = {.kind = IC_PRIM_TORUS, .major_radius = 2.0, .radius = 0.5};
    ic_primitive ell = {.kind = IC_PRIM_ELLIPSOID, .axes = {0.6, 0.8, 1.0}};
    ic_primitive sph = {.kind = IC_PRIM_SPHERE, .radius = 2.0};
    const char *cyl[3] = {"1 + sin(v)", "cos(v)", "u"};
    const char *sphere[3] = {"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"};
    const char *enneper[3] = {"u - u^3/3 + u*v^2", "-v - u^2*v + v^3/3", "u^2 - v^2"};
    const char *torus_f[3] = {"(2 + 0.5*cos(v))*cos(u)", "(2 + 0.5*cos(v))*sin(u)", "0.5*sin(v)"};
#define ADD(label, call, a0, a1, a2)                                                            \
    do {                                                                                        \
        ic_surface *s_ = NULL;                                                                  \
        if ((call) != IC_OK) {                                                                  \
            fprintf(stderr, "cannot create %s\n", label);                                       \
            return 1;                                                                           \
        }                                                                                       \
        cases[nc++] = (bench_surface){label, s_, {a0, a1, a2}};                                 \
    } while (0)
    ADD("Viviani cylinder (formula)", ic_surface_new_parametric(&s_, cyl, NULL, NULL, 0, NULL, NULL), 0.3, 1.4, 0);
    ADD("Viviani sphere (formula)", ic_surface_new_parametric(&s_, sphere, NULL, NULL, 0, NULL, NULL), 0.3, 0.4, 0);
    ADD("Enneper (formula)", ic_surface_new_parametric(&s_, enneper, NULL, NULL, 0, NULL, NULL), 1.4, 3.0, 0);
    ADD("torus (formula)", ic_surface_new_parametric(&s_, torus_f, NULL, NULL, 0, NULL, NULL), 0.3, 0.4, 0);
    ADD("torus (primitive, parametric)", ic_surface_new_primitive(&s_, &torus, IC_PARAMETRIC, NULL), 0.3, 0.4, 0);
    ADD("torus (primitive, implicit)", ic_surface_new_primitive(&s_, &torus, IC_IMPLICIT, NULL), 1.2, 1.3, 0.2);
    ADD("ellipsoid (implicit)", ic_surface_new_primitive(&s_, &ell, IC_IMPLICIT, NULL), 0.2, 0.3, 0.4);
    ADD("sphere (primitive, parametric)", ic_surface_new_primitive(&s_, &sph, IC_PARAMETRIC, NULL), 0.3, 0.4, 0);
    /* the exact rational NURBS sphere (radius 2; the 9-point circle by the
     * 5-point semicircle, tests/truth/gen_nurbs_quadrics.py) and a bicubic */
    static const double kc[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double ks[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    static const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    static const double rr[5] = {0, 1, 1, 1, 0}, hh[5] = {-1, -1, 0, 1, 1};
    const double h = 0.70710678118654752;
    double pts[9 * 5 * 3], wts[9 * 5];
    for (int i = 0; i < 9; i++)
        for (int j = 0; j < 5; j++) {
            pts[3 * (5 * i + j) + 0] = 2 * rr[j] * cx[i];
            pts[3 * (5 * i + j) + 1] = 2 * rr[j] * cy[i];
            pts[3 * (5 * i + j) + 2] = 2 * hh[j];
            wts[5 * i + j] = (i % 2 ? h : 1) * (j % 2 ? h : 1);
        }
    const ic_nurbs nsphere = {{2, 2}, {9, 5}, {kc, ks}, pts, wts, {0, 0}};
    ADD("sphere (NURBS, rational)", ic_surface_new_nurbs(&s_, &nsphere, NULL), 0.3, 0.4, 0);
    static const double kb[10] = {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1};
    double bic[6 * 6 * 3];
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++) {
            bic[3 * (6 * i + j) + 0] = i, bic[3 * (6 * i + j) + 1] = j;
            bic[3 * (6 * i + j) + 2] = ((i * 7 + j * 3) % 5) * 0.3;
        }
    const ic_nurbs nbic = {{3, 3}, {6, 6}, {kb, kb}, bic, NULL, {0, 0}};
    ADD("bicubic (NURBS, 3 x 3 spans)", ic_surface_new_nurbs(&s_, &nbic, NULL), 0.45, 0.4, 0);

    ic_jet_space *d2[2] = {NULL}, *d4[2] = {NULL}, *c[3] = {NULL};
    const int corders[3] = {4, 8, 16};
    for (int k = 0; k < 2; k++)
        if (ic_jet_space_new(&d2[k], 2 + k, 2, NULL) || ic_jet_space_new(&d4[k], 2 + k, 4, NULL))
            return 1;
    for (int k = 0; k < 3; k++)
        if (ic_jet_space_new(&c[k], 1, corders[k], NULL))
            return 1;
    double *out = calloc(3 * 1024, sizeof *out);
    double curve[3][17];

    printf("%-32s %10s %10s %10s %10s %10s %10s\n", "surface (ns per call)", "point",
           "order 2", "order 4", "curve K=4", "K=8", "K=16");
    for (int i = 0; i < nc; i++) {
        const int imp = ic_surface_get_kind(cases[i].s) == IC_IMPLICIT;
        job j = {.s = cases[i].s, .out = out};
        double r[6];
        memcpy(j.at, cases[i].at, sizeof j.at);
        r[0] = bench_ns_per_call(run_eval, &j);
        j.sp = d2[imp];
        r[1] = bench_ns_per_call(run_taylor, &j);
        j.sp = d4[imp];
        r[2] = bench_ns_per_call(run_taylor, &j);
        for (int k = 0; k < 3; k++) {
            /* a curve through the point: at + s (0.6, -0.8, 0.3) + s^2 (0.1, 0.2, -0.1) */
            const double dir[3] = {0.6, -0.8, 0.3}, acc[3] = {0.1, 0.2, -0.1};
            for (int v = 0; v < 3; v++) {
                memset(curve[v], 0, sizeof curve[v]);
                curve[v][0] = cases[i].at[v];
                curve[v][1] = dir[v];
                curve[v][2] = acc[v];
            }
            const double *in[3] = {curve[0], curve[1], curve[2]};
            j.in = in;
            j.sp = c[k];
            r[3 + k] = bench_ns_per_call(run_compose, &j);
        }
        printf("%-32s %10.0f %10.0f %10.0f %10.0f %10.0f %10.0f\n", cases[i].name, r[0], r[1],
               r[2], r[3], r[4], r[5]);
    }
    for (int i = 0; i < nc; i++)
        ic_surface_free(cases[i].s);
    for (int k = 0; k < 2; k++)
        ic_jet_space_free(d2[k]), ic_jet_space_free(d4[k]);
    for (int k = 0; k < 3; k++)
        ic_jet_space_free(c[k]);
    free(out);
    return 0;
}

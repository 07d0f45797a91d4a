/* Surface derivatives of orders 1 to 3 against finite differences in long
 * double: tensor products of central differences, Richardson-extrapolated
 * over h, h/2, h/4, h/8 (error O(h^8)). The surfaces are written out again
 * here in long double, independently of the formula parser. */
#include <string.h>

#include "harness.h"
#include "intercurve/surface.h"

typedef void (*ld_surface)(long double *out, const long double *x);

static const long double PI_L = 3.141592653589793238462643383279502884L;

static void sphere2(long double *o, const long double *x)
{
    o[0] = 2 * cosl(x[0]) * cosl(x[1]);
    o[1] = 2 * sinl(x[0]) * cosl(x[1]);
    o[2] = 2 * sinl(x[1]);
}

static void enneper(long double *o, const long double *x)
{
    const long double u = x[0], v = x[1];
    o[0] = u - u * u * u / 3 + u * v * v;
    o[1] = -v - u * u * v + v * v * v / 3;
    o[2] = u * u - v * v;
}

static void torus_parametric(long double *o, const long double *x)
{
    const long double w = 2 + cosl(2 * PI_L * x[1]);
    o[0] = cosl(2 * PI_L * x[0]) * w - 0.2L;
    o[1] = sinl(2 * PI_L * x[0]) * w;
    o[2] = 1 + sinl(2 * PI_L * x[1]);
}

static void torus_implicit(long double *o, const long double *x)
{
    const long double r2 = x[0] * x[0] + x[1] * x[1];
    const long double s = r2 + x[2] * x[2] + 3;
    o[0] = s * s - 16 * r2;
}

static void mix(long double *o, const long double *x)
{
    o[0] = expl(x[0] / 2) * sinl(x[1]) - logl(2 + x[2] * x[2]) +
           sqrtl(1 + x[0] * x[0] * x[1] * x[1]);
}

typedef struct {
    const char *name;
    const char *formulas[3];
    int implicit;
    ld_surface f;
    double at[3];
    double h; /* step: small against the scale on which the surface varies */
} fd_case;

/* Central difference of multi-index alpha with step h: the tensor product
 * of the 1-D operators sum_i (-1)^i C(k, i) f(x + (k/2 - i) h) / h^k. */
static void central(long double *out, ld_surface f, int nin, int nout, const double *at,
                    const int *alpha, long double h)
{
    static const int binom[4][4] = {{1}, {1, 1}, {1, 2, 1}, {1, 3, 3, 1}};
    int idx[3] = {0, 0, 0};
    for (int k = 0; k < nout; k++)
        out[k] = 0;
    for (;;) {
        long double x[3], w = 1, val[3];
        for (int v = 0; v < nin; v++) {
            x[v] = at[v] + (alpha[v] / 2.0L - idx[v]) * h;
            w *= (idx[v] % 2 ? -1 : 1) * binom[alpha[v]][idx[v]];
        }
        f(val, x);
        for (int k = 0; k < nout; k++)
            out[k] += w * val[k];
        int v = 0;
        while (v < nin && ++idx[v] > alpha[v])
            idx[v++] = 0;
        if (v == nin)
            break;
    }
    int total = 0;
    for (int v = 0; v < nin; v++)
        total += alpha[v];
    for (int k = 0; k < nout; k++)
        out[k] /= powl(h, total);
}

static void richardson(long double *out, ld_surface f, int nin, int nout, const double *at,
                       const int *alpha, long double h)
{
    long double t[4][3];
    for (int l = 0; l < 4; l++)
        central(t[l], f, nin, nout, at, alpha, h / (1 << l));
    for (int level = 1; level < 4; level++) {
        const long double q = powl(4.0L, level);
        for (int l = 0; l + level < 4; l++)
            for (int k = 0; k < nout; k++)
                t[l][k] = (q * t[l + 1][k] - t[l][k]) / (q - 1);
    }
    for (int k = 0; k < nout; k++)
        out[k] = t[0][k];
}

int main(void)
{
    const fd_case cases[] = {
        {"sphere-r2", {"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"}, 0, sphere2,
         {-1.2, 0.4}, 0.2},
        {"enneper", {"u - u^3/3 + u*v^2", "-v - u^2*v + v^3/3", "u^2 - v^2"}, 0,
         enneper, {1.4142135623730951, 3.0}, 0.2},
        {"torus-parametric",
         {"cos(2*pi*u)*(2 + cos(2*pi*v)) - 1/5", "sin(2*pi*u)*(2 + cos(2*pi*v))",
          "1 + sin(2*pi*v)"},
         0, torus_parametric, {0.6845, 0.75}, 0.04},
        {"torus-implicit", {"(x^2 + y^2 + z^2 + 3)^2 - 16*(x^2 + y^2)"}, 1, torus_implicit,
         {0.6, 0.8, 0.1}, 0.2},
        {"analytic-mix", {"exp(x/2)*sin(y) - log(2 + z^2) + sqrt(1 + x^2*y^2)"}, 1, mix,
         {0.3, -0.8, 1.2}, 0.04},
    };
    /* Tolerance of an order-d difference: its rounding error, eps_ld max|f|
     * 2^d / (h/8)^d (2^d: the sum of the stencil weights), times 16 for the
     * extrapolation's amplification; the O(h^8) truncation is far below it
     * at these steps (the analytic mix has a complex singularity at
     * |x y| = 1, about 1.3 away, so its step is small). Plus the jet's own
     * double rounding, TIER_DERIVATIVE (harness.h). Relative to the largest
     * derivative of the order. */
    double worst = 0.0;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const fd_case *fc = &cases[c];
        ic_surface *s = NULL;
        ic_error err;
        ic_status st = fc->implicit
                           ? ic_surface_new_implicit(&s, fc->formulas[0], NULL, 0, &err)
                           : ic_surface_new_parametric(&s, fc->formulas, NULL, NULL, 0, NULL, &err);
        CHECK(st == IC_OK, "%s: %s", fc->name, err.message);
        if (st != IC_OK)
            continue;
        const int nin = fc->implicit ? 3 : 2, nout = fc->implicit ? 1 : 3;
        ic_jet_space *sp = NULL;
        if (!REQUIRE(ic_jet_space_new(&sp, nin, 3, NULL) == IC_OK, "%s: jet space of order 3",
                     fc->name)) {
            ic_surface_free(s);
            continue;
        }
        const int n = ic_jet_space_len(sp);
        double t[3 * 20];
        CHECK(ic_surface_taylor(s, t, fc->at, sp, NULL) == IC_OK, "%s taylor", fc->name);
        double fmax_abs = 1.0; /* |f| near the point */
        {
            long double x[3] = {fc->at[0], fc->at[1], fc->at[2]}, val[3];
            fc->f(val, x);
            for (int k = 0; k < nout; k++)
                fmax_abs = fmax(fmax_abs, 2.0 * fabs((double)val[k]));
        }
        for (int d = 1; d <= 3; d++) {
            double scale = 1.0;
            long double fd[20][3];
            for (int i = ic_jet_degree_start(sp, d); i < ic_jet_degree_start(sp, d + 1); i++) {
                int alpha[3] = {0, 0, 0};
                ic_jet_exponents(sp, i, alpha);
                richardson(fd[i], fc->f, nin, nout, fc->at, alpha, fc->h);
                for (int k = 0; k < nout; k++)
                    scale = fmax(scale, fabs((double)fd[i][k]));
            }
            const double tol = 16.0 * LDBL_EPSILON * fmax_abs * pow(2.0, d) /
                                   pow(fc->h / 8.0, d) / scale +
                               TIER_DERIVATIVE;
            for (int i = ic_jet_degree_start(sp, d); i < ic_jet_degree_start(sp, d + 1); i++)
                for (int k = 0; k < nout; k++) {
                    const double got = t[k * n + i] * ic_jet_factorial(sp, i);
                    const double e = fabs(got - (double)fd[i][k]) / scale;
                    worst = fmax(worst, e / tol);
                    CHECK(e <= tol, "%s: derivative %d component %d: jet %.17g, fd %.17Lg (%g)",
                          fc->name, i, k, got, fd[i][k], e);
                }
        }
        ic_jet_space_free(sp);
        ic_surface_free(s);
    }
    printf("worst difference to long double finite differences: %.2g of its rounding bound\n",
           worst);
    return harness_finish("test_surface_fd");
}

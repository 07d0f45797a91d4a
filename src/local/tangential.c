/*
 * The height-difference method at a tangential point (docs/tangential.md).
 * With g = psi_A - psi_B the height difference over the common tangent
 * plane, the intersection near P is the zero set of g, a
 * plane curve singular at 0. In coordinates (r, w) along a unit direction d
 * and its normal d_perp, each smooth branch is w = phi(r) + r^p omega(r),
 * where omega solves G(r, omega) = g(r, w) / r^q = 0 by the implicit
 * function theorem, degree by degree:
 *   branch point (Delta > 0):   d a root of g2, p = 1, q = 2;
 *   higher-order contact:       d a simple root of the leading form g_m, p = 1, q = m;
 *   tangential curve (Delta = 0, g = 0 along dg/dw = 0): w = phi(r);
 *   tacnode (Delta = 0, h = g(r, phi) ~ h_m r^m, m even, -h_m/lambda > 0):
 *                               p = m/2, q = m, omega(0) = +-sqrt(-h_m/lambda).
 * Each branch is lifted to c(r) = P + x e1 + y e2 + psi_A(x, y) N and
 * reparametrised by arc length (series reversion).
 */
#include "tangential.h"
#include "common/mathconst.h"
#include "common/vec3.h"
#include "jet/jet_chain.h"
#include "surface/surface_jets.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const ic_heights *h;
    const ic_jet_space *sp2; /* (x, y) or (r, w), order H */
    ic_jet_space *sp1;       /* univariate, order H */
    int H;
    double *s2, *s1; /* scratch of sp2 and sp1 */
    const ic_local_options *opt;
} tctx;

static int idx2(const ic_jet_space *sp, int i, int j)
{
    const int a[2] = {i, j};
    return ic_jet_index(sp, a);
}

/* The coefficients of a bivariate jet of the highest order. */
enum { MAX_LEN2 = (IC_JET_MAX_ORDER + 1) * (IC_JET_MAX_ORDER + 2) / 2 };

/* out(r, w) = a(r d + w dp). The substitution's jets are on the stack: a
 * failed allocation here could not be reported (found by tests/test_nomem.c,
 * "apparatus, tangential": the branches came from uninitialised memory).
 * The substitution is linear, so the power products of the composition one
 * degree at a time (jet/jet_chain.h) are homogeneous: each is one product,
 * where the nested Horner scheme of ic_jet_compose multiplies whole jets. */
static void rotate(const tctx *cx, double *out, const double *a, const double *d, const double *dp)
{
    double X[MAX_LEN2], Y[MAX_LEN2];
    ic_jet_zero(X, cx->sp2);
    ic_jet_zero(Y, cx->sp2);
    X[1] = d[0], X[2] = dp[0];
    Y[1] = d[1], Y[2] = dp[1];
    const double *in[2] = {X, Y}, *P[1] = {a};
    ic_jet_chain ch;
    ic_jet_chain_init(&ch, cx->sp2, P, 1, in, cx->sp2, cx->s2);
    ic_jet_chain_set_delta_degree(&ch, 1);
    out[0] = a[0];
    for (int k = 1; k <= cx->H; k++) {
        ic_jet_chain_extend(&ch, k);
        ic_jet_chain_part(&ch, out, a, k);
    }
}

/* out = d a / dw (the second variable) */
static void deriv_w(const ic_jet_space *sp, double *out, const double *a)
{
    const int n = ic_jet_space_len(sp);
    ic_jet_zero(out, sp);
    for (int i = 0; i < n; i++) {
        int e[2];
        ic_jet_exponents(sp, i, e);
        if (e[1] >= 1) {
            const int j = idx2(sp, e[0], e[1] - 1);
            if (j >= 0)
                out[j] += e[1] * a[i];
        }
    }
}

/* out(r) = a(r, w(r)) for a univariate w with w(0) = 0 */
static void along(const tctx *cx, double *out, const double *a, const double *w)
{
    const int n1 = ic_jet_space_len(cx->sp1);
    double r[IC_JET_MAX_ORDER + 1];
    ic_jet_set_var(r, 0.0, 0, cx->sp1);
    (void)n1;
    const double *in[2] = {r, w};
    ic_jet_compose(out, a, cx->sp2, in, cx->sp1, cx->s1);
}

/* w(r) with w(0) = 0 from a(r, w(r)) = 0, dG = da/dw(0, 0): the degree-k
 * coefficient of a(r, w) depends on w_k only through dG w_k, so a is
 * composed with (r, w) one degree at a time (jet/jet_chain.h) while w is
 * found, instead of once per degree. Returns the valid orders, H. */
static int solve_curve(const tctx *cx, double *w, const double *a, double dG)
{
    double r[IC_JET_MAX_ORDER + 1], S[IC_JET_MAX_ORDER + 1];
    ic_jet_set_var(r, 0.0, 0, cx->sp1);
    ic_jet_zero(w, cx->sp1);
    const double *in[2] = {r, w}, *P[1] = {a};
    ic_jet_chain ch; /* sp2's scratch holds its power products over sp1 */
    ic_jet_chain_init(&ch, cx->sp2, P, 1, in, cx->sp1, cx->s2);
    for (int k = 1; k <= cx->H; k++) {
        ic_jet_chain_extend(&ch, k);
        ic_jet_chain_part(&ch, S, a, k);
        w[k] = -S[k] / dG;
    }
    return cx->H;
}

/* w(r) = base(r) + r^p omega(r), omega(0) = omega0, from G = a(r, w)/r^q = 0
 * with dG/domega(0) = dG. Returns the number of valid orders of w. */
static int solve_branch(const tctx *cx, double *w, const double *a, const double *base, int p,
                        int q, double omega0, double dG)
{
    const int H = cx->H;
    double omega[IC_JET_MAX_ORDER + 1] = {0}, S[IC_JET_MAX_ORDER + 1];
    omega[0] = omega0;
    for (int k = 1; k + q <= H; k++) {
        for (int i = 0; i <= H; i++)
            w[i] = (base ? base[i] : 0.0) + (i >= p ? omega[i - p] : 0.0);
        along(cx, S, a, w);
        omega[k] = -S[k + q] / dG;
    }
    for (int i = 0; i <= H; i++)
        w[i] = (base ? base[i] : 0.0) + (i >= p ? omega[i - p] : 0.0);
    return p + H - q;
}

/* The branch w(r) in direction d, lifted to 3-D and reparametrised by arc
 * length: br->derivs[0 .. order-1]. */
static ic_status lift_branch(const tctx *cx, ic_branch *br, const double *w, const double *d,
                             const double *dp, int valid, int order, ic_error *err)
{
    if (valid < order)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "the contact is of too high an order for derivatives to order %d "
                            "(jets of order %d)",
                            order, cx->H);
    const ic_heights *h = cx->h;
    const ic_jet_space *sp1 = cx->sp1;
    const int H = cx->H;
    double x[IC_JET_MAX_ORDER + 1], y[IC_JET_MAX_ORDER + 1], r[IC_JET_MAX_ORDER + 1];
    double psi[IC_JET_MAX_ORDER + 1], c[3][IC_JET_MAX_ORDER + 1];
    ic_jet_set_var(r, 0.0, 0, sp1);
    for (int i = 0; i <= H; i++) {
        x[i] = r[i] * d[0] + w[i] * dp[0];
        y[i] = r[i] * d[1] + w[i] * dp[1];
    }
    const double *in[2] = {x, y};
    ic_jet_compose(psi, h->psi[0], cx->sp2, in, sp1, cx->s1);
    psi[0] = 0.0; /* measured from P along N */
    for (int k = 0; k < 3; k++)
        for (int i = 0; i <= H; i++)
            c[k][i] =
                (i == 0 ? h->P[k] : 0.0) + x[i] * h->e1[k] + y[i] * h->e2[k] + psi[i] * h->N[k];
    /* speed sigma = |c'(r)|, arc length s(r) = int sigma, r(s) by reversion */
    double dc[3][IC_JET_MAX_ORDER + 1], sq[IC_JET_MAX_ORDER + 1], tmp[IC_JET_MAX_ORDER + 1];
    double sigma[IC_JET_MAX_ORDER + 1], s[IC_JET_MAX_ORDER + 1], rs[IC_JET_MAX_ORDER + 1];
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < H; i++)
            dc[k][i] = (i + 1) * c[k][i + 1];
        dc[k][H] = 0.0;
    }
    ic_jet_zero(sq, sp1);
    for (int k = 0; k < 3; k++) {
        ic_jet_mul(tmp, dc[k], dc[k], sp1);
        ic_jet_add(sq, sq, tmp, sp1);
    }
    ic_status st = ic_jet_sqrt(sigma, sq, sp1, err);
    if (st != IC_OK)
        return st;
    s[0] = 0.0;
    for (int i = 1; i <= H; i++)
        s[i] = sigma[i - 1] / i;
    st = ic_jet_revert(rs, s, sp1, cx->s1, err);
    if (st != IC_OK)
        return st;
    const double *rin[1] = {rs};
    memset(br, 0, sizeof *br);
    br->order = order;
    br->regular = 1;
    double fact = 1.0;
    double cs[3][IC_JET_MAX_ORDER + 1];
    for (int k = 0; k < 3; k++)
        ic_jet_compose(cs[k], c[k], sp1, rin, sp1, cx->s1);
    for (int i = 1; i <= order; i++) {
        fact *= i;
        for (int k = 0; k < 3; k++)
            br->derivs[i - 1][k] = fact * cs[k][i];
    }
    /* orientation: the first clearly nonzero coordinate of t is positive */
    for (int k = 0; k < 3; k++)
        if (fabs(br->derivs[0][k]) > 1e-9) {
            if (br->derivs[0][k] < 0)
                for (int i = 1; i <= order; i++)
                    if (i % 2)
                        ic_scale3(br->derivs[i - 1], br->derivs[i - 1], -1.0);
            break;
        }
    return IC_OK;
}

/* Largest coefficient magnitude of degree j of a 2-variable jet. */
static double degree_max(const ic_jet_space *sp, const double *a, int j)
{
    double m = 0.0;
    for (int i = ic_jet_degree_start(sp, j); i < ic_jet_degree_start(sp, j + 1); i++)
        m = fmax(m, fabs(a[i]));
    return m;
}

/* What moving the point by delta (opt->place_tol) can change the degree-j
 * coefficients of the height difference g by: the degree-i terms
 * contribute binom(i, j) |g_i| delta^(i-j) per monomial, bounded here by
 * 2^i max|g_i| delta^(i-j), up to the jets' order H. */
static double shift_noise(const ic_jet_space *sp, const double *g, int j, int H, double delta)
{
    double noise = 0.0;
    for (int i = j + 1; i <= H && delta > 0; i++)
        noise += ldexp(degree_max(sp, g, i), i) * pow(delta, i - j);
    return noise;
}

/* The leading form g_m(cos phi, sin phi). */
static double form_at(const tctx *cx, const double *g, int m, double phi)
{
    double val = 0.0;
    for (int i = 0; i <= m; i++)
        val += g[idx2(cx->sp2, i, m - i)] * pow(cos(phi), i) * pow(sin(phi), m - i);
    return val;
}

/* Simple real roots phi in [0, pi) of the leading form g_m(cos phi, sin
 * phi), by sign changes on a grid offset by half a step from 0, so that a
 * root at phi = 0 (a branch along e1: a circle crossing a tangential
 * equator, crossing.c) lies inside a step. */
static int form_roots(const tctx *cx, const double *g, int m, double *roots, int max)
{
    const int M = 1440;
    const double step = IC_PI / M, start = -0.5 * step;
    int count = 0;
    double prev = form_at(cx, g, m, start);
    for (int k = 1; k <= M; k++) {
        const double phi = start + step * k;
        const double val = form_at(cx, g, m, phi);
        if (((prev < 0 && val >= 0) || (prev > 0 && val <= 0)) && count < max) {
            double lo = phi - step, hi = phi, flo = prev;
            for (int it = 0; it < 80; it++) {
                const double mid = 0.5 * (lo + hi);
                const double fm = form_at(cx, g, m, mid);
                if ((fm < 0) == (flo < 0))
                    lo = mid, flo = fm;
                else
                    hi = mid;
            }
            double root = 0.5 * (lo + hi);
            if (root < 0) /* phi and phi + pi are one direction */
                root += IC_PI;
            roots[count++] = root;
        }
        prev = val;
    }
    return count;
}

static ic_status smooth_branch(const tctx *cx, ic_local_result *res, const double *g, double phi,
                               int q, int order, ic_error *err)
{
    const int n = ic_jet_space_len(cx->sp2);
    const double d[2] = {cos(phi), sin(phi)}, dp[2] = {-sin(phi), cos(phi)};
    double *gr = malloc((size_t)n * sizeof *gr);
    if (!gr)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    rotate(cx, gr, g, d, dp);
    const double dG = gr[idx2(cx->sp2, q - 1, 1)];
    double w[IC_JET_MAX_ORDER + 1];
    ic_status st;
    if (!(fabs(dG) > 0.0))
        st = ic_error_set(err, IC_ERR_UNABLE, 0, "a branch direction is a multiple root");
    else if (res->nbranches >= IC_LOCAL_MAX_BRANCHES)
        st = ic_error_set(err, IC_ERR_UNABLE, 0, "more than %d branches", IC_LOCAL_MAX_BRANCHES);
    else {
        const int valid = solve_branch(cx, w, gr, NULL, 1, q, 0.0, dG);
        st = lift_branch(cx, &res->branches[res->nbranches], w, d, dp, valid, order, err);
        if (st == IC_OK)
            res->nbranches++;
    }
    free(gr);
    return st;
}

/* The curve dg/dw = 0 across the kernel of the quadratic part a x^2 + b xy
 * + c y^2 (Delta = 0): the kernel direction d and its normal dp, g rotated
 * to (r, w) in gr, lambda = the w^2 coefficient, w = phi(r) and h(r) =
 * g(r, phi(r)), with each height along the same curve (hA, hB) for the scale. */
typedef struct {
    double d[2], dp[2], lambda;
    double phi[IC_JET_MAX_ORDER + 1], h[IC_JET_MAX_ORDER + 1];
    double hA[IC_JET_MAX_ORDER + 1], hB[IC_JET_MAX_ORDER + 1];
    double *gr; /* owned */
} polar_curve;

static ic_status polar_curve_new(const tctx *cx, polar_curve *pc, const double *g, double a,
                                 double b, double c, ic_error *err)
{
    const ic_jet_space *sp2 = cx->sp2;
    const int n = ic_jet_space_len(sp2);
    double *d = pc->d, *dp = pc->dp;
    if (fabs(a) >= fabs(c))
        d[0] = -b / 2, d[1] = a;
    else
        d[0] = c, d[1] = -b / 2;
    const double len = hypot(d[0], d[1]);
    d[0] /= len, d[1] /= len;
    dp[0] = -d[1], dp[1] = d[0];
    pc->gr = malloc(3 * (size_t)n * sizeof *pc->gr);
    if (!pc->gr)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    double *dw = pc->gr + n, *rot = pc->gr + 2 * n;
    rotate(cx, pc->gr, g, d, dp);
    pc->lambda = pc->gr[idx2(sp2, 0, 2)];
    deriv_w(sp2, dw, pc->gr);
    solve_curve(cx, pc->phi, dw, 2 * pc->lambda);
    along(cx, pc->h, pc->gr, pc->phi);
    rotate(cx, rot, cx->h->psi[0], d, dp);
    along(cx, pc->hA, rot, pc->phi);
    rotate(cx, rot, cx->h->psi[1], d, dp);
    along(cx, pc->hB, rot, pc->phi);
    return IC_OK;
}

/* The curvature (1/length) that sets the rounding noise of the heights'
 * coefficients at each degree: the largest of the heights' own along the
 * polar curve and 8/L (L the problem's size; the surfaces curve across it
 * more than along it: the torus of Bendrici & Boumedien-Zidani 2022,
 * Example 3 (tangential curve), radius 1 across, needs
 * 1/length 1 where L is 5.7, and 1/L let rounding pass as contact terms). */
static double noise_curvature(const polar_curve *pc, double L)
{
    const double k = fmax(fabs(pc->lambda), fmax(fabs(pc->hA[2]), fabs(pc->hB[2])));
    return fmax(k, 8 / L);
}

/* Delta = 0 with a nonzero quadratic part: follow dg/dw = 0 across the kernel. */
static ic_status degenerate(const tctx *cx, ic_local_result *res, const double *g, double a,
                            double b, double c, int order, ic_error *err)
{
    const int H = cx->H;
    polar_curve pc;
    ic_status st = polar_curve_new(cx, &pc, g, a, b, c, err);
    if (st != IC_OK)
        return st;
    const double *d = pc.d, *dp = pc.dp, *h = pc.h, *hA = pc.hA, *hB = pc.hB, *phi = pc.phi;
    const double lambda = pc.lambda;
    double *gr = pc.gr;
    int m = 0;
    for (int j = 3; j <= H && !m; j++)
        if (fabs(h[j]) > cx->opt->contact_tol * fmax(fabs(hA[j]), fabs(hB[j])) &&
            /* h_j has the units of length^(1-j): rounding noise at
             * eps k^(j-1), k the largest curvature at hand (lambda, the
             * two heights' second coefficients, 1/L), is no contact term */
            fabs(h[j]) > DBL_EPSILON * pow(noise_curvature(&pc, cx->opt->scale), j - 1))
            m = j;
    res->contact_order = m;
    if (m == 0) { /* g vanishes along the curve to order H: a tangential curve */
        res->type = IC_POINT_TANGENTIAL_CURVE;
        st = lift_branch(cx, &res->branches[0], phi, d, dp, H, order, err);
        if (st == IC_OK)
            res->nbranches = 1;
    } else if (m % 2 == 1) { /* a cusp: two half-branches on the side -h_m r^m / lambda > 0 */
        res->type = IC_POINT_CUSP;
        const double side = -h[m] / lambda > 0 ? 1.0 : -1.0;
        for (int k = 0; k < 2; k++) {
            ic_branch *br = &res->branches[k];
            memset(br, 0, sizeof *br);
            br->order = 1;
            br->regular = 0;
            for (int i = 0; i < 3; i++)
                br->derivs[0][i] = side * (d[0] * cx->h->e1[i] + d[1] * cx->h->e2[i]);
            memcpy(br->t, br->derivs[0], sizeof br->t);
            if (m == 3) { /* w - phi ~ +-r^(3/2): n -> +-d_perp */
                const double sg = k == 0 ? 1.0 : -1.0;
                for (int i = 0; i < 3; i++)
                    br->n[i] = sg * (dp[0] * cx->h->e1[i] + dp[1] * cx->h->e2[i]);
                ic_cross3(br->b, br->t, br->n);
                br->frame_defined = 1;
            }
        }
        res->nbranches = 2;
    } else if (-h[m] / lambda < 0) {
        res->type = IC_POINT_ISOLATED_CONTACT;
    } else { /* a tacnode: w = phi +- r^(m/2) sqrt(-h_m/lambda) + ... */
        res->type = IC_POINT_TACNODE;
        const double w0 = sqrt(-h[m] / lambda);
        for (int k = 0; k < 2 && st == IC_OK; k++) {
            double w[IC_JET_MAX_ORDER + 1];
            const double om = k == 0 ? w0 : -w0;
            const int valid = solve_branch(cx, w, gr, phi, m / 2, m, om, 2 * lambda * om);
            st = lift_branch(cx, &res->branches[k], w, d, dp, valid, order, err);
            if (st == IC_OK)
                res->nbranches++;
        }
    }
    free(gr);
    return st;
}

/* The expansion at the sheets' point: jet spaces of order H, scratch and
 * the heights (ic_height_close frees them). */
typedef struct {
    const ic_jet_space *sp2; /* the first sheet's surface's (cached there) */
    ic_jet_space *sp1;
    double *s2, *s1;
    ic_heights h;
    double linear[2]; /* g's linear part (x, y), set aside */
} expansion;

static void expansion_close(expansion *ex)
{
    ic_heights_free(&ex->h);
    free(ex->s1);
    free(ex->s2);
    ic_jet_space_free(ex->sp1);
}

static ic_status expansion_open(expansion *ex, tctx *cx, const ic_sheet sh[2], int H,
                                const ic_local_options *opt, ic_error *err)
{
    memset(ex, 0, sizeof *ex);
    ic_status st = IC_OK;
    ex->sp2 = ic_surface_plane_space(sh[0].s, H, err);
    if (!ex->sp2)
        st = err ? err->code : IC_ERR_NOMEM;
    if (st == IC_OK)
        st = ic_jet_space_new(&ex->sp1, 1, H, err);
    if (st != IC_OK) {
        expansion_close(ex);
        return st;
    }
    ex->s2 = malloc(ic_jet_scratch_len(ex->sp2) * sizeof *ex->s2);
    ex->s1 = malloc(ic_jet_scratch_len(ex->sp1) * sizeof *ex->s1);
    if (!ex->s2 || !ex->s1)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory at a tangential point");
    if (st == IC_OK)
        st = ic_heights_compute(&ex->h, sh, ex->sp2, err);
    if (st != IC_OK) {
        expansion_close(ex);
        return st;
    }
    const tctx c = {&ex->h, ex->sp2, ex->sp1, H, ex->s2, ex->s1, opt};
    *cx = c;
    /* the constant and linear parts measure how far P is from an exact
     * tangential point (the residual); the analysis uses the rest */
    ex->linear[0] = ex->h.g[1];
    ex->linear[1] = ex->h.g[2];
    ex->h.g[0] = ex->h.g[1] = ex->h.g[2] = 0.0;
    return IC_OK;
}

/* The root of the polynomial sum_i p[i] r^i (degree deg) nearest 0 by
 * Newton from 0, within |r| <= reach; 0 when there is none. */
static int poly_root_near_zero(const double *p, int deg, double reach, double *root)
{
    double r = 0.0;
    for (int it = 0; it < 200; it++) {
        double f = 0.0, df = 0.0;
        for (int i = deg; i >= 0; i--) {
            df = df * r + f;
            f = f * r + p[i];
        }
        if (df == 0.0)
            return 0;
        const double step = f / df;
        r -= step;
        if (!(fabs(r) <= reach))
            return 0;
        if (fabs(step) <= 1e-16 * (fabs(r) + 1e-300)) {
            *root = r;
            return 1;
        }
    }
    *root = r;
    return 1; /* a multiple root converges linearly: the last iterate */
}

/* sum a[i] x^i y^j of a bivariate jet */
static double eval2(const ic_jet_space *sp, const double *a, double x, double y)
{
    double sum = 0.0;
    for (int i = ic_jet_space_len(sp) - 1; i >= 0; i--) {
        int e[2];
        ic_jet_exponents(sp, i, e);
        sum += a[i] * pow(x, e[0]) * pow(y, e[1]);
    }
    return sum;
}

ic_status ic_height_degenerate_step(const ic_sheet sh[2], int m, double reach,
                                    const ic_local_options *opt, double X[3], ic_error *err)
{
    expansion ex;
    tctx cx;
    const int H = 12;
    if (m < 3 || m >= H)
        return ic_error_set(err, IC_ERR_INVALID, 0, "contact order %d outside 3..%d", m, H - 1);
    ic_status st = expansion_open(&ex, &cx, sh, H, opt, err);
    if (st != IC_OK)
        return st;
    const double *g = ex.h.g;
    polar_curve pc;
    st = polar_curve_new(&cx, &pc, g, g[3], g[4], g[5], err);
    if (st != IC_OK) {
        expansion_close(&ex);
        return st;
    }
    /* h^(m-1)(r) / (m-1)! = sum_i C(i + m - 1, m - 1) h[i + m - 1] r^i */
    double p[IC_JET_MAX_ORDER + 1];
    const int deg = H - (m - 1);
    for (int i = 0; i <= deg; i++) {
        double binom = 1.0;
        for (int k = 1; k <= m - 1; k++)
            binom = binom * (i + k) / k;
        p[i] = binom * pc.h[i + m - 1];
    }
    double r;
    if (!poly_root_near_zero(p, deg, reach, &r)) {
        st =
            ic_error_set(err, IC_ERR_UNABLE, 0, "no point of contact order %d within %g", m, reach);
    } else {
        /* w from dg/dw(r, w) = 0 with g's linear part restored (it moves the
         * curve off P by the residual), by Newton from phi(r) */
        double w = 0.0;
        for (int i = H; i >= 0; i--)
            w = w * r + pc.phi[i];
        const int n = ic_jet_space_len(ex.sp2);
        double *gww = pc.gr + 2 * n; /* free after polar_curve_new */
        deriv_w(ex.sp2, gww, pc.gr + n);
        const double cw = ex.linear[0] * pc.dp[0] + ex.linear[1] * pc.dp[1];
        for (int it = 0; it < 20; it++) {
            const double G = eval2(ex.sp2, pc.gr + n, r, w) + cw;
            const double dG = eval2(ex.sp2, gww, r, w);
            if (dG == 0.0)
                break;
            w -= G / dG;
            if (fabs(G / dG) <= 1e-17 + 1e-16 * fabs(w))
                break;
        }
        const double x = r * pc.d[0] + w * pc.dp[0], y = r * pc.d[1] + w * pc.dp[1];
        const double z = eval2(ex.sp2, ex.h.psi[0], x, y);
        for (int i = 0; i < 3; i++)
            X[i] = ex.h.P[i] + x * ex.h.e1[i] + y * ex.h.e2[i] + z * ex.h.N[i];
    }
    free(pc.gr);
    expansion_close(&ex);
    return st;
}

ic_status ic_height_difference(ic_local_result *res, const ic_sheet sh[2], int order,
                               const ic_local_options *opt, ic_error *err)
{
    /* contact orders up to H are told apart; K + 4 leaves the branches of a
     * branch point or a tacnode their K orders (at least 10 for the
     * classification; K + 8 before cost 2.4 times more along a tangential
     * curve) */
    const int want = order + 4 > 10 ? order + 4 : 10;
    const int H = want < IC_JET_MAX_ORDER ? want : IC_JET_MAX_ORDER;
    expansion ex;
    tctx cx;
    ic_status st = expansion_open(&ex, &cx, sh, H, opt, err);
    if (st != IC_OK)
        return st;
    const ic_jet_space *sp2 = ex.sp2;
    const ic_heights *h = &ex.h;
    double *g = ex.h.g;
    const double a = g[3], b = g[4], c = g[5];
    const double scale2 = fmax(degree_max(sp2, h->psi[0], 2), degree_max(sp2, h->psi[1], 2));
    const double q2 = fmax(fmax(fabs(a), fabs(c)), fabs(b) / 2);
    res->discriminant = b * b / 4 - a * c;
    res->nbranches = 0;
    const double delta = opt->place_tol > 0 ? opt->place_tol : 0.0;
    if (q2 > opt->contact_tol * scale2 && q2 > shift_noise(sp2, g, 2, H, delta)) {
        const double D = res->discriminant;
        if (fabs(D) <= opt->contact_tol * q2 * q2) {
            res->discriminant = 0.0;
            st = degenerate(&cx, res, g, a, b, c, order, err);
        } else if (D < 0) {
            res->type = IC_POINT_ISOLATED_CONTACT;
        } else {
            /* g2(cos phi, sin phi) = A0 + B0 cos 2phi + C0 sin 2phi = 0 */
            res->type = IC_POINT_BRANCH;
            const double A0 = (a + c) / 2, B0 = (a - c) / 2, C0 = b / 2;
            const double R = hypot(B0, C0), alpha = atan2(C0, B0), beta = acos(-A0 / R);
            for (int k = 0; k < 2 && st == IC_OK; k++)
                st = smooth_branch(&cx, res, g, 0.5 * (alpha + (k ? -beta : beta)), 2, order, err);
        }
    } else {
        /* the quadratic parts agree: the leading form decides */
        int m = 0;
        for (int j = 3; j <= H && !m; j++) {
            const double sj = fmax(degree_max(sp2, h->psi[0], j), degree_max(sp2, h->psi[1], j));
            const double gj = degree_max(sp2, g, j);
            if (gj > opt->contact_tol * sj && gj > shift_noise(sp2, g, j, H, delta))
                m = j;
        }
        if (m == 0) {
            st = ic_error_set(err, IC_ERR_UNABLE, 0,
                              "the surfaces agree to order %d at the point: they coincide "
                              "near it",
                              H);
            goto cleanup;
        }
        res->type = IC_POINT_HIGHER_ORDER_CONTACT;
        res->contact_order = m;
        double roots[IC_LOCAL_MAX_BRANCHES];
        const int nr = form_roots(&cx, g, m, roots, IC_LOCAL_MAX_BRANCHES);
        for (int k = 0; k < nr && st == IC_OK; k++)
            st = smooth_branch(&cx, res, g, roots[k], m, order, err);
    }
cleanup:
    expansion_close(&ex);
    return st;
}

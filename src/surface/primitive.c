/*
 * Primitive surfaces (surface.h lists both forms of each).
 *
 * Parametric primitives are sums of products f(u) g(v) of cos, sin and
 * linear functions, so their Taylor coefficients are products of the
 * one-variable ones: d^i/du^i cos u = cos(u + i pi/2). Implicit quadrics
 * sum_i A_i d_i^2 + B_i d_i + C (d = x - center) have a constant Hessian;
 * the torus is expanded with jet arithmetic (a quartic, exact). A placed
 * primitive (placement.c) is evaluated in its local frame: the parametric
 * jets are rotated to space, the implicit form is evaluated by jet
 * arithmetic on the jets of the local coordinates Q^T (x - center).
 */
#include "surface_internal.h"
#include "common/mathconst.h"

#include <math.h>
#include <string.h>

#define MAXK (IC_JET_MAX_ORDER + 1)

static int positive(double x) { return isfinite(x) && x > 0.0; }

/* Whether a frame is exactly the standard one (x, y, z): then the
 * primitive keeps the fast path of its standard position. */
static int is_identity(const double f[3][3])
{
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            if (f[j][k] != (j == k ? 1.0 : 0.0))
                return 0;
    return 1;
}

/* The placement: the plane's frame, or the frame of the others. */
static ic_status place(ic_surface *s, ic_error *err)
{
    double frame[3][3];
    const ic_status st = ic_primitive_frame(&s->prim, frame, err);
    if (st != IC_OK)
        return st;
    if (s->prim.kind == IC_PRIM_PLANE) {
        memcpy(s->plane_frame, frame, sizeof frame);
        return IC_OK;
    }
    memcpy(s->frame, frame, sizeof frame);
    s->placed = !is_identity(frame);
    return IC_OK;
}

ic_status ic_primitive_check(ic_surface *s, ic_error *err)
{
    const ic_primitive *p = &s->prim;
    for (int i = 0; i < 3; i++)
        if (!isfinite(p->center[i]))
            return ic_error_set(err, IC_ERR_INVALID, 0, "primitive: center is not finite");
    const ic_status st = place(s, err);
    if (st != IC_OK)
        return st;
    switch (p->kind) {
    case IC_PRIM_PLANE:
        return IC_OK;
    case IC_PRIM_SPHERE:
    case IC_PRIM_CYLINDER:
        if (!positive(p->radius))
            return ic_error_set(err, IC_ERR_INVALID, 0, "radius must be positive, got %g",
                                p->radius);
        return IC_OK;
    case IC_PRIM_CONE:
        if (!(p->half_angle > 0.0 && p->half_angle < 0.5 * IC_PI))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "cone: half_angle must be in (0, pi/2) radians, got %g",
                                p->half_angle);
        return IC_OK;
    case IC_PRIM_TORUS:
        if (!positive(p->radius) || !positive(p->major_radius))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "torus: radii must be positive, got R = %g, r = %g",
                                p->major_radius, p->radius);
        return IC_OK;
    case IC_PRIM_ELLIPSOID:
        for (int i = 0; i < 3; i++)
            if (!positive(p->axes[i]))
                return ic_error_set(err, IC_ERR_INVALID, 0,
                                    "ellipsoid: semi-axes must be positive, got %g", p->axes[i]);
        return IC_OK;
    }
    return ic_error_set(err, IC_ERR_INVALID, 0, "unknown primitive kind %d", (int)p->kind);
}

void ic_primitive_default_domain(ic_surface *s)
{
    const ic_primitive *p = &s->prim;
    const double two_pi = 2.0 * IC_PI;
    double d[2][2] = {{-INFINITY, INFINITY}, {-INFINITY, INFINITY}};
    int per[2] = {0, 0};
    switch (p->kind) {
    case IC_PRIM_PLANE:
        break;
    case IC_PRIM_SPHERE:
    case IC_PRIM_ELLIPSOID:
        d[0][0] = 0.0, d[0][1] = two_pi, per[0] = 1;
        d[1][0] = -0.5 * IC_PI, d[1][1] = 0.5 * IC_PI;
        break;
    case IC_PRIM_CYLINDER:
    case IC_PRIM_CONE:
        d[0][0] = 0.0, d[0][1] = two_pi, per[0] = 1;
        break;
    case IC_PRIM_TORUS:
        d[0][0] = 0.0, d[0][1] = two_pi, per[0] = 1;
        d[1][0] = 0.0, d[1][1] = two_pi, per[1] = 1;
        break;
    }
    for (int i = 0; i < 2; i++) {
        s->domain[i][0] = d[i][0];
        s->domain[i][1] = d[i][1];
        s->periodic[i] = per[i];
    }
}

/* One-variable Taylor coefficients at t up to order K. */
static void taylor_cos_sin(double *c, double *s, double t, int K)
{
    const double ct = cos(t), st = sin(t);
    const double cyc_c[4] = {ct, -st, -ct, st}, cyc_s[4] = {st, ct, -st, -ct};
    double inv_fact = 1.0;
    for (int i = 0; i <= K; i++) {
        if (i > 0)
            inv_fact /= i;
        c[i] = cyc_c[i % 4] * inv_fact;
        s[i] = cyc_s[i % 4] * inv_fact;
    }
}

static void taylor_linear(double *l, double t, int K)
{
    for (int i = 0; i <= K; i++)
        l[i] = i == 0 ? t : i == 1 ? 1.0 : 0.0;
}

static void taylor_one(double *one, int K)
{
    for (int i = 0; i <= K; i++)
        one[i] = i == 0 ? 1.0 : 0.0;
}

/* out += scale * f(u) g(v) as a two-variable jet. */
static void add_tensor(double *out, const ic_jet_space *sp, double scale, const double *f,
                       const double *g)
{
    const int K = ic_jet_space_order(sp);
    for (int i = 0; i <= K; i++) {
        if (f[i] == 0.0)
            continue;
        for (int j = 0; i + j <= K; j++)
            out[ic_jet_degree_start(sp, i + j) + j] += scale * f[i] * g[j];
    }
}

/* Local coordinates (three jets) to space: rotated by the frame when
 * placed, then moved to the center. */
static void to_space(const ic_surface *s, double *xyz, const ic_jet_space *sp)
{
    const int n = ic_jet_space_len(sp);
    if (s->placed)
        ic_placement_jets_to_space(s->frame, xyz, n);
    for (int k = 0; k < 3; k++)
        xyz[k * n] += s->prim.center[k];
}

static void parametric_taylor(const ic_surface *s, double *out, const double *at,
                              const ic_jet_space *sp)
{
    const ic_primitive *p = &s->prim;
    const int K = ic_jet_space_order(sp), n = ic_jet_space_len(sp);
    double cu[MAXK], su[MAXK], cv[MAXK], sv[MAXK], lu[MAXK], lv[MAXK], one[MAXK];
    taylor_cos_sin(cu, su, at[0], K);
    taylor_cos_sin(cv, sv, at[1], K);
    taylor_linear(lu, at[0], K);
    taylor_linear(lv, at[1], K);
    taylor_one(one, K);
    double *x = out, *y = out + n, *z = out + 2 * n;
    memset(out, 0, 3 * (size_t)n * sizeof *out);
    switch (p->kind) {
    case IC_PRIM_PLANE:
        for (int k = 0; k < 3; k++) {
            add_tensor(out + k * n, sp, s->plane_frame[0][k], lu, one);
            add_tensor(out + k * n, sp, s->plane_frame[1][k], one, lv);
        }
        break;
    case IC_PRIM_SPHERE:
    case IC_PRIM_ELLIPSOID: {
        const double a = p->kind == IC_PRIM_SPHERE ? p->radius : p->axes[0];
        const double b = p->kind == IC_PRIM_SPHERE ? p->radius : p->axes[1];
        const double c = p->kind == IC_PRIM_SPHERE ? p->radius : p->axes[2];
        add_tensor(x, sp, a, cu, cv);
        add_tensor(y, sp, b, su, cv);
        add_tensor(z, sp, c, one, sv);
        break;
    }
    case IC_PRIM_CYLINDER:
        add_tensor(x, sp, p->radius, cu, one);
        add_tensor(y, sp, p->radius, su, one);
        add_tensor(z, sp, 1.0, one, lv);
        break;
    case IC_PRIM_CONE: {
        const double t = tan(p->half_angle);
        add_tensor(x, sp, t, cu, lv);
        add_tensor(y, sp, t, su, lv);
        add_tensor(z, sp, 1.0, one, lv);
        break;
    }
    case IC_PRIM_TORUS:
        add_tensor(x, sp, p->major_radius, cu, one);
        add_tensor(x, sp, p->radius, cu, cv);
        add_tensor(y, sp, p->major_radius, su, one);
        add_tensor(y, sp, p->radius, su, cv);
        add_tensor(z, sp, p->radius, one, sv);
        break;
    }
    to_space(s, out, sp);
}

/* sum_i A_i d_i^2 + B_i d_i + C with d = x - center. */
static void quadric_taylor(const ic_surface *s, double *out, const double *at,
                           const ic_jet_space *sp, const double A[3], const double B[3], double C)
{
    const int K = ic_jet_space_order(sp);
    ic_jet_zero(out, sp);
    double f = C;
    for (int i = 0; i < 3; i++) {
        const double d = at[i] - s->prim.center[i];
        f += (A[i] * d + B[i]) * d;
        if (K >= 1)
            out[1 + i] = 2.0 * A[i] * d + B[i];
        if (K >= 2) {
            int alpha[3] = {0, 0, 0};
            alpha[i] = 2;
            out[ic_jet_index(sp, alpha)] = A[i];
        }
    }
    out[0] = f;
}

/* The implicit torus on jets d = x - center (w: 4 jets of workspace). */
static void torus_on_jets(const ic_primitive *p, double *out, double *const d[3],
                          const ic_jet_space *sp, double *w)
{
    const int n = ic_jet_space_len(sp);
    double *sq = w, *sum = w + n, *rho = w + 2 * n, *tmp = w + 3 * n;
    const double R = p->major_radius, r = p->radius;
    ic_jet_zero(rho, sp); /* (x-cx)^2 + (y-cy)^2 */
    for (int i = 0; i < 2; i++) {
        ic_jet_mul(sq, d[i], d[i], sp);
        ic_jet_add(rho, rho, sq, sp);
    }
    ic_jet_mul(sq, d[2], d[2], sp);
    ic_jet_add(sum, rho, sq, sp);
    sum[0] += R * R - r * r;
    ic_jet_mul(tmp, sum, sum, sp);
    ic_jet_scale(rho, rho, -4.0 * R * R, sp);
    ic_jet_add(out, tmp, rho, sp);
}

void ic_primitive_quadric_coefficients(const ic_primitive *p, double A[3], double B[3], double *C)
{
    for (int i = 0; i < 3; i++)
        A[i] = B[i] = 0.0;
    *C = 0.0;
    switch (p->kind) {
    case IC_PRIM_PLANE:
        for (int i = 0; i < 3; i++)
            B[i] = p->normal[i];
        break;
    case IC_PRIM_SPHERE:
        A[0] = A[1] = A[2] = 1.0;
        *C = -p->radius * p->radius;
        break;
    case IC_PRIM_CYLINDER:
        A[0] = A[1] = 1.0;
        *C = -p->radius * p->radius;
        break;
    case IC_PRIM_CONE: {
        const double t = tan(p->half_angle);
        A[0] = A[1] = 1.0;
        A[2] = -t * t;
        break;
    }
    case IC_PRIM_ELLIPSOID:
        for (int i = 0; i < 3; i++)
            A[i] = 1.0 / (p->axes[i] * p->axes[i]);
        *C = -1.0;
        break;
    case IC_PRIM_TORUS:
        break;
    }
}

/* Parametric primitive on jets u, v (w: 4 jets of workspace). */
static void parametric_on_jets(const ic_surface *s, double *out, const double *u, const double *v,
                               const ic_jet_space *sp, double *w)
{
    const ic_primitive *p = &s->prim;
    const int n = ic_jet_space_len(sp);
    double *x = out, *y = out + n, *z = out + 2 * n;
    double *cu = w, *su = w + n, *cv = w + 2 * n, *sv = w + 3 * n;
    ic_jet_sin_cos(su, cu, u, sp);
    ic_jet_sin_cos(sv, cv, v, sp);
    switch (p->kind) {
    case IC_PRIM_PLANE:
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < n; i++)
                out[k * n + i] = s->plane_frame[0][k] * u[i] + s->plane_frame[1][k] * v[i];
        break;
    case IC_PRIM_SPHERE:
    case IC_PRIM_ELLIPSOID: {
        const int sph = p->kind == IC_PRIM_SPHERE;
        ic_jet_mul(x, cu, cv, sp);
        ic_jet_scale(x, x, sph ? p->radius : p->axes[0], sp);
        ic_jet_mul(y, su, cv, sp);
        ic_jet_scale(y, y, sph ? p->radius : p->axes[1], sp);
        ic_jet_scale(z, sv, sph ? p->radius : p->axes[2], sp);
        break;
    }
    case IC_PRIM_CYLINDER:
        ic_jet_scale(x, cu, p->radius, sp);
        ic_jet_scale(y, su, p->radius, sp);
        ic_jet_copy(z, v, sp);
        break;
    case IC_PRIM_CONE: {
        const double t = tan(p->half_angle);
        ic_jet_mul(x, cu, v, sp);
        ic_jet_scale(x, x, t, sp);
        ic_jet_mul(y, su, v, sp);
        ic_jet_scale(y, y, t, sp);
        ic_jet_copy(z, v, sp);
        break;
    }
    case IC_PRIM_TORUS:
        ic_jet_scale(cv, cv, p->radius, sp); /* w = R + r cos v */
        cv[0] += p->major_radius;
        ic_jet_mul(x, cv, cu, sp);
        ic_jet_mul(y, cv, su, sp);
        ic_jet_scale(z, sv, p->radius, sp);
        break;
    }
    to_space(s, out, sp);
}

/* f_local on the jets d of the local coordinates (w: 4 jets of workspace). */
static void implicit_on_jets(const ic_primitive *p, double *out, double *const d[3],
                             const ic_jet_space *sp, double *w)
{
    if (p->kind == IC_PRIM_TORUS) {
        torus_on_jets(p, out, d, sp, w);
        return;
    }
    const int n = ic_jet_space_len(sp);
    double A[3], B[3], C, *sq = w;
    ic_primitive_quadric_coefficients(p, A, B, &C);
    ic_jet_set_const(out, C, sp);
    for (int i = 0; i < 3; i++) {
        if (A[i] != 0.0) {
            ic_jet_mul(sq, d[i], d[i], sp);
            for (int j = 0; j < n; j++)
                out[j] += A[i] * sq[j];
        }
        for (int j = 0; j < n; j++)
            out[j] += B[i] * d[i][j];
    }
}

ic_status ic_primitive_compose(ic_surface *s, double *out, const double *const *in,
                               const ic_jet_space *sp, ic_error *err)
{
    const int n = ic_jet_space_len(sp);
    double *w = ic_surface_work(s, IC_WORK_COMPOSE, 7 * (size_t)n);
    if (!w)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory composing a primitive");
    if (s->kind == IC_PARAMETRIC) {
        parametric_on_jets(s, out, in[0], in[1], sp, w);
        return IC_OK;
    }
    double *d[3] = {w, w + n, w + 2 * n};
    for (int i = 0; i < 3; i++) {
        ic_jet_copy(d[i], in[i], sp);
        d[i][0] -= s->prim.center[i];
    }
    if (s->placed)
        ic_placement_jets_to_local(s->frame, d, n);
    implicit_on_jets(&s->prim, out, d, sp, w + 3 * n);
    return IC_OK;
}

/* The implicit torus, and every placed implicit primitive, at a point: f_local
 * on the jets of the local coordinates, linear in x, y, z. */
static ic_status taylor_on_jets(ic_surface *s, double *out, const double *at,
                                const ic_jet_space *sp, ic_error *err)
{
    const int n = ic_jet_space_len(sp);
    double *w = ic_surface_work(s, IC_WORK_EVAL, 7 * (size_t)n);
    if (!w)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory evaluating a primitive");
    double *d[3] = {w, w + n, w + 2 * n};
    for (int i = 0; i < 3; i++)
        ic_jet_set_var(d[i], at[i] - s->prim.center[i], i, sp);
    if (s->placed)
        ic_placement_jets_to_local(s->frame, d, n);
    implicit_on_jets(&s->prim, out, d, sp, w + 3 * n);
    return IC_OK;
}

ic_status ic_primitive_taylor(ic_surface *s, double *out, const double *at, const ic_jet_space *sp,
                              ic_error *err)
{
    if (s->kind == IC_PARAMETRIC) {
        parametric_taylor(s, out, at, sp);
        return IC_OK;
    }
    if (s->prim.kind == IC_PRIM_TORUS || s->placed)
        return taylor_on_jets(s, out, at, sp, err);
    double A[3], B[3], C;
    ic_primitive_quadric_coefficients(&s->prim, A, B, &C);
    quadric_taylor(s, out, at, sp, A, B, C);
    return IC_OK;
}

/*
 * Abdel-All et al. (2012), section 4 (docs/references.md): tangential
 * intersection of two implicit surfaces f = 0, h = 0 with grad f = A grad h
 * (4.1), the curve parametrised by a coordinate, beta = (x1, x2(x1), x3(x1)).
 * Derived again before transcription (docs/ERRATA.md lists the printed
 * errors this corrects):
 *  - directions (4.8)-(4.10): beta'^T D beta' = 0, D = H1 - A H2, with
 *    grad f . beta' = 0; a11 x3'^2 + 2 a12 x3' + a13 = 0 as printed;
 *  - curvature: grad h . beta'' = -beta'^T H2 beta' (4.15) and, from
 *    grad f . beta''' = A grad h . beta''' with (3.4) for f and h,
 *    3 beta'^T D beta'' = A T_h - T_f (T = sum g_ijk beta'beta'beta'),
 *    the corrected (4.16)-(4.18);
 *  - torsion: grad h . beta''' = -3 beta'^T H2 beta'' - T_h (3.4) and, from
 *    grad f . beta'''' = A grad h . beta'''' with the fourth derivative
 *    g_ijkl b'^4 + 6 g_ijk b'b'b'' + 3 b''^T H b'' + 4 b'^T H b''' + grad g . b''''
 *    (the corrected (3.5)), 4 beta'^T D beta''' = A F_h - F_f; then (4.23).
 * The parametrising coordinate is chosen per branch: x2 is the axis along
 * which the normal is largest, x1 the remaining axis along which the branch
 * moves most (the paper's "without loss of generality").
 */
#include "tangential.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

typedef struct {
    double g[3], H[3][3], T[3][3][3], F[3][3][3][3];
} derivs4;

static void load(derivs4 *d, const ic_sheet *sh, const int *perm)
{
    for (int i = 0; i < 3; i++) {
        int e[3] = {0, 0, 0};
        e[perm[i]]++;
        d->g[i] = ic_sheet_fpartial(sh, e[0], e[1], e[2]);
        for (int j = 0; j < 3; j++) {
            int e2[3] = {0, 0, 0};
            e2[perm[i]]++, e2[perm[j]]++;
            d->H[i][j] = ic_sheet_fpartial(sh, e2[0], e2[1], e2[2]);
            for (int k = 0; k < 3; k++) {
                int e3[3] = {0, 0, 0};
                e3[perm[i]]++, e3[perm[j]]++, e3[perm[k]]++;
                d->T[i][j][k] = ic_sheet_fpartial(sh, e3[0], e3[1], e3[2]);
                for (int l = 0; l < 3; l++) {
                    int e4[3] = {0, 0, 0};
                    e4[perm[i]]++, e4[perm[j]]++, e4[perm[k]]++, e4[perm[l]]++;
                    d->F[i][j][k][l] = ic_sheet_fpartial(sh, e4[0], e4[1], e4[2]);
                }
            }
        }
    }
}

static double q2(const double H[3][3], const double *a, const double *b)
{
    double s = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            s += H[i][j] * a[i] * b[j];
    return s;
}

/* sum T_ijk a_i a_j b_k */
static double q3(const double T[3][3][3], const double *a, const double *b)
{
    double s = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                s += T[i][j][k] * a[i] * a[j] * b[k];
    return s;
}

static double q4(const double F[3][3][3][3], const double *a)
{
    double s = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                for (int l = 0; l < 3; l++)
                    s += F[i][j][k][l] * a[i] * a[j] * a[k] * a[l];
    return s;
}

/* x2, x3 components of a solution of [r; h] y = [s; sh] with y_1 = 0 */
static int solve23(double *y, const double *r, double s, const double *h, double sh)
{
    const double det = r[1] * h[2] - r[2] * h[1];
    if (det == 0.0 || !isfinite(det))
        return -1;
    y[0] = 0.0;
    y[1] = (s * h[2] - sh * r[2]) / det;
    y[2] = (r[1] * sh - h[1] * s) / det;
    return 0;
}

/* The axes of the paper's parametrisation for a branch along dir (NULL: any):
 * its own (x, y, z) where f2 and the branch's x-component are clearly
 * nonzero; otherwise x2 along the largest normal component and x1 the other
 * axis along which dir is largest (perm[new] = old). */
static void choose_axes(int perm[3], const double *N, const double *dir)
{
    int a1 = 0, a2 = 1, a3 = 2;
    if (!(fabs(N[1]) >= 0.3 && (!dir || fabs(dir[0]) >= 0.3 * ic_norm3(dir)))) {
        a2 = 0;
        for (int k = 1; k < 3; k++)
            if (fabs(N[k]) > fabs(N[a2]))
                a2 = k;
        a1 = (a2 + 1) % 3, a3 = (a2 + 2) % 3;
        if (dir && fabs(dir[a3]) > fabs(dir[a1])) {
            const int tmp = a1;
            a1 = a3, a3 = tmp;
        }
    }
    perm[0] = a1, perm[1] = a2, perm[2] = a3;
}

/* A of (4.1) and a11, a12, a13 of (4.10) in the axes perm; D = H1 - A H2. */
static void coefficients(double paper[4], double D[3][3], const derivs4 *f, const derivs4 *h)
{
    int kmax = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(h->g[k]) > fabs(h->g[kmax]))
            kmax = k;
    const double A = f->g[kmax] / h->g[kmax];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            D[i][j] = f->H[i][j] - A * h->H[i][j];
    const double f1 = f->g[0], f2 = f->g[1], f3 = f->g[2];
    paper[0] = A;
    paper[1] = f2 * f2 * D[2][2] - 2 * f2 * f3 * D[1][2] + f3 * f3 * D[1][1];
    paper[2] = f2 * f2 * D[0][2] - f1 * f2 * D[1][2] - f2 * f3 * D[0][1] + f1 * f3 * D[1][1];
    paper[3] = f1 * f1 * D[1][1] - 2 * f1 * f2 * D[0][1] + f2 * f2 * D[0][0];
}

void ic_closed_abdel_all_coefficients(ic_local_result *res, const ic_sheet sh[2])
{
    int perm[3];
    choose_axes(perm, sh[0].geo.normal, NULL);
    derivs4 f, h;
    load(&f, &sh[0], perm);
    load(&h, &sh[1], perm);
    double D[3][3];
    coefficients(res->paper_values, D, &f, &h);
    res->npaper = 4;
    res->paper_names[0] = "A", res->paper_names[1] = "a11";
    res->paper_names[2] = "a12", res->paper_names[3] = "a13";
}

/* One branch whose tangent (in the original axes) is `dir`. */
static int branch(ic_branch *br, const ic_sheet sh[2], const double *dir, double *paper)
{
    int perm[3];
    choose_axes(perm, sh[0].geo.normal, dir);
    const int a1 = perm[0], a3 = perm[2];
    derivs4 f, h;
    load(&f, &sh[0], perm);
    load(&h, &sh[1], perm);
    double D[3][3];
    coefficients(paper, D, &f, &h); /* (4.1), (4.10) */
    const double A = paper[0], f1 = f.g[0], f2 = f.g[1], f3 = f.g[2];
    /* (4.9): a11 x3'^2 + 2 a12 x3' + a13 = 0; of its roots the one along this
     * branch (dir only picks the root); x2' from grad f . beta' = 0 (4.6), as
     * in the roots printed after (4.10) */
    const double a11 = paper[1], a12 = paper[2], a13 = paper[3];
    const double want = dir[a3] / dir[a1];
    double x3d;
    if (fabs(a11) > 1e-12 * (fabs(a12) + fabs(a13))) {
        const double root = sqrt(fmax(a12 * a12 - a11 * a13, 0.0));
        const double r1 = (-a12 + root) / a11, r2 = (-a12 - root) / a11;
        x3d = fabs(r1 - want) <= fabs(r2 - want) ? r1 : r2;
    } else {
        x3d = -a13 / (2 * a12); /* one finite root; the other is x1' = 0 */
    }
    double b1[3];
    b1[0] = 1.0;
    b1[2] = x3d;
    b1[1] = -(f1 + f3 * b1[2]) / f2;
    /* curvature: (4.15) and the corrected (4.16) */
    double Db[3];
    for (int i = 0; i < 3; i++)
        Db[i] = D[i][0] * b1[0] + D[i][1] * b1[1] + D[i][2] * b1[2];
    const double Tf = q3(f.T, b1, b1), Th = q3(h.T, b1, b1);
    double r[3], b2[3];
    for (int i = 0; i < 3; i++)
        r[i] = 3 * Db[i];
    if (solve23(b2, r, A * Th - Tf, h.g, -q2(h.H, b1, b1)) != 0)
        return -1;
    /* torsion: (3.4) for h and the corrected fourth-order condition */
    const double Ff = q4(f.F, b1) + 6 * q3(f.T, b1, b2) + 3 * q2(f.H, b2, b2);
    const double Fh = q4(h.F, b1) + 6 * q3(h.T, b1, b2) + 3 * q2(h.H, b2, b2);
    double b3[3];
    for (int i = 0; i < 3; i++)
        r[i] = 4 * Db[i];
    if (solve23(b3, r, A * Fh - Ff, h.g, -3 * q2(h.H, b1, b2) - q3(h.T, b1, b1)) != 0)
        return -1;
    double c[3][3];
    ic_arc_length_derivs(c, b1, b2, b3);
    memset(br, 0, sizeof *br);
    br->order = 3;
    br->regular = 1;
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++)
            br->derivs[k][perm[i]] = c[k][i];
    /* the orientation of the other tangential methods */
    for (int k = 0; k < 3; k++)
        if (fabs(br->derivs[0][k]) > 1e-9) {
            if (br->derivs[0][k] < 0) {
                ic_scale3(br->derivs[0], br->derivs[0], -1.0);
                ic_scale3(br->derivs[2], br->derivs[2], -1.0);
            }
            break;
        }
    return 0;
}

ic_status ic_closed_abdel_all_tangential(ic_local_result *res, const ic_sheet sh[2],
                                         const ic_local_options *opt, ic_error *err)
{
    (void)opt;
    if (sh[0].parametric || sh[1].parametric)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "Abdel-All et al. (2012), section 4, needs two implicit sheets");
    if (!(res->type == IC_POINT_BRANCH || res->type == IC_POINT_TANGENTIAL_CURVE) ||
        res->nbranches < 1)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "the closed form (Abdel-All et al. (2012), section 4) gives the "
                            "branches of branch points and tangential curves; this point is %s",
                            ic_point_type_name(res->type));
    /* the directions solve beta'^T D beta' = 0 in the tangent plane, the
     * roots of (4.9); the classification's branches give which root is which */
    ic_branch out[IC_LOCAL_MAX_BRANCHES];
    double paper[4] = {0, 0, 0, 0};
    for (int b = 0; b < res->nbranches; b++) {
        const double *t = res->branches[b].derivs[0]; /* the classification's tangent */
        if (branch(&out[b], sh, t, paper) != 0)
            return ic_error_set(err, IC_ERR_UNABLE, 0,
                                "Abdel-All et al. (2012), eq. (4.18): Omega = 0, the system "
                                "for x2'', x3'' is singular (as on a tangential curve, where "
                                "the paper's formulas do not apply); use height-difference");
    }
    memcpy(res->branches, out, (size_t)res->nbranches * sizeof out[0]);
    res->npaper = 4;
    res->paper_names[0] = "A", res->paper_values[0] = paper[0];
    res->paper_names[1] = "a11", res->paper_values[1] = paper[1];
    res->paper_names[2] = "a12", res->paper_values[2] = paper[2];
    res->paper_names[3] = "a13", res->paper_values[3] = paper[3];
    return IC_OK;
}

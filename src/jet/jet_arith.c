/* Linear operations, product and quotient of jets (jet.h). */
#include "common/args.h"
#include "jet_internal.h"

#include <math.h>
#include <string.h>

void ic_jet_zero(double *c, const ic_jet_space *sp)
{
    if (!c || !sp)
        return;
    memset(c, 0, (size_t)sp->n * sizeof *c);
}

void ic_jet_set_const(double *c, double value, const ic_jet_space *sp)
{
    if (!c || !sp)
        return;
    ic_jet_zero(c, sp);
    c[0] = value;
}

void ic_jet_set_var(double *c, double value, int var, const ic_jet_space *sp)
{
    if (!c || !sp)
        return;
    ic_jet_set_const(c, value, sp);
    if (sp->K >= 1 && var >= 0 && var < sp->m)
        c[1 + var] = 1.0; /* degree-1 monomials are x_0, x_1, ... in order */
}

void ic_jet_copy(double *c, const double *a, const ic_jet_space *sp)
{
    if (!c || !a || !sp)
        return;
    if (c != a)
        memmove(c, a, (size_t)sp->n * sizeof *c);
}

void ic_jet_add(double *c, const double *a, const double *b, const ic_jet_space *sp)
{
    if (!c || !a || !b || !sp)
        return;
    for (int i = 0; i < sp->n; i++)
        c[i] = a[i] + b[i];
}

void ic_jet_sub(double *c, const double *a, const double *b, const ic_jet_space *sp)
{
    if (!c || !a || !b || !sp)
        return;
    for (int i = 0; i < sp->n; i++)
        c[i] = a[i] - b[i];
}

void ic_jet_neg(double *c, const double *a, const ic_jet_space *sp)
{
    if (!c || !a || !sp)
        return;
    for (int i = 0; i < sp->n; i++)
        c[i] = -a[i];
}

void ic_jet_scale(double *c, const double *a, double s, const ic_jet_space *sp)
{
    if (!c || !a || !sp)
        return;
    for (int i = 0; i < sp->n; i++)
        c[i] = s * a[i];
}

void ic_jet_add_const(double *c, const double *a, double s, const ic_jet_space *sp)
{
    if (!c || !a || !sp)
        return;
    ic_jet_copy(c, a, sp);
    c[0] += s;
}

void ic_jet_mul(double *c, const double *a, const double *b, const ic_jet_space *sp)
{
    if (!c || !a || !b || !sp)
        return;
    if (sp->m == 1) { /* plain convolution: the common case of curve jets */
        for (int k = 0; k <= sp->K; k++) {
            double sum = 0.0;
            for (int i = 0; i <= k; i++)
                sum += a[i] * b[k - i];
            c[k] = sum;
        }
        return;
    }
    ic_jet_zero(c, sp);
    for (int j = 0; j <= sp->K; j++)
        for (int k = 0; j + k <= sp->K; k++)
            ic_jet_hacc(sp, c, a, j, b, k, 1.0);
}

/* q b = a, degree by degree: q_d = (a_d - sum_{j=1..d} b_j q_{d-j}) / b_0. */
ic_status ic_jet_div(double *q, const double *a, const double *b, const ic_jet_space *sp,
                     ic_error *err)
{
    IC_ARG_NOT_NULL(q, "q");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(sp, "sp");
    if (b[0] == 0.0 || !isfinite(b[0]))
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "division by a jet whose value is %g", b[0]);
    const double inv = 1.0 / b[0];
    for (int d = 0; d <= sp->K; d++) {
        for (int i = sp->deg_start[d]; i < sp->deg_start[d + 1]; i++)
            q[i] = a[i];
        for (int j = 1; j <= d; j++)
            ic_jet_hacc(sp, q, b, j, q, d - j, -1.0);
        ic_jet_part_scale(sp, q, d, inv);
    }
    return IC_OK;
}

/* Composition one degree at a time (jet_chain.h). */
#include "jet_chain.h"
#include "jet_internal.h"

#include <string.h>

int ic_jet_support_degree(const double *P, const ic_jet_space *sp_p)
{
    for (int i = sp_p->n - 1; i > 0; i--)
        if (P[i] != 0.0) {
            int d = 1;
            while (sp_p->deg_start[d + 1] <= i)
                d++;
            return d;
        }
    return 0;
}

/* The chain's highest degree: P's, the spaces' and the caller's bounds. */
static int chain_degree(const ic_jet_space *sp_p, int deg, const ic_jet_space *sp)
{
    if (deg > sp_p->K)
        deg = sp_p->K;
    if (deg > sp->K)
        deg = sp->K;
    return deg;
}

/* Number of monomials of sp_p of degree 2..deg. */
static size_t nonlinear_count(const ic_jet_space *sp_p, int deg)
{
    return deg < 2 ? 0 : (size_t)(sp_p->deg_start[deg + 1] - sp_p->deg_start[2]);
}

size_t ic_jet_chain_len(const ic_jet_space *sp_p, int deg, const ic_jet_space *sp)
{
    return nonlinear_count(sp_p, chain_degree(sp_p, deg, sp)) * (size_t)sp->n;
}

void ic_jet_chain_init(ic_jet_chain *ch, const ic_jet_space *sp_p, int deg,
                       const double *const *delta, const ic_jet_space *sp, double *work)
{
    ch->sp_p = sp_p;
    ch->sp = sp;
    ch->deg = chain_degree(sp_p, deg, sp);
    for (int i = 0; i < sp_p->m && i < IC_JET_MAX_VARS; i++)
        ch->delta[i] = delta[i];
    ch->pw = work;
    const size_t len = nonlinear_count(sp_p, ch->deg) * (size_t)sp->n;
    if (len)
        memset(work, 0, len * sizeof *work);
}

/* The jet of delta^alpha for monomial i of sp_p (degree 1: the delta). */
static const double *power(const ic_jet_chain *ch, int i)
{
    const ic_jet_space *sp_p = ch->sp_p;
    if (i < sp_p->deg_start[2])
        return ch->delta[i - 1];
    return ch->pw + (size_t)(i - sp_p->deg_start[2]) * (size_t)ch->sp->n;
}

/* [delta^alpha]_k for monomial i of degree d >= 2 into its jet. */
static void extend_one(ic_jet_chain *ch, int i, int d, int k)
{
    const ic_jet_space *sp = ch->sp;
    const int v = ch->sp_p->lower_var[i];
    const double *dv = ch->delta[v], *low = power(ch, ch->sp_p->lower[i]);
    double *out = (double *)power(ch, i);
    if (sp->m == 1) { /* one coefficient per degree: a plain convolution */
        double sum = 0.0;
        for (int j = 1; j <= k - d + 1; j++)
            sum += dv[j] * low[k - j];
        out[k] = sum;
        return;
    }
    ic_jet_part_zero(sp, out, k);
    for (int j = 1; j <= k - d + 1; j++)
        ic_jet_hacc(sp, out, dv, j, low, k - j, 1.0);
}

void ic_jet_chain_extend(ic_jet_chain *ch, int k)
{
    const ic_jet_space *sp_p = ch->sp_p;
    const int top = k < ch->deg ? k : ch->deg;
    /* by degree: each monomial's lower one is final below degree k, and
     * its degree-k part is not read */
    for (int d = 2; d <= top; d++)
        for (int i = sp_p->deg_start[d]; i < sp_p->deg_start[d + 1]; i++)
            extend_one(ch, i, d, k);
}

void ic_jet_chain_part(const ic_jet_chain *ch, double *out, const double *P, int k)
{
    const ic_jet_space *sp_p = ch->sp_p, *sp = ch->sp;
    const int top = k < ch->deg ? k : ch->deg;
    ic_jet_part_zero(sp, out, k);
    if (top < 1)
        return;
    for (int i = 1; i < sp_p->deg_start[top + 1]; i++)
        if (P[i] != 0.0)
            ic_jet_part_axpy(sp, out, k, P[i], power(ch, i));
}

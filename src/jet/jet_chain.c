/* Composition one degree at a time (jet_chain.h). */
#include "jet_chain.h"
#include "jet_internal.h"

#include <stdint.h>
#include <string.h>

/* Whether a degree's coefficients are all zero (either sign): an OR of
 * their bits without the sign, which the compiler vectorises; the polynomials
 * scanned are mostly zero above a low degree (quadrics, polynomials). */
static int part_is_zero(const double *P, int i0, int i1)
{
    const uint64_t magnitude = ~((uint64_t)1 << 63);
    uint64_t any = 0;
    for (int i = i0; i < i1; i++) {
        uint64_t bits;
        memcpy(&bits, &P[i], sizeof bits);
        any |= bits & magnitude;
    }
    return any == 0;
}

/* The highest degree <= top with a nonzero coefficient of P (0 if none). */
static int support_below(const double *P, const ic_jet_space *sp_p, int top)
{
    for (int d = top; d > 0; d--)
        if (!part_is_zero(P, sp_p->deg_start[d], sp_p->deg_start[d + 1]))
            return d;
    return 0;
}

int ic_jet_support_degree(const double *P, const ic_jet_space *sp_p)
{
    return support_below(P, sp_p, sp_p->K);
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

/* Doubles holding one byte per monomial of sp_p up to degree deg. */
static size_t flag_len(const ic_jet_space *sp_p, int deg)
{
    return ((size_t)sp_p->deg_start[deg + 1] + sizeof(double) - 1) / sizeof(double);
}

size_t ic_jet_chain_len(const ic_jet_space *sp_p, int deg, const ic_jet_space *sp)
{
    deg = chain_degree(sp_p, deg, sp);
    return nonlinear_count(sp_p, deg) * (size_t)sp->n + flag_len(sp_p, deg);
}

/* Marks the power products the polynomials' terms need, and the lower
 * ones each is built from (from the top down: a monomial's lower one has a
 * smaller index). */
static void mark_needed(ic_jet_chain *ch, const double *const *P, int np)
{
    const ic_jet_space *sp_p = ch->sp_p;
    const int top = sp_p->deg_start[ch->deg + 1];
    memset(ch->need, 0, (size_t)top);
    if (ch->deg < 2)
        return;
    for (int i = top - 1; i >= sp_p->deg_start[2]; i--) {
        for (int q = 0; q < np && !ch->need[i]; q++)
            ch->need[i] = P[q][i] != 0.0;
        if (ch->need[i])
            ch->need[sp_p->lower[i]] = 1;
    }
}

void ic_jet_chain_init(ic_jet_chain *ch, const ic_jet_space *sp_p, const double *const *P,
                       int np, const double *const *delta, const ic_jet_space *sp, double *work)
{
    ic_jet_chain_init_upto(ch, sp_p, P, np, sp_p->K, delta, sp, work);
}

void ic_jet_chain_init_upto(ic_jet_chain *ch, const ic_jet_space *sp_p, const double *const *P,
                            int np, int bound, const double *const *delta,
                            const ic_jet_space *sp, double *work)
{
    const int top = bound < 0 || bound > sp_p->K ? sp_p->K : bound;
    int deg = 0;
    for (int q = 0; q < np; q++) {
        const int d = support_below(P[q], sp_p, top);
        deg = d > deg ? d : deg;
    }
    ch->sp_p = sp_p;
    ch->sp = sp;
    ch->deg = chain_degree(sp_p, deg, sp);
    for (int i = 0; i < sp_p->m && i < IC_JET_MAX_VARS; i++)
        ch->delta[i] = delta[i];
    ch->pw = work;
    const size_t len = nonlinear_count(sp_p, ch->deg) * (size_t)sp->n;
    if (len)
        memset(work, 0, len * sizeof *work);
    ch->need = (unsigned char *)(work + len);
    mark_needed(ch, P, np);
    ch->delta_deg = sp->K;
}

void ic_jet_chain_set_delta_degree(ic_jet_chain *ch, int deg) { ch->delta_deg = deg; }

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
    const double *dv = ch->delta[ch->sp_p->lower_var[i]], *low = power(ch, ch->sp_p->lower[i]);
    double *out = (double *)power(ch, i);
    /* delta_v has no terms above delta_deg */
    const int jmax = k - d + 1 < ch->delta_deg ? k - d + 1 : ch->delta_deg;
    if (sp->m == 1) { /* one coefficient per degree: a plain convolution */
        double sum = 0.0;
        for (int j = 1; j <= jmax; j++)
            sum += dv[j] * low[k - j];
        out[k] = sum;
        return;
    }
    ic_jet_part_zero(sp, out, k);
    for (int j = 1; j <= jmax; j++)
        ic_jet_hacc(sp, out, dv, j, low, k - j, 1.0);
}

void ic_jet_chain_extend(ic_jet_chain *ch, int k)
{
    const ic_jet_space *sp_p = ch->sp_p;
    const int top = k < ch->deg ? k : ch->deg;
    /* by degree: each monomial's lower one is final below degree k, and
     * its degree-k part is not read */
    for (int d = 2; d <= top; d++) {
        if (k > d * ch->delta_deg) /* no terms of degree k: zero from init */
            continue;
        for (int i = sp_p->deg_start[d]; i < sp_p->deg_start[d + 1]; i++)
            if (ch->need[i])
                extend_one(ch, i, d, k);
    }
}

/* The one-variable case: out[k] as one sum over P's terms (the curve of the
 * jet method, the reversions of one variable). */
static void part_univariate(const ic_jet_chain *ch, double *out, const double *P, int k, int top)
{
    const ic_jet_space *sp_p = ch->sp_p;
    const int s2 = sp_p->deg_start[2], n = ch->sp->n;
    double sum = 0.0;
    for (int v = 0; v < sp_p->m; v++)
        sum += P[1 + v] * ch->delta[v][k];
    const double *pw = ch->pw + k;
    for (int i = s2; i < sp_p->deg_start[top + 1]; i++)
        sum += P[i] * pw[(size_t)(i - s2) * (size_t)n];
    out[k] = sum;
}

void ic_jet_chain_part(const ic_jet_chain *ch, double *out, const double *P, int k)
{
    const ic_jet_space *sp_p = ch->sp_p, *sp = ch->sp;
    const int top = k < ch->deg ? k : ch->deg;
    ic_jet_part_zero(sp, out, k);
    if (top < 1)
        return;
    if (sp->m == 1) {
        part_univariate(ch, out, P, k, top);
        return;
    }
    for (int i = 1; i < sp_p->deg_start[top + 1]; i++)
        if (P[i] != 0.0)
            ic_jet_part_axpy(sp, out, k, P[i], power(ch, i));
}

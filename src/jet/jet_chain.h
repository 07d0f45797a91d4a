/*
 * Composition one degree at a time ("relaxed" composition): the degree-k
 * part of P(delta_1, ..., delta_p) from the parts of degree < k of the deltas
 * (and the degree-k part of the deltas through P's linear terms only).
 *
 * An algorithm that finds the degree-k coefficients of the deltas from the
 * degree-k part of the composition (series reversion, the curve of the jet
 * method, the heights at a tangential point) recomposed the whole series at
 * every degree: O(K) compositions. The chain instead keeps every power
 * product delta^alpha, 2 <= |alpha| <= deg, and extends each by one degree
 * per step with the product rule
 *     [delta^alpha]_k = sum_{j=1}^{k-|alpha|+1} [delta_v]_j [delta^(alpha - e_v)]_{k-j}
 * (the Cauchy product; v the first variable of alpha; delta^(alpha - e_v)
 * has no terms below degree |alpha| - 1): only parts of degree < k of the
 * deltas enter, so the parts already computed are final. This is on-line
 * ("relaxed") multiplication in its naive quadratic form (van der Hoeven,
 * "Relax, but don't be too lazy", J. Symbolic Comput. 34 (2002)). Every
 * coefficient is then computed once.
 *
 * Only the power products the polynomials need are kept: those of their
 * nonzero terms and the lower ones these are built from (a quadric needs
 * its own squares and products only).
 *
 * Usage: ic_jet_chain_init once with the polynomials, then for k = 1, 2,
 * ... in order ic_jet_chain_extend(k) (the deltas final below degree k) and
 * ic_jet_chain_part(k) for each polynomial.
 */
#ifndef IC_JET_CHAIN_H
#define IC_JET_CHAIN_H

#include "intercurve/jet.h"

typedef struct {
    const ic_jet_space *sp_p; /* P's space: p variables */
    const ic_jet_space *sp;   /* the deltas' space */
    int deg;                  /* the power products kept: degrees 2..deg */
    const double *delta[IC_JET_MAX_VARS];
    double *pw;          /* their jets, one per monomial of sp_p of degree 2..deg */
    unsigned char *need; /* per monomial of sp_p up to degree deg: computed or not */
    int delta_deg;       /* the deltas have no terms above this degree */
} ic_jet_chain;

/* Highest degree with a nonzero coefficient of P (0 if none): the power
 * products above it are never needed (a quadric's are of degree 2). */
int ic_jet_support_degree(const double *P, const ic_jet_space *sp_p);

/* Doubles of work a chain of P's space up to degree `deg` over sp needs
 * (deg = the order of sp_p: enough for any polynomial). */
size_t ic_jet_chain_len(const ic_jet_space *sp_p, int deg, const ic_jet_space *sp);

/* Starts a chain for the np polynomials P[0..np-1] of sp_p: delta[i] are p
 * jets of sp (their constant terms are ignored; they are read, never
 * written, and may change between steps in the degrees not yet final);
 * work holds ic_jet_chain_len(sp_p, d, sp) doubles, d at least the
 * polynomials' ic_jet_support_degree. */
void ic_jet_chain_init(ic_jet_chain *ch, const ic_jet_space *sp_p, const double *const *P,
                       int np, const double *const *delta, const ic_jet_space *sp, double *work);

/* The same for polynomials known to have no terms above degree `bound`
 * (their degree is then found below it, not over the whole space). */
void ic_jet_chain_init_upto(ic_jet_chain *ch, const ic_jet_space *sp_p, const double *const *P,
                            int np, int bound, const double *const *delta,
                            const ic_jet_space *sp, double *work);

/* Declares that the deltas have no terms above degree `deg` (a linear
 * substitution: 1), so a power product of degree d has none above d deg and
 * its steps beyond are skipped. Call after ic_jet_chain_init. */
void ic_jet_chain_set_delta_degree(ic_jet_chain *ch, int deg);

/* The degree-k parts of the power products (k >= 1, after steps 1..k-1). */
void ic_jet_chain_extend(ic_jet_chain *ch, int k);

/* out's degree-k part = [P(delta)]_k, P one of the chain's polynomials
 * (its constant term left out, its linear terms with the deltas' current
 * degree-k parts); the rest of out is untouched. */
void ic_jet_chain_part(const ic_jet_chain *ch, double *out, const double *P, int k);

#endif

/* The peer benchmark (docs/peers.md): the types every engine fills and the
 * runner reads. An engine turns one case's two surfaces into curves and
 * isolated points; what it found is reduced to samples (a point with the
 * curvature and torsion the engine gives there), which metrics.c scores
 * against the closed forms, all inside the child process that ran it. */
#ifndef IC_PEERS_H
#define IC_PEERS_H

#include "cases.h"

#ifdef __cplusplus
extern "C" {
#endif

/* isolated points kept per run: more than any case has */
#define PEER_MAX_POINTS 16

typedef struct {
    double xyz[3];
    double kappa, tau;
    int has_kappa, has_tau; /* 0 where the engine gives no value (or no frame) */
} peer_sample;

/* What one run of an engine found. */
typedef struct {
    int ncurves;
    int npoints;                       /* isolated points reported */
    double points[PEER_MAX_POINTS][3]; /* the first PEER_MAX_POINTS of them */
    double length;                     /* total length of the curves */
    peer_sample *samples;              /* along every curve, owned */
    int nsamples, cap;
    int stationary; /* samples where the curve's parametrisation stands still */
    int failed;     /* 1: the engine reported an error (note says which) */
    char note[200]; /* what the engine said beyond the counts */
} peer_output;

void peer_output_clear(peer_output *out);
void peer_output_free(peer_output *out);
/* Appends a sample; returns 0, or -1 when out of memory. */
int peer_output_add(peer_output *out, const double xyz[3], double kappa, double tau,
                    int has_kappa, int has_tau);
/* A fraction of the mean speed of the parametrisation below which a curve
 * counts as standing still: no curvature or torsion there. */
#define PEER_STATIONARY_SPEED 1e-6

/* Appends a sample of a parametrised curve from its first three derivatives
 * d[0..2]: curvature and torsion by frenet_from_derivs, none where the speed
 * is at most PEER_STATIONARY_SPEED * mean_speed (counted in out->stationary). */
int peer_output_add_derivs(peer_output *out, const double xyz[3], const double d[3][3],
                           double mean_speed);
void peer_output_note(peer_output *out, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* An engine: runs the case once, timing only the intersection itself
 * (*seconds), and fills out. Returns 0, or -1 when it could not run at all. */
typedef int (*peer_engine_fn)(const bench_case *c, peer_output *out, double *seconds);

typedef struct {
    const char *name;
    peer_engine_fn run;
} peer_engine;

int peer_intercurve(const bench_case *c, peer_output *out, double *seconds);
/* the same, scored on its fitted B-splines (docs/bspline.md) */
int peer_intercurve_bspline(const bench_case *c, peer_output *out, double *seconds);
/* the exact surfaces as intercurve's implicit primitives, in a box around the
 * nets (what OpenCASCADE's analytic engine is given) */
int peer_intercurve_primitives(const bench_case *c, peer_output *out, double *seconds);
int peer_sisl(const bench_case *c, peer_output *out, double *seconds);
int peer_occt_nurbs(const bench_case *c, peer_output *out, double *seconds);
int peer_occt_analytic(const bench_case *c, peer_output *out, double *seconds);

#ifdef __cplusplus
}
#endif

#endif

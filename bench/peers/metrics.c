/* Scores an engine's output against the closed forms: distance of every
 * sample (and isolated point) from both exact surfaces, distance from the
 * exact curves, and the curvature and torsion errors at the nearest point of
 * the exact curve. */
#include <math.h>
#include <string.h>

#include "metrics.h"

static double surface_dist(const bench_case *c, const double p[3])
{
    return fmax(exact_distance(&c->A, p), exact_distance(&c->B, p));
}

static void score_samples(const bench_case *c, const peer_output *out, peer_summary *sum)
{
    for (int i = 0; i < out->nsamples; i++) {
        const peer_sample *s = out->samples + i;
        sum->max_surface_dist = fmax(sum->max_surface_dist, surface_dist(c, s->xyz));
        double dist, kappa[TRUTH_MAX_TIES], tau[TRUTH_MAX_TIES];
        const int ties = truth_nearest(c, s->xyz, &dist, kappa, tau);
        if (ties == 0)
            continue; /* curves where there are none: seen in the counts and distances */
        sum->max_curve_dist = fmax(sum->max_curve_dist, dist);
        /* at a crossing, the branch that fits best */
        double kappa_err = INFINITY, tau_err = INFINITY;
        for (int t = 0; t < ties; t++) {
            kappa_err = fmin(kappa_err, fabs(s->kappa - kappa[t]));
            tau_err = fmin(tau_err, fabs(s->tau - tau[t]));
        }
        if (s->has_kappa) {
            sum->max_kappa_err = fmax(sum->max_kappa_err, kappa_err);
            sum->kappa_count++;
        }
        if (s->has_tau) {
            sum->max_tau_err = fmax(sum->max_tau_err, tau_err);
            sum->tau_count++;
        }
    }
}

static void score_points(const bench_case *c, const peer_output *out, peer_summary *sum)
{
    sum->point_err = NAN;
    const int kept = out->npoints < PEER_MAX_POINTS ? out->npoints : PEER_MAX_POINTS;
    for (int i = 0; i < kept; i++) {
        const double *p = out->points[i];
        sum->max_surface_dist = fmax(sum->max_surface_dist, surface_dist(c, p));
        if (c->expect_points == 0)
            continue;
        const double d = sqrt(pow(p[0] - c->expect_point[0], 2) +
                              pow(p[1] - c->expect_point[1], 2) +
                              pow(p[2] - c->expect_point[2], 2));
        if (!(d >= sum->point_err))
            sum->point_err = d;
    }
}

void peer_summarize(const bench_case *c, const peer_output *out, peer_summary *sum)
{
    sum->status = out->failed ? RUN_ERROR : RUN_OK;
    sum->ncurves = out->ncurves, sum->npoints = out->npoints, sum->nsamples = out->nsamples;
    sum->length = out->length;
    sum->max_surface_dist = sum->max_curve_dist = 0.0;
    sum->max_kappa_err = sum->max_tau_err = 0.0;
    sum->kappa_count = sum->tau_count = 0;
    score_samples(c, out, sum);
    score_points(c, out, sum);
    sum->stationary = out->stationary;
    memcpy(sum->note, out->note, sizeof sum->note);
}

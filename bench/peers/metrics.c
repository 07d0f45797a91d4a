/* Scores an engine's output against the closed forms: distance of every
 * sample (and isolated point) from both exact surfaces, distance from the
 * exact curves, and the curvature and torsion errors at the nearest point of
 * the exact curve. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "metrics.h"

static double surface_dist(const bench_case *c, const double p[3])
{
    return fmax(exact_distance(&c->A, p), exact_distance(&c->B, p));
}

static int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the median of v[0..n-1] (sorted in place); NaN for none */
static double median(double *v, int n)
{
    if (n == 0)
        return NAN;
    qsort(v, n, sizeof v[0], compare_doubles);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Returns -1 when out of memory. */
static int score_samples(const bench_case *c, const peer_output *out, peer_summary *sum)
{
    double *kappa_errs = malloc(sizeof(double) * (out->nsamples + 1));
    double *tau_errs = malloc(sizeof(double) * (out->nsamples + 1));
    if (!kappa_errs || !tau_errs) {
        free(kappa_errs);
        free(tau_errs);
        return -1;
    }
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
            kappa_errs[sum->kappa_count++] = kappa_err;
        }
        if (s->has_tau) {
            sum->max_tau_err = fmax(sum->max_tau_err, tau_err);
            tau_errs[sum->tau_count++] = tau_err;
        }
    }
    sum->median_kappa_err = median(kappa_errs, sum->kappa_count);
    sum->median_tau_err = median(tau_errs, sum->tau_count);
    free(kappa_errs);
    free(tau_errs);
    return 0;
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
    sum->note[0] = 0;
    if (score_samples(c, out, sum) != 0)
        snprintf(sum->note, sizeof sum->note, "out of memory scoring the samples; ");
    score_points(c, out, sum);
    sum->stationary = out->stationary;
    const size_t used = strlen(sum->note);
    snprintf(sum->note + used, sizeof sum->note - used, "%s", out->note);
}

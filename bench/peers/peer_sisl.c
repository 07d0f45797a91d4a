/* SISL on a case: the two nets as rational B-spline surfaces (newSurf),
 * s1859 for the intersection points and the guide points of every curve,
 * s1310 to march each curve into a B-spline curve, s1221 for its
 * derivatives (curvature and torsion), s1240 for its length. */
#include <math.h>
#include <stdlib.h>
#include <time.h>

#include <sisl.h>

#include "peers.h"

/* geometric tolerance given to s1859 and s1310 (length units) */
#define SISL_GEOMETRY_TOL 1e-7
/* computational resolution (unused by SISL, passed as documented) */
#define SISL_RESOLUTION 1e-15
/* parameter samples along each marched curve */
#define SISL_SAMPLES_PER_CURVE 1000
/* a SISL surface that differs from our own evaluation of the net by more
 * than this (length units) means the conversion is wrong */
#define SISL_CONVERSION_TOL 1e-12

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* SISL wants the first parameter running fastest and, for a rational surface,
 * homogeneous vertices (w x, w y, w z, w). */
static SISLSurf *make_surface(const case_net *net)
{
    const int n1 = net->count[0], n2 = net->count[1];
    double *coef = malloc(sizeof(double) * 4 * n1 * n2);
    if (!coef)
        return NULL;
    for (int i = 0; i < n1; i++)
        for (int j = 0; j < n2; j++) {
            const int ours = i * n2 + j, theirs = j * n1 + i;
            const double w = net->weights[ours];
            for (int k = 0; k < 3; k++)
                coef[4 * theirs + k] = w * net->points[3 * ours + k];
            coef[4 * theirs + 3] = w;
        }
    SISLSurf *s = newSurf(n1, n2, net->degree[0] + 1, net->degree[1] + 1,
                          (double *)net->knots[0], (double *)net->knots[1], coef, 2, 3, 1);
    free(coef);
    return s;
}

/* Largest difference between SISL's surface and our evaluation of the net. */
static double conversion_error(SISLSurf *s, const case_net *net)
{
    double worst = 0.0;
    int left1 = 0, left2 = 0, stat = 0;
    for (int a = 0; a <= 4; a++)
        for (int b = 0; b <= 4; b++) {
            double par[2], theirs[3], ours[3];
            for (int d = 0; d < 2; d++) {
                const double lo = net->knots[d][net->degree[d]], hi = net->knots[d][net->count[d]];
                par[d] = lo + (hi - lo) * (0.1 + 0.2 * (d ? b : a));
            }
            s1424(s, 0, 0, par, &left1, &left2, theirs, &stat);
            net_eval(net, par[0], par[1], ours);
            for (int k = 0; k < 3; k++)
                worst = fmax(worst, fabs(theirs[k] - ours[k]));
        }
    return worst;
}

static int sample_curve(SISLCurve *cv, peer_output *out)
{
    const double t0 = cv->et[cv->ik - 1], t1 = cv->et[cv->in];
    int left = 0, stat = 0;
    double len = 0.0;
    s1240(cv, SISL_GEOMETRY_TOL, &len, &stat);
    out->length += len;
    for (int i = 0; i <= SISL_SAMPLES_PER_CURVE; i++) {
        double der[12];
        s1221(cv, 3, t0 + (t1 - t0) * i / SISL_SAMPLES_PER_CURVE, &left, der, &stat);
        if (stat < 0)
            return -1;
        const double d[3][3] = {{der[3], der[4], der[5]}, {der[6], der[7], der[8]},
                                {der[9], der[10], der[11]}};
        if (peer_output_add_derivs(out, der, d, len / (t1 - t0)) != 0)
            return -1;
    }
    return 0;
}

static void collect_points(SISLSurf *a, int npt, const double *par, peer_output *out)
{
    out->npoints = npt;
    for (int i = 0; i < npt && i < PEER_MAX_POINTS; i++) {
        int left1 = 0, left2 = 0, stat = 0;
        double p[3];
        s1424(a, 0, 0, (double *)par + 2 * i, &left1, &left2, p, &stat);
        for (int k = 0; k < 3; k++)
            out->points[i][k] = p[k];
    }
}

/* s1859, then s1310 on each curve; the time covers both. */
static int intersect(SISLSurf *a, SISLSurf *b, peer_output *out, double *seconds)
{
    int npt = 0, ncrv = 0, stat = 0;
    double *par1 = NULL, *par2 = NULL;
    SISLIntcurve **curves = NULL;
    const double t0 = now_seconds();
    s1859(a, b, SISL_RESOLUTION, SISL_GEOMETRY_TOL, &npt, &par1, &par2, &ncrv, &curves, &stat);
    if (stat < 0) {
        *seconds = now_seconds() - t0;
        out->failed = 1;
        peer_output_note(out, "s1859 status %d", stat);
        return 0;
    }
    int marched = 0;
    for (int i = 0; i < ncrv; i++) {
        int mstat = 0;
        s1310(a, b, curves[i], SISL_GEOMETRY_TOL, 0.0, 1, 0, &mstat);
        if (mstat < 0 || !curves[i]->pgeom)
            peer_output_note(out, "s1310 on curve %d: status %d; ", i, mstat);
        else
            marched++;
    }
    *seconds = now_seconds() - t0;
    out->ncurves = marched;
    if (marched < ncrv)
        peer_output_note(out, "%d of %d curves marched; ", marched, ncrv);
    collect_points(a, npt, par1, out);
    int rc = 0;
    for (int i = 0; i < ncrv && rc == 0; i++)
        if (curves[i]->pgeom)
            rc = sample_curve(curves[i]->pgeom, out);
    free(par1);
    free(par2);
    if (curves)
        freeIntcrvlist(curves, ncrv);
    return rc;
}

int peer_sisl(const bench_case *c, peer_output *out, double *seconds)
{
    SISLSurf *a = make_surface(&c->netA), *b = make_surface(&c->netB);
    int rc = -1;
    if (!a || !b) {
        peer_output_note(out, "newSurf failed");
        goto done;
    }
    const double conv = fmax(conversion_error(a, &c->netA), conversion_error(b, &c->netB));
    if (!(conv <= SISL_CONVERSION_TOL)) {
        peer_output_note(out, "the SISL surfaces are not the nets (off by %.1e)", conv);
        goto done;
    }
    rc = intersect(a, b, out, seconds);
done:
    if (a)
        freeSurf(a);
    if (b)
        freeSurf(b);
    return rc;
}

/* peer_output: the samples an engine found, grown as it adds them. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peers.h"

void peer_output_clear(peer_output *out)
{
    memset(out, 0, sizeof *out);
}

void peer_output_free(peer_output *out)
{
    free(out->samples);
    peer_output_clear(out);
}

int peer_output_add(peer_output *out, const double xyz[3], double kappa, double tau,
                    int has_kappa, int has_tau)
{
    if (out->nsamples == out->cap) {
        const int cap = out->cap ? 2 * out->cap : 1024;
        peer_sample *grown = realloc(out->samples, sizeof *grown * cap);
        if (!grown)
            return -1;
        out->samples = grown, out->cap = cap;
    }
    peer_sample *s = out->samples + out->nsamples++;
    memcpy(s->xyz, xyz, sizeof s->xyz);
    s->kappa = kappa, s->tau = tau, s->has_kappa = has_kappa, s->has_tau = has_tau;
    return 0;
}

int peer_output_add_derivs(peer_output *out, const double xyz[3], const double d[3][3],
                           double mean_speed)
{
    const double speed = sqrt(d[0][0] * d[0][0] + d[0][1] * d[0][1] + d[0][2] * d[0][2]);
    if (!(speed > PEER_STATIONARY_SPEED * mean_speed)) {
        out->stationary++;
        return peer_output_add(out, xyz, 0.0, 0.0, 0, 0);
    }
    double kappa, tau;
    int has_tau;
    frenet_from_derivs(d[0], d[1], d[2], &kappa, &tau, &has_tau);
    return peer_output_add(out, xyz, kappa, tau, 1, has_tau);
}

void peer_output_note(peer_output *out, const char *fmt, ...)
{
    const size_t used = strlen(out->note);
    if (used + 1 >= sizeof out->note)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(out->note + used, sizeof out->note - used, fmt, ap);
    va_end(ap);
}

/* Where two meridian profiles meet (exact_profile.h): lines and circles
 * intersected in closed form, each meeting with the angle between the
 * pieces there; a tangency within IC_EXACT_TANGENT of the problem's size is
 * exact, one within IC_EXACT_NEAR is left to the general path. */
#include "exact_profile.h"

#include <math.h>

static double dot2(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1]; }
static double cross2(const double *a, const double *b) { return a[0] * b[1] - a[1] * b[0]; }

/* The angle between two directions, either way round: in [0, pi/2]. */
static double line_angle(const double *a, const double *b)
{
    return atan2(fabs(cross2(a, b)), fabs(dot2(a, b)));
}

/* The direction of a piece at its point (rho, z): a circle's is normal to
 * the radius there. */
static void piece_direction(const ic_profile_piece *p, double rho, double z, double dir[2])
{
    if (!p->circle) {
        dir[0] = p->d[0], dir[1] = p->d[1];
        return;
    }
    dir[0] = -(z - p->c[1]), dir[1] = rho - p->c[0];
}

static void add(ic_profile_meeting *out, int *n, const ic_profile_piece *a,
                const ic_profile_piece *b, double rho, double z, int tangent)
{
    ic_profile_meeting *m = &out[(*n)++];
    m->rho = rho, m->z = z, m->tangent = tangent;
    double da[2], db[2];
    piece_direction(a, rho, z, da);
    piece_direction(b, rho, z, db);
    m->angle = tangent ? 0.0 : line_angle(da, db);
}

static int line_line(const ic_profile_piece *a, const ic_profile_piece *b, double L,
                     ic_profile_meeting *out, int *n)
{
    const double w[2] = {b->c[0] - a->c[0], b->c[1] - a->c[1]};
    const double cr = cross2(a->d, b->d);
    if (fabs(cr) <= IC_EXACT_COAXIAL) /* parallel: apart, or (nearly) one line */
        return fabs(cross2(w, a->d)) <= IC_EXACT_NEAR * L ? -1 : 0;
    const double t = cross2(w, b->d) / cr;
    add(out, n, a, b, a->c[0] + t * a->d[0], a->c[1] + t * a->d[1], 0);
    return 0;
}

static int line_circle(const ic_profile_piece *line, const ic_profile_piece *circ, double L,
                       ic_profile_meeting *out, int *n)
{
    const double w[2] = {circ->c[0] - line->c[0], circ->c[1] - line->c[1]};
    const double along = dot2(w, line->d);
    const double foot[2] = {line->c[0] + along * line->d[0], line->c[1] + along * line->d[1]};
    const double dist = fabs(cross2(w, line->d)), gap = circ->r - dist;
    if (fabs(gap) <= IC_EXACT_TANGENT * L) {
        add(out, n, line, circ, foot[0], foot[1], 1);
        return 0;
    }
    if (fabs(gap) <= IC_EXACT_NEAR * L)
        return -1;
    if (gap < 0)
        return 0;
    const double half = sqrt((circ->r - dist) * (circ->r + dist));
    for (int sg = -1; sg <= 1; sg += 2)
        add(out, n, line, circ, foot[0] + sg * half * line->d[0], foot[1] + sg * half * line->d[1],
            0);
    return 0;
}

static int circle_circle(const ic_profile_piece *a, const ic_profile_piece *b, double L,
                         ic_profile_meeting *out, int *n)
{
    const double w[2] = {b->c[0] - a->c[0], b->c[1] - a->c[1]};
    const double dist = hypot(w[0], w[1]);
    if (dist <= IC_EXACT_TANGENT * L) /* concentric: apart, or (nearly) one circle */
        return fabs(a->r - b->r) <= IC_EXACT_NEAR * L ? -1 : 0;
    const double u[2] = {w[0] / dist, w[1] / dist};
    const double outer = dist - (a->r + b->r), inner = fabs(a->r - b->r) - dist;
    if (fabs(outer) <= IC_EXACT_TANGENT * L || fabs(inner) <= IC_EXACT_TANGENT * L) {
        /* touching outside, or inside: on a's side towards b, or away */
        const double s = fabs(outer) <= IC_EXACT_TANGENT * L || a->r >= b->r ? a->r : -a->r;
        add(out, n, a, b, a->c[0] + s * u[0], a->c[1] + s * u[1], 1);
        return 0;
    }
    if (fabs(outer) <= IC_EXACT_NEAR * L || fabs(inner) <= IC_EXACT_NEAR * L)
        return -1;
    if (outer > 0 || inner > 0)
        return 0;
    const double along = (dist * dist + a->r * a->r - b->r * b->r) / (2 * dist);
    const double half = sqrt(fmax(0.0, (a->r - along) * (a->r + along)));
    for (int sg = -1; sg <= 1; sg += 2)
        add(out, n, a, b, a->c[0] + along * u[0] - sg * half * u[1],
            a->c[1] + along * u[1] + sg * half * u[0], 0);
    return 0;
}

static int pieces_meet(const ic_profile_piece *a, const ic_profile_piece *b, double L,
                       ic_profile_meeting *out, int *n)
{
    if (!a->circle && !b->circle)
        return line_line(a, b, L, out, n);
    if (a->circle && b->circle)
        return circle_circle(a, b, L, out, n);
    return a->circle ? line_circle(b, a, L, out, n) : line_circle(a, b, L, out, n);
}

int ic_profile_meet(const ic_profile *a, const ic_profile *b, double L,
                    ic_profile_meeting out[IC_PROFILE_MAX_MEETINGS], int *n)
{
    *n = 0;
    for (int i = 0; i < a->n; i++)
        for (int j = 0; j < b->n; j++)
            if (pieces_meet(&a->piece[i], &b->piece[j], L, out, n) != 0)
                return -1;
    return 0;
}

/* The exact rational NURBS nets of the surfaces: the full circle as the
 * 9-point rational quadratic (knots 0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1,
 * weights 1 and sqrt(2)/2 alternating) revolved about the axis as a tensor
 * product with a profile (a half circle for the sphere, a segment for the
 * cylinder, a circle for the torus); the plane as a bilinear patch. */
#include <math.h>
#include <string.h>

#include "cases.h"

#define CIRCLE_COUNT 9

static const double circle_x[CIRCLE_COUNT] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
static const double circle_y[CIRCLE_COUNT] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
static const double circle_knots[CIRCLE_COUNT + 3] = {0,    0,   0,   0.25, 0.25, 0.5,
                                                      0.5,  0.75, 0.75, 1,    1,    1};

static double circle_weight(int i)
{
    return i % 2 ? sqrt(0.5) : 1.0;
}

/* A profile in the (rho, z) half plane: distance from the axis, height. */
typedef struct {
    int degree, count;
    double knots[NET_MAX_KNOTS];
    double rho[NET_MAX_COUNT], z[NET_MAX_COUNT], w[NET_MAX_COUNT];
    int periodic;
} profile;

static void to_space(const exact_surface *s, double x, double y, double z, double out[3])
{
    const double *a = s->axis, *e1 = s->ref;
    const double e2[3] = {a[1] * e1[2] - a[2] * e1[1], a[2] * e1[0] - a[0] * e1[2],
                          a[0] * e1[1] - a[1] * e1[0]};
    for (int k = 0; k < 3; k++)
        out[k] = s->center[k] + x * e1[k] + y * e2[k] + z * a[k];
}

static void revolve(case_net *net, const exact_surface *s, const profile *pr)
{
    net->degree[0] = 2, net->count[0] = CIRCLE_COUNT, net->periodic[0] = 1;
    memcpy(net->knots[0], circle_knots, sizeof circle_knots);
    net->degree[1] = pr->degree, net->count[1] = pr->count, net->periodic[1] = pr->periodic;
    memcpy(net->knots[1], pr->knots, sizeof(double) * (pr->count + pr->degree + 1));
    for (int i = 0; i < CIRCLE_COUNT; i++)
        for (int j = 0; j < pr->count; j++) {
            const int at = i * pr->count + j;
            to_space(s, pr->rho[j] * circle_x[i], pr->rho[j] * circle_y[i], pr->z[j],
                     net->points + 3 * at);
            net->weights[at] = circle_weight(i) * pr->w[j];
        }
}

static void sphere_profile(profile *pr, double r)
{
    static const double knots[] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    const double rho[] = {0, r, r, r, 0}, z[] = {-r, -r, 0, r, r};
    pr->degree = 2, pr->count = 5, pr->periodic = 0;
    memcpy(pr->knots, knots, sizeof knots);
    for (int j = 0; j < 5; j++)
        pr->rho[j] = rho[j], pr->z[j] = z[j], pr->w[j] = circle_weight(j);
}

static void cylinder_profile(profile *pr, double r, double half_length)
{
    static const double knots[] = {0, 0, 1, 1};
    pr->degree = 1, pr->count = 2, pr->periodic = 0;
    memcpy(pr->knots, knots, sizeof knots);
    for (int j = 0; j < 2; j++)
        pr->rho[j] = r, pr->z[j] = j ? half_length : -half_length, pr->w[j] = 1;
}

static void torus_profile(profile *pr, double major, double r)
{
    pr->degree = 2, pr->count = CIRCLE_COUNT, pr->periodic = 1;
    memcpy(pr->knots, circle_knots, sizeof circle_knots);
    for (int j = 0; j < CIRCLE_COUNT; j++) {
        pr->rho[j] = major + r * circle_x[j];
        pr->z[j] = r * circle_y[j];
        pr->w[j] = circle_weight(j);
    }
}

static void plane_net(case_net *net, const exact_surface *s)
{
    static const double knots[] = {0, 0, 1, 1};
    const double h = s->half_length;
    for (int d = 0; d < 2; d++) {
        net->degree[d] = 1, net->count[d] = 2, net->periodic[d] = 0;
        memcpy(net->knots[d], knots, sizeof knots);
    }
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            to_space(s, i ? h : -h, j ? h : -h, 0, net->points + 3 * (2 * i + j));
            net->weights[2 * i + j] = 1;
        }
}

void net_from_exact(case_net *net, const exact_surface *s)
{
    memset(net, 0, sizeof *net);
    profile pr;
    memset(&pr, 0, sizeof pr);
    switch (s->kind) {
    case EXACT_PLANE:
        plane_net(net, s);
        return;
    case EXACT_SPHERE:
        sphere_profile(&pr, s->radius);
        break;
    case EXACT_CYLINDER:
        cylinder_profile(&pr, s->radius, s->half_length);
        break;
    case EXACT_TORUS:
        torus_profile(&pr, s->major, s->radius);
        break;
    }
    revolve(net, s, &pr);
}

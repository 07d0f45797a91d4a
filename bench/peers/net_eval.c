/* Our own evaluation of a rational net, independent of every engine: the
 * Cox-de Boor recursion for the basis, then the weighted sum and the
 * division. Used only to check that the nets are the exact surfaces. */
#include <math.h>

#include "cases.h"

/* The span s with knots[s] <= t < knots[s + 1] (the last nonempty span at
 * the domain's right end). */
static int find_span(const double *knots, int degree, int count, double t)
{
    int s = degree;
    while (s < count - 1 && t >= knots[s + 1])
        s++;
    return s;
}

/* basis[r] = N_{span - degree + r, degree}(t), r = 0..degree, built up
 * degree by degree from the piecewise constant N_{span, 0} = 1. */
static void basis_at(const double *knots, int degree, int span, double t, double *basis)
{
    basis[0] = 1.0;
    for (int d = 1; d <= degree; d++) {
        double carry = 0.0;
        for (int r = 0; r < d; r++) {
            const double hi = knots[span + r + 1], lo = knots[span + r + 1 - d];
            const double share = basis[r] / (hi - lo);
            basis[r] = carry + (hi - t) * share;
            carry = (t - lo) * share;
        }
        basis[d] = carry;
    }
}

void net_eval(const case_net *net, double u, double v, double out[3])
{
    const double at[2] = {u, v};
    int span[2];
    double basis[2][NET_MAX_COUNT];
    for (int d = 0; d < 2; d++) {
        span[d] = find_span(net->knots[d], net->degree[d], net->count[d], at[d]);
        basis_at(net->knots[d], net->degree[d], span[d], at[d], basis[d]);
    }
    double sum[4] = {0, 0, 0, 0}; /* homogeneous: w x, w y, w z, w */
    for (int a = 0; a <= net->degree[0]; a++)
        for (int b = 0; b <= net->degree[1]; b++) {
            const int i = span[0] - net->degree[0] + a, j = span[1] - net->degree[1] + b;
            const int at_ij = i * net->count[1] + j;
            const double f = basis[0][a] * basis[1][b] * net->weights[at_ij];
            for (int k = 0; k < 3; k++)
                sum[k] += f * net->points[3 * at_ij + k];
            sum[3] += f;
        }
    for (int k = 0; k < 3; k++)
        out[k] = sum[k] / sum[3];
}

double net_check(const case_net *net, const exact_surface *s, int n)
{
    double worst = 0.0;
    for (int a = 0; a <= n; a++)
        for (int b = 0; b <= n; b++) {
            double t[2], p[3];
            for (int d = 0; d < 2; d++) {
                const double lo = net->knots[d][net->degree[d]];
                const double hi = net->knots[d][net->count[d]];
                t[d] = lo + (hi - lo) * (d ? b : a) / n;
            }
            net_eval(net, t[0], t[1], p);
            const double dist = exact_distance(s, p);
            if (isnan(dist))
                return dist;
            if (dist > worst)
                worst = dist;
        }
    return worst;
}

/* The apparatus of the curve points next to a located singular point taken
 * from the branch's Taylor series there, where the jet method loses digits
 * (docs/tracing.md). */
#include "common/vec3.h"
#include "trace_internal.h"

#include <math.h>

/* Near a tangential point the jet method's frame matrix [t; N_A; N_B] is
 * nearly singular, and each order of c^(k) loses more digits: torsion is
 * off by about eps / angle^4 (Viviani: 1e-5 at an angle of 1e-3, 1000 times
 * the true value at 1e-5). Points within ANGLE of parallel take their
 * apparatus from the branch's series at the singular point instead, while
 * its truncation (the last term kept) stays below 1e-12 of c'''. */
void ic_trace_refit_near_special(ic_trace_point *pts, int n, const ic_branch *br, double sg)
{
    const double ANGLE = 0.1;
    const int K = br->order;
    if (K < 4 || !br->regular)
        return;
    for (int k = n - 1; k >= 0 && pts[k].angle < ANGLE; k--) {
        const double sb = sg * (pts[k].s - pts[n].s); /* arc length along the branch */
        double D[3][3] = {{0}}, last = 0;
        for (int j = 1; j <= 3; j++) {
            double f = 1.0; /* sb^i / i! */
            for (int i = 0; j + i <= K; i++) {
                for (int c = 0; c < 3; c++)
                    D[j - 1][c] += f * br->derivs[j + i - 1][c];
                if (j == 3 && j + i == K)
                    last = fabs(f) * ic_norm3(br->derivs[K - 1]);
                f *= sb / (i + 1);
            }
            if (j % 2 == 1 && sg < 0) /* c^(j) of the curve = sg^j c^(j) of the branch */
                ic_scale3(D[j - 1], D[j - 1], -1.0);
        }
        if (!(last <= 1e-12 * (1 + ic_norm3(D[2]))))
            break;
        double cr[3];
        ic_cross3(cr, D[0], D[1]);
        const double v = ic_norm3(D[0]), w = ic_norm3(cr);
        ic_trace_point *p = &pts[k];
        ic_scale3(p->t, D[0], 1.0 / v);
        p->kappa = w / (v * v * v);
        p->frame_defined = w > 0;
        if (p->frame_defined) {
            ic_scale3(p->b, cr, 1.0 / w);
            ic_cross3(p->n, p->b, p->t);
            p->tau = ic_dot3(cr, D[2]) / (w * w);
        }
    }
}

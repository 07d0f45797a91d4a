/* The traced curves of the pictures as smooth paths (docs/plots.md): each
 * stretch between two traced points is drawn as cubic Bezier pieces that
 * match the curve's point and tangent at their ends, so an SVG or PDF stays
 * smooth at any zoom. Where the curve has its B-spline (docs/bspline.md),
 * the pieces' inner ends come from it; without one, the stretch is one
 * cubic through the traced points and their exact tangents. */
#include "plot_internal.h"

#include <math.h>
#include <string.h>

#include "common/vec3.h"
#include "intercurve/bspline.h"

/* radians: the most one cubic piece turns (up to PLOT_MAX_PIECES per
 * stretch; the tracer bounds its steps' turning well below that). With
 * handles of (4/3) tan(a/4) of the radius, a cubic through the ends of a
 * circular arc of angle a with its tangents there is off the arc by 1.8e-5
 * a^6 of the radius (measured); where the curvature varies (an ellipse of
 * axes 2 and 1) about 0.06 a^4 of the size: 1e-8 at this angle, well
 * below cairo's own rounding (1/256 of a unit, 3e-6 of a picture 1400
 * wide). */
#define PLOT_PIECE_TURN 0.02
/* cosine: a traced tangent further than 60 degrees from the chord is not
 * this stretch's (a branch point's other branch): the chord is used */
#define PLOT_TANGENT_COS 0.5

/* The unit tangent at a stretch end: the point's own, unless it is
 * undefined or leaves the chord (unit) too far. */
static void end_tangent(double d[3], const ic_trace_point *p, const double chord[3])
{
    const int usable = isfinite(p->t[0]) && isfinite(p->t[1]) && isfinite(p->t[2]) &&
                       ic_dot3(p->t, chord) > PLOT_TANGENT_COS;
    for (int j = 0; j < 3; j++)
        d[j] = usable ? p->t[j] : chord[j];
}

/* One cubic from (x0, d0) to (x1, d1) (unit tangents) over an arc of
 * length h, its control points projected into b (x0, y0, ..., x3, y3; the
 * camera is affine: the projection of the cubic). The handles are those of
 * the circular arc turning by the angle between the tangents: (4/3)
 * tan(phi/4) r with r = h / phi, h / 3 when the piece is straight. */
static void cubic(double b[8], const plot_camera *cam, const double x0[3], const double d0[3],
                  const double x1[3], const double d1[3], double h)
{
    double cr3[3], c[4][3];
    ic_cross3(cr3, d0, d1);
    const double phi = atan2(ic_norm3(cr3), ic_dot3(d0, d1));
    const double handle = phi > 1e-6 ? h * (4.0 / 3.0) * tan(phi / 4) / phi : h / 3;
    memcpy(c[0], x0, sizeof c[0]);
    ic_axpy3(c[1], x0, handle, d0);
    ic_axpy3(c[2], x1, -handle, d1);
    memcpy(c[3], x1, sizeof c[3]);
    for (int k = 0; k < 4; k++)
        ic_plot_camera_project(cam, c[k], &b[2 * k], &b[2 * k + 1], NULL);
}

int ic_plot_curve_pieces(const plot_camera *cam, const ic_trace_result *tr, int curve, int k,
                         double (*b)[8])
{
    const ic_trace_curve *cv = ic_trace_result_curve(tr, curve);
    const ic_trace_point *p = &cv->points[k], *q = &cv->points[k + 1];
    const ic_curve_fit *fit = ic_trace_result_fit(tr, curve);
    double chord[3];
    ic_axpy3(chord, q->xyz, -1.0, p->xyz);
    const double h = q->s - p->s, len = ic_norm3(chord);
    if (!(h > 0) || !(len > 0) || !isfinite(h)) { /* a straight cubic */
        const double none[3] = {0, 0, 0};
        cubic(b[0], cam, p->xyz, none, q->xyz, none, 0);
        return 1;
    }
    ic_scale3(chord, chord, 1 / len);
    const double turn = fmax(fabs(p->kappa), fabs(q->kappa)) * h;
    const int pieces = fit && isfinite(turn)
                           ? (int)fmin(PLOT_MAX_PIECES, fmax(1, ceil(turn / PLOT_PIECE_TURN)))
                           : 1;
    double x0[3], d0[3], s0 = p->s;
    memcpy(x0, p->xyz, sizeof x0);
    end_tangent(d0, p, chord);
    int n = 0;
    for (int i = 1; i <= pieces; i++) {
        const double s1 = i < pieces ? p->s + h * i / pieces : q->s;
        double at[6];
        if (i == pieces) {
            memcpy(at, q->xyz, sizeof q->xyz);
            end_tangent(at + 3, q, chord);
        } else if (ic_bspline_eval(&fit->curve, s1, 1, at, NULL) != IC_OK ||
                   !(ic_norm3(at + 3) > 0)) {
            continue; /* not evaluated: the next piece is longer */
        } else {
            ic_scale3(at + 3, at + 3, 1 / ic_norm3(at + 3));
        }
        cubic(b[n++], cam, x0, d0, at, at + 3, s1 - s0);
        memcpy(x0, at, sizeof x0);
        memcpy(d0, at + 3, sizeof d0);
        s0 = s1;
    }
    return n;
}

void ic_plot_curve_path(cairo_t *cr, const plot_camera *cam, const ic_trace_result *tr, int curve,
                        int k)
{
    double b[PLOT_MAX_PIECES][8];
    const int n = ic_plot_curve_pieces(cam, tr, curve, k, b);
    cairo_move_to(cr, b[0][0], b[0][1]);
    for (int i = 0; i < n; i++)
        cairo_curve_to(cr, b[i][2], b[i][3], b[i][4], b[i][5], b[i][6], b[i][7]);
}

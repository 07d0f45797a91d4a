/* The five cases of the peer benchmark (docs/peers.md): each a pair of exact
 * surfaces (closed-form distance functions), the same pair as exact rational
 * NURBS nets (fed to every engine), and the closed form of what the
 * intersection is (curves, points, length, curvature and torsion). */
#ifndef IC_PEERS_CASES_H
#define IC_PEERS_CASES_H

#ifdef __cplusplus
extern "C" {
#endif

/* C11 <math.h> has no M_PI without extensions */
#define PEERS_PI 3.14159265358979323846264338327950288

typedef enum { EXACT_PLANE, EXACT_SPHERE, EXACT_CYLINDER, EXACT_TORUS } exact_kind;

/* A placed quadric or torus. The frame (ref, axis x ref, axis) is the one the
 * NURBS net is built in: u = 0 on the ref side. */
typedef struct {
    exact_kind kind;
    double center[3]; /* sphere, torus: centre; cylinder: on the axis; plane: a point */
    double axis[3];   /* unit: cylinder and torus axis, sphere pole axis, plane normal */
    double ref[3];    /* unit, normal to axis */
    double radius;    /* sphere, cylinder; torus: tube radius */
    double major;     /* torus: distance of the tube's centre line from the axis */
    double half_length; /* cylinder along its axis, plane in both directions: the patch's extent */
} exact_surface;

/* distance of p from the whole (unbounded) exact surface */
double exact_distance(const exact_surface *s, const double p[3]);

/* control points per direction: 9 for the full circle */
#define NET_MAX_COUNT 9
#define NET_MAX_KNOTS (NET_MAX_COUNT + 3)

/* A rational tensor-product net in the layout of ic_nurbs (point (i, j) at
 * points[3 * (i * count[1] + j)], i along u), clamped full knot vectors. */
typedef struct {
    int degree[2], count[2];
    double knots[2][NET_MAX_KNOTS];
    double points[3 * NET_MAX_COUNT * NET_MAX_COUNT];
    double weights[NET_MAX_COUNT * NET_MAX_COUNT];
    int periodic[2]; /* the net closes on itself along u (v) */
} case_net;

typedef enum { TRUTH_NONE, TRUTH_CIRCLE, TRUTH_VIVIANI, TRUTH_STEINMETZ } truth_kind;

typedef struct {
    const char *name;  /* short, for the table */
    const char *title; /* one line */
    exact_surface A, B;
    case_net netA, netB;
    truth_kind truth;
    double circle_center[3], circle_axis[3], circle_radius; /* TRUTH_CIRCLE */
    int expect_curves, expect_points; /* closed curves and isolated points */
    double expect_length;             /* total length of the curves */
    double expect_point[3];           /* the isolated point, if any */
} bench_case;

#define BENCH_NUM_CASES 6

/* Fills the cases (nets built from the exact surfaces); returns how many. */
int bench_cases_build(bench_case cases[BENCH_NUM_CASES]);

/* The net built for an exact surface: the 9-point rational circle revolved
 * about the axis (sphere, cylinder, torus), a bilinear patch (plane). */
void net_from_exact(case_net *net, const exact_surface *s);

/* The exact curves of a case: how many, their period, and c, c', c'', c'''
 * at parameter t on curve k. */
int truth_num_curves(const bench_case *c);
double truth_period(const bench_case *c);
void truth_derivs(const bench_case *c, int k, double t, double d[4][3]);

/* nearest points of the exact curves this close (length units) to the
 * nearest are ties: at a crossing the sample may belong to either branch */
#define TRUTH_TIE 1e-12
#define TRUTH_MAX_TIES 4

/* Distance of p from the exact curves, and the curvature and torsion (closed
 * forms) at the nearest point and at every tie. Returns how many (0: the
 * case has no curve). */
int truth_nearest(const bench_case *c, const double p[3], double *dist,
                  double kappa[TRUTH_MAX_TIES], double tau[TRUTH_MAX_TIES]);

/* Curvature and torsion from the first three derivatives of a space curve in
 * any parametrisation; *has_tau = 0 where c' x c'' vanishes (no binormal). */
void frenet_from_derivs(const double d1[3], const double d2[3], const double d3[3],
                        double *kappa, double *tau, int *has_tau);

/* Own evaluation of a net (Cox-de Boor and the weighted sum), independent of
 * every engine. */
void net_eval(const case_net *net, double u, double v, double out[3]);

/* Largest distance from the exact surface of the net's points on a grid of
 * n x n parameter values. */
double net_check(const case_net *net, const exact_surface *s, int n);

#ifdef __cplusplus
}
#endif
#endif

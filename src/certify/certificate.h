/*
 * A certificate of a whole intersection (docs/tracing.md, "The
 * certificate"): a cover of the search region by a tree of cells, each leaf
 * proven by interval arithmetic alone to be
 *   empty    - an enclosure of F excludes 0;
 *   outside  - the sheet's image misses the box (parametric pairings);
 *   diagonal - a self-intersection's trivial solutions only: R(a) = R(b)
 *              forces a = b over the cell;
 *   regular  - the minor of J without column `axis` is regular over the
 *              whole cell, so every arc in it is a graph over that
 *              coordinate; every crossing of the cell's faces is isolated
 *              by a Krawczyk test on its face, and sorted along `axis` the
 *              crossings pair up into the cell's arcs;
 *   singular - not empty nor outside, and the cell's image lies within the
 *              singular box of a singular point the result reports (half
 *              width IC_CERTIFY_SINGULAR_HALF of the region's size): what
 *              the cell holds is not proven, only the crossings of the
 *              regular cells around it (tried before regular);
 *   tangential - the same, within the tube about a tangential curve the
 *              result reports (radius IC_CERTIFY_TUBE_HALF, tube.c), whose
 *              points must be where the surfaces touch (claims.c);
 * or refused, with the reason. The checker then holds the traced curves
 * against the crossings (match.c). It uses the pairing's equations and the
 * surfaces' enclosures (system.h), never the tracer's decisions.
 */
#ifndef IC_CERTIFY_CERTIFICATE_H
#define IC_CERTIFY_CERTIFICATE_H

#include "imat.h"
#include "pairing/pairing.h"

typedef enum {
    IC_CELL_SPLIT,
    IC_CELL_EMPTY,
    IC_CELL_OUTSIDE,
    IC_CELL_DIAGONAL,
    IC_CELL_REGULAR,
    IC_CELL_SINGULAR,
    IC_CELL_TANGENTIAL,
    IC_CELL_REFUSED
} ic_cell_kind;

typedef struct {
    double lo[4], hi[4];
    ic_cell_kind kind;
    int axis;        /* split: the coordinate split; regular: the monotone one */
    double at;       /* split: where */
    int child[2];    /* split: the two halves (z[axis] < at, and the rest) */
    int first, ncross; /* regular: its face crossings */
    int nbox;          /* regular: its box crossings, after the face crossings */
} ic_cell;

/* A crossing of a regular cell's face z[face] = (side ? hi : lo): the one
 * root of F on that face in X, which lies in K inside X. */
typedef struct {
    int cell, face, side;
    ic_interval X[4], K[4];
    int mate;   /* the other crossing of its arc in the cell; a box crossing:
                 * its arc's (the lower index of the arc's two crossings) */
    int events; /* how many traced passages met it (match.c) */
    int box;    /* -1 a crossing of the face; else 2 k + side: the root of F
                 * and R_k = box[k][side] inside the cell (boxcross.c), an
                 * end of a curve on the box */
    int outside; /* a face crossing outside the box: no curve meets it */
} ic_crossing;

/* Poles of the sheets at most: four edges of two sheets, each sheet of a
 * self-intersection in both places. */
#define IC_CERTIFY_MAX_POLES 16

/* Untraced arcs a summary gives a point of, at most: one start point per
 * missed curve is enough, and the tracer covers the rest of a curve's
 * arcs by the curve it traces from the first. */
#define IC_CERTIFY_MAX_SEEDS 16

/* A tangential curve the result reports: n points (xyz), closed or not. */
typedef struct {
    const double *xyz;
    int n, closed;
} ic_certify_tube;

typedef struct {
    long cells, empty, outside, diagonal, regular, singular, tangential, refused;
    long crossings, arcs;
    int poles;   /* singular boxes at the sheets' poles (poles.c) */
    int corners; /* and where a curve meets the boundary at a corner or
                  * touches it (corners.c) */
    double seconds;
    int accepted;
    char reason[240];
    /* refused for arcs no traced curve passes: a point of each of the
     * first IC_CERTIFY_MAX_SEEDS (search coordinates, the crossing's
     * enclosure's centre), where the tracer may start again */
    double seeds[IC_CERTIFY_MAX_SEEDS][4];
    int nseeds;
} ic_certify_summary;

/* The work limits of a certificate: cells, the smallest cell as a fraction
 * of the region's width, face boxes per face, and a deadline on the
 * monotonic clock (0: none). */
typedef struct {
    long max_cells;
    double min_width;
    int face_boxes;
    double deadline;
} ic_certify_limits;

/* A certificate file's cover to replay (plan.h). */
typedef struct ic_cover_plan ic_cover_plan;

typedef struct {
    const ic_pairing *pg;
    int dim, m;
    double lo[4], hi[4];
    int periodic[4];
    /* each coordinate's length in space across the region: the longest of
     * its sampled lines, 0 unknown; by_span when they differ by more than
     * IC_CERTIFY_SPAN_RATIO (certificate.c: ic_certificate_rel) */
    double span[4];
    int by_span;
    int has_box;
    double box[3][2];
    ic_cell *cells;
    long ncells, capc;
    ic_crossing *cross;
    long ncross, capx;
    /* the singular points the result reports, then the poles the checker
     * finds (owned), and their boxes' half width (a length:
     * IC_CERTIFY_SINGULAR_HALF of the region's image diagonal) */
    double (*singular)[3];
    double *singular_scale; /* each box's half width over singular_half */
    /* per box, its cells, and those of them where the intersection is
     * proven smooth (leaf.c): a claimed point whose box is smooth all
     * through is no singular point (ic_certificate_refute_smooth) */
    long *box_cells, *box_smooth;
    int nsingular;
    double singular_half;
    /* the poles (poles.c): the search coordinate j whose edge z[j] = edge
     * a sheet collapses, the strip from it to z[j] = edge + strip whose
     * image lies in the pole's singular box, and the point */
    struct {
        int j;
        double edge, strip, xyz[3];
    } poles[IC_CERTIFY_MAX_POLES];
    int npoles;
    /* the tangential curves, their tubes' radius (a length), and the box of
     * every chunk of their segments (tube.c) */
    const ic_certify_tube *tubes;
    int ntubes;
    double tube_half;
    double (*chunk_box)[6];
    /* work memory of face.c, kept from face to face: boxes of a face */
    ic_interval (*face_stack)[4];
    int face_cap;
    /* a file's cover to replay instead of growing one (plan.h), and its
     * next node */
    const ic_cover_plan *plan;
    long plan_next;
    ic_certify_summary summary;
} ic_certificate;

/* A self-intersection's (u, v) periods cut this fraction of the period
 * after the domain's start, its (p, q) periods twice as far (certificate.c):
 * not at the domain's start, not where each other's are, and at
 * irrational-looking places no symmetric problem favours. */
#define IC_CERTIFY_SELF_SEAM_OFFSET 0.0371

/* A new certificate over the pairing's search region (box: the problem's,
 * has_box 0 when it has none); NULL out of memory or when the region has
 * no finite box (err says). */
/* Where search coordinate k was moved from (the pairing's frame, trace/frame.h):
 * the user's coordinate is z[k] + this. */
double ic_certificate_origin(const ic_certificate *c, int k);

ic_certificate *ic_certificate_new(const ic_pairing *pg, const double box[3][2], int has_box,
                                   ic_error *err);
void ic_certificate_free(ic_certificate *c);

/* A width d of coordinate k as a fraction of the region: d over the
 * region's width, or with by_span d's length in space (the coordinate's
 * over the region's width) over the longest coordinate's; with `floor` (or
 * where its length is 0) at least IC_CERTIFY_SPAN_FLOOR of the longest's.
 * The cover splits the cell whose width so measured (floored: a coordinate
 * whose lines collapse is still split) is largest; Newton's steps are
 * measured by it. */
#define IC_CERTIFY_SPAN_FLOOR (1.0 / 64)
double ic_certificate_rel(const ic_certificate *c, int k, double d, int floor);

/* The singular half width: of the region's image diagonal (a fraction). */
#define IC_CERTIFY_SINGULAR_HALF 1e-5

/* A curve end on the region's boundary: within this fraction of the
 * region's width of it. */
#define IC_CERTIFY_END_REACH 1e-6
/* A curve end on the box: within this fraction of the box's width of its
 * face (the tracer sets the coordinate to the bound). */
#define IC_CERTIFY_BOX_REACH 1e-9

/* The result's singular points (copied; scale: each box's half width over
 * IC_CERTIFY_SINGULAR_HALF's, NULL all 1), and a box at each pole of a
 * parametric sheet (ic_certificate_find_poles): 1, 0 when the region's
 * image cannot be enclosed (then no box is given), -1 out of memory. */
int ic_certificate_set_singular(ic_certificate *c, const double (*xyz)[3], const double *scale,
                                int n);

/* The box of a cusp, a tacnode or a higher-order contact, over the
 * others': there two branches share a tangent and lie d^(3/2) (a cusp) or
 * d^2 (the surfaces osculate) apart at distance d, and so are the cells
 * that prove them apart; with a box 400 times wider they are 10^4 to 10^5
 * times wider at its edge. At 100 the cells just outside the box of a
 * crossing of a tangential curve (docs/tracing.md), where the normals are
 * 1.4e-5 apart, stayed undecided to the finest width. */
#define IC_CERTIFY_CONTACT_SCALE 400.0

/* A pole: a domain edge (not a seam) whose image lies within this fraction
 * of the region's size of one point (the sphere's u at v = +-pi/2, a NURBS
 * patch's collapsed row of control points). Its preimage near the edge is
 * a whole strip of parameters, where J loses rank all along; the tracer
 * joins a curve across it and the checker boxes it like a singular point.
 * A small fraction of the box's half width, so the box holds the edge's
 * whole image. Halvings of the strip's width at most, in search of the
 * strip whose image lies in the box. */
#define IC_CERTIFY_POLE_SPREAD 1e-9
#define IC_CERTIFY_POLE_HALVINGS 60

/* Finds the poles of the pairing's parametric sheets (poles.c) and their
 * strips, in c->poles; needs singular_half set. */
void ic_certificate_find_poles(ic_certificate *c);

/* The cell i reaches across the strip of a pole from its edge: the
 * coordinate to split (the strip's other side in *at), or -1. */
int ic_certificate_pole_split(const ic_certificate *c, long i, double *at);

/* The image of cell i (ic_certify_image): 0 when it has no enclosure. */
int ic_certificate_cell_image(const ic_certificate *c, long i, ic_interval img[3]);

/* Where the image over X lies against the problem's box: 1 it misses the
 * box, 0 it lies inside, -1 it straddles a face or cannot be enclosed. */
int ic_certificate_against_box(const ic_certificate *c, const ic_interval *X);

/* The singular point whose box holds cell i's image (the first), or -1. */
int ic_certificate_singular_box(const ic_certificate *c, long i);
#define ic_certificate_in_singular_box(c, i) (ic_certificate_singular_box((c), (i)) >= 0)

/* Refuses the certificate at the first of the claimed singular points
 * 0..nclaimed-1 whose box holds no cell, or only cells where the
 * intersection is proven smooth, piece by piece (a full-rank Jacobian: no
 * branch point, contact, cusp or tacnode there; leaf.c): 1 none such, 0
 * refused. A surface's own singular point (a pole, an apex) is not spared:
 * there the sheet's normal, and so the Jacobian, degenerates, and no piece
 * about it is smooth (before, such points were skipped, and a file could
 * claim one anywhere). */
int ic_certificate_refute_smooth(ic_certificate *c, int nclaimed);

/* The tubes' radius: of the region's image diagonal (a fraction). */
#define IC_CERTIFY_TUBE_HALF 5e-4

/* The result's tangential curves (kept by reference: they must outlive
 * c): 1, 0 when the region's image cannot be enclosed, -1 out of memory. */
int ic_certificate_set_tubes(ic_certificate *c, const ic_certify_tube *tubes, int n);

/* Sets tube_half from the region's size: 0 when it has no enclosure. */
int ic_certificate_tube_size(ic_certificate *c);

/* 1 when cell i's image lies within a tube. */
int ic_certificate_in_tube(const ic_certificate *c, long i);

/* The tubes neither come back on themselves nor meet (else the certificate
 * is refused): 1, 0 refused, -1 out of memory. */
int ic_certificate_tubes_apart(ic_certificate *c);

/* A leaf whose content is not examined: singular or tangential. */
static inline int ic_cell_unexamined(ic_cell_kind kind)
{
    return kind == IC_CELL_SINGULAR || kind == IC_CELL_TANGENTIAL;
}

/* Appends a cell (its box) or a crossing: the index, or -1 out of memory. */
long ic_certificate_add_cell(ic_certificate *c, const double *lo, const double *hi);
long ic_certificate_add_crossing(ic_certificate *c, const ic_crossing *x);

/* A decided leaf of this kind counted in the summary. */
void ic_certificate_count(ic_certificate *c, ic_cell_kind kind);

/* Refuses: the first reason is kept. */
void ic_certificate_refuse(ic_certificate *c, const char *fmt, ...) IC_PRINTF(2, 3);

/* z brought into the region's period on periodic coordinates; a point on
 * the region's upper face stays there (a walk may stand on it). */
void ic_certificate_wrap(const ic_certificate *c, const double *z, double *w);

/* The leaf holding z (in the region, as ic_certificate_wrap leaves it), a
 * tie on coordinate j (a point on a split across j) broken towards dir
 * (+1 the upper cell, -1 the lower; j = -1: no tie, the upper cell); -1
 * when z is outside the region. */
long ic_certificate_locate(const ic_certificate *c, const double *z, int j, int dir);

/* The cover (cover.c): the tree grown from the region, every leaf proven
 * on the spot (leaf.c); stops at the first refusal. IC_OK, or an error out
 * of memory. */
ic_status ic_certify_cover(ic_certificate *c, const ic_certify_limits *lim, ic_error *err);

/* One leaf (leaf.c): labels cell i and isolates its crossings; 1 decided,
 * 0 undecided (split it), -1 out of memory. */
int ic_certify_leaf(ic_certificate *c, long i, const ic_certify_limits *lim);

/* A regular cell whose image straddles the box (boxcross.c): the roots of
 * F with R_k = box[k][side] inside it isolated for every face of the box
 * its image meets, each put on its arc, and its face crossings outside the
 * box marked. 1 done, 0 undecided (split it), -1 out of memory. */
int ic_certify_box_crossings(ic_certificate *c, long cell, int max_boxes);

/* A crossing's enclosure K narrowed by Krawczyk steps on its face while
 * they halve it (face.c): the root, proven unique in X, stays in K. */
void ic_certify_tighten(const ic_certificate *c, ic_crossing *x);

/* The roots of F on face z[j] = v of the box lo..hi (face.c), appended as
 * crossings of cell `cell`: 1 when the whole face was decided, 0 when
 * some part of it could not be within `max_boxes`, -1 out of memory. */
int ic_certify_face(ic_certificate *c, long cell, int j, int side, int max_boxes);

#endif

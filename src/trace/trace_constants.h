/*
 * The register of the tracer's constants (docs/tracing.md, "Constants"):
 * each with its unit and the reason for its value. Lengths are never
 * absolute here: they are fractions of the search region or of a cell, or
 * counts. tests/test_trust.c exercises them (the kink's two lines 0.002
 * apart need IC_TRACE_ON_CURVE, the coincident planes the coincidence
 * constants, the time limit and the overflow cases the work limits); a test
 * per constant that fails when it is changed tenfold is not written yet.
 */
#ifndef IC_TRACE_CONSTANTS_H
#define IC_TRACE_CONSTANTS_H

/* count: search cells one trace may examine, first search and refinement
 * together. A cell costs 1 to 10 microseconds (interval enclosures, a
 * Newton iteration, the loop test), so this bounds the search to seconds on
 * any input; reaching it leaves the rest undecided (complete: false). */
#define IC_TRACE_MAX_CELLS 2000000L

/* levels: how far below the first search's leaves an undecided cell is
 * subdivided (one level halves each side). 16 levels reach 2^-22 of the
 * region at the default depth 6: far below any curve feature the marching
 * resolves, and a refinement that needs more is reported, not pursued. */
#define IC_TRACE_MAX_REFINE_LEVELS 16

/* levels: a loop cell holding a located singular point or a traced
 * tangential curve (where the loop test cannot succeed: N_A x N_B vanishes
 * there) is explained by that point's local analysis once it is this many
 * levels below the first search (1/8 of a first-search cell): nearer cells
 * beside it are refined until proven loop-free. */
#define IC_TRACE_EXPLAIN_LEVELS 3

/* count: undecided cells are merged into at most this many regions, each
 * listed in the report's failures with its box and reason. */
#define IC_TRACE_MAX_REGIONS 64

/* relative (of the problem's scale L): two surfaces through a common point
 * with parallel normals coincide there when points of A at L/8 .. L/64
 * from it lie on B within this fraction of L. Rounding leaves 1e-15; a
 * contact of finite order separates them by far more at L/8. Cells within
 * IC_TRACE_COINCIDENT_REACH L of such a point are part of the coincident
 * region. */
#define IC_TRACE_COINCIDENT_TOL 1e-10
#define IC_TRACE_COINCIDENT_REACH (1.0 / 64)

/* relative (of L): a start candidate, a converged point of both surfaces,
 * lies on a traced curve when it is within the curve's sagitta and this
 * fraction of L of its polyline. Newton leaves 1e-10 L at most; curves
 * closer together than this are taken as one. */
#define IC_TRACE_ON_CURVE 1e-8

/* relative (of L): how far from both surfaces a point the tracer locates
 * may be (the locators' point_tol). Newton leaves about 1e-15 L; 1e-7 L
 * accepts the start candidates of the search (1e-10 L) with room. */
#define IC_TRACE_POINT_TOL 1e-7

/* relative (of L): how well the place of an isolated contact must be known
 * (ic_local_tangential_place: the radius where the locator's residuals sink
 * into rounding) for it to be exact; beyond, it is approximate. */
#define IC_TRACE_PLACE_REL 1e-8

/* relative (of a domain's width, or of L for a box face): a curve whose
 * every step fails, this near a bound it heads across, has left there (a
 * step landed on the bound itself) */
#define IC_TRACE_EDGE_REL 1e-9

/* units in the last place of L: how well a located tangential point's place
 * is known at best (the locator stops at steps of 1e-15 of the unknowns'
 * size); coefficients a shift this small makes are no contact terms */
#define IC_TRACE_PLACE_ULPS 16

/* relative (of L): points of a curve nearer than this to a singular point
 * of a surface (a cone's apex) are dropped: the normal vanishes there and
 * their apparatus errs by about eps (L/d)^2, 1e-8 at this distance. */
#define IC_TRACE_SINGULAR_CLEARANCE 1.5e-4

/* relative (of L): two singular points closer than IC_TRACE_SAME_EXACT L
 * are one (located points agree to 1e-12 L); an approximate one (a curve
 * end that could not be located: the march stops about 2e-6 L before a
 * branch point) is the same as any within IC_TRACE_SAME_APPROX L. */
#define IC_TRACE_SAME_EXACT 1e-10
#define IC_TRACE_SAME_APPROX 1e-4

/* relative (of L): how far from a curve's last point the point it stops
 * before is sought: on the collinear normals (a branch point, about 2e-6 L
 * ahead), and by the degenerate locator (a tacnode's end stops about 2e-3
 * away at L = 1, where Gauss-Newton is ill-conditioned along the curve). */
#define IC_TRACE_END_REACH 1e-4
#define IC_TRACE_DEGENERATE_REACH 5e-3

#endif

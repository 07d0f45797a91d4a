/*
 * The register of the tracer's constants (docs/tracing.md, "Constants"):
 * each with its unit and the reason for its value. Lengths are never
 * absolute here: they are fractions of the search region or of a cell, or
 * counts. Each is pinned by a test that fails when it is changed tenfold
 * (levels: by 4, a factor 16 in cell size), or says below why that change
 * cannot matter (docs/testing.md, "Constants pinned";
 * tests/mutation/mutate_constants.sh builds every mutant; tests/test_constants.c
 * holds the cases).
 */
#ifndef IC_TRACE_CONSTANTS_H
#define IC_TRACE_CONSTANTS_H

/* count: search cells one trace may examine, first search and refinement
 * together. A cell costs 1 to 10 microseconds (interval enclosures, a
 * Newton iteration, the loop test), so this bounds the search to seconds on
 * any input; reaching it leaves the rest undecided (complete: false).
 * Pinned /10 (near planes at depth 9 need 7e5 cells). x10 only bounds time:
 * an input that reaches it takes ten times longer (the expanded quartic of
 * test_contact_place: 25 s, then 290 s), none traced whole needs more. */
#define IC_TRACE_MAX_CELLS 2000000L

/* levels: how far below the first search's leaves an undecided cell is
 * subdivided (one level halves each side). 16 levels reach 2^-22 of the
 * region at the default depth 6: far below any curve feature the marching
 * resolves, and a refinement that needs more is reported, not pursued.
 * Pinned -4 (a loop of width 1e-6 needs 14 levels). +4 only costs time: a
 * deeper refinement finds more, never less, and what needs it is reported. */
#define IC_TRACE_MAX_REFINE_LEVELS 16

/* levels: a loop cell holding a located singular point or a traced
 * tangential curve (where the loop test cannot succeed: N_A x N_B vanishes
 * there) is explained by that point's local analysis once it is this many
 * levels below the first search (1/8 of a first-search cell): nearer cells
 * beside it are refined until proven loop-free.
 * Pinned both ways (0: a loop 0.02 from a contact hidden; 7: the contacts of
 * test_contact_place undecided). */
#define IC_TRACE_EXPLAIN_LEVELS 3

/* count: undecided cells are merged into at most this many regions, each
 * listed in the report's failures with its box and reason.
 * Pinned /10 (eight overflow bands listed one by one). x10 changes only the
 * count in the summary line of an input with more than 64 undecided places:
 * the failures list shows 15 regions at most. */
#define IC_TRACE_MAX_REGIONS 64

/* relative (of the problem's scale L): two surfaces through a common point
 * with parallel normals coincide there when points of A at L/8 .. L/64
 * from it lie on B within this fraction of L. Rounding leaves 1e-15; a
 * contact of finite order separates them by far more at L/8. Cells within
 * IC_TRACE_COINCIDENT_REACH L of such a point are part of the coincident
 * region.
 * Pinned: TOL x10 (a Morse contact 3e-10 L apart at L/8), REACH /10
 * (coincident planes refined: 380 s instead of 0.7). TOL /10 cannot matter:
 * coincident surfaces of the tests agree to 1e-15 L, four orders below; only
 * a formula losing 4 digits to cancellation would. REACH x10 changes only
 * the listed region: the report is incomplete either way, and transversal
 * start points inside it are traced all the same. */
#define IC_TRACE_COINCIDENT_TOL 1e-10
#define IC_TRACE_COINCIDENT_REACH (1.0 / 64)

/* relative (of L): a start candidate, a converged point of both surfaces,
 * lies on a traced curve when it is within the curve's sagitta and this
 * fraction of L of its polyline. Newton leaves 1e-10 L at most; curves
 * closer together than this are taken as one.
 * Pinned x10 (two branches 5e-8 L apart). /10 cannot matter: start points
 * and polylines lie on the surfaces to rounding (1e-15 L below offsets of
 * 1e5 L) and the sagitta allowed is twice a circle's. */
#define IC_TRACE_ON_CURVE 1e-8

/* relative (of L): how far from both surfaces a point the tracer locates
 * may be (the locators' point_tol). Newton leaves about 1e-15 L; 1e-7 L
 * accepts the start candidates of the search (1e-10 L) with room.
 * Not pinned: a gate no point reaches. Every point given to the locators
 * comes from Newton converged to 1e-10 (L + |x|) or better; x10 admits
 * nothing more, /10 still leaves a factor 100. */
#define IC_TRACE_POINT_TOL 1e-7

/* relative (of L): how well the place of an isolated contact must be known
 * (ic_local_tangential_place: the radius where the locator's residuals sink
 * into rounding) for it to be exact; beyond, it is approximate.
 * Not pinned: for two implicit surfaces the place radius is a decade of L
 * (the probe's rungs 1e-15 L 10^k) and 1e-8 L is itself one, so a contact
 * on that rung is exact or approximate by rounding (z = (x - 1/64)^4
 * written out: 1.0000 e-8 L, approximate), and a tenfold change only moves
 * the threshold onto the next rung. A test would pin rounding. */
#define IC_TRACE_PLACE_REL 1e-8
/* The same for a crossing of a tangential curve (crossing.c), placed by
 * the change of sign of the bend across the curve between two points of
 * it: the tangential curve, a double root, is known to about sqrt(eps) L
 * across (a parametric sphere's tangential equator: 1e-8 L), and the
 * bracket stops there, at 2e-8 to 6e-8 L on the sweep of
 * tests/test_certificate_crossings.c. */
#define IC_TRACE_CROSSING_PLACE_REL 1e-6
/* A point known to within place (a crossing) is the same as one recorded
 * within this many places of it: the crossing met from both sides of the
 * transversal curve, each bracket stopping 2e-8 to 6e-8 L wide and up to
 * about a bracket from the other's. */
#define IC_TRACE_SAME_PLACES 16

/* relative (of a domain's width, or of L for a box face): a curve whose
 * every step fails, this near a bound it heads across, has left there (a
 * step landed on the bound itself).
 * Not pinned: a curve that landed on the bound stands on it to rounding
 * (1e-16 of the width), so any tolerance above that decides the same; the
 * rule itself is pinned (test_trust, "tangential arc cut by the domain"). */
#define IC_TRACE_EDGE_REL 1e-9

/* A step whose ends are inside the box and the domains may leave them
 * between (a circle past a box's corner by 1e-7, a step of 1e-2): the
 * predictor (accurate to tol over the step) is sampled at this many
 * intervals, and where a sample comes within IC_TRACE_EXCURSION_REACH of
 * the step's length of a bound, the coordinate's extreme along the
 * predictor is found by golden section; an extreme within
 * IC_TRACE_EXCURSION_TOLS tol of the bound (a length; for a parameter, the
 * same fraction of the domain's width as tol is of L) is tested on the
 * corrected point there. Pinned by tests/test_certificate.c (the clipped
 * circles at b = 0.99999 .. 0.9999999). */
#define IC_TRACE_EXCURSION_SAMPLES 8
#define IC_TRACE_EXCURSION_REACH 0.25
#define IC_TRACE_EXCURSION_TOLS 4.0
#define IC_TRACE_EXCURSION_SECTIONS 40

/* relative (of the problem's size, and of a domain's width for the
 * sheets' parameters): two ends that left the domain this close together,
 * each continuing the other, are one curve touching the
 * domain's edge (Viviani's curve on a sphere whose seam is a plain edge):
 * near the touch the curve lies within rounding of the edge over a stretch
 * of order sqrt(eps), 2.4e-8 measured, and the tracer stops on both sides
 * of it. They are joined across that gap (a curve truly leaving and coming
 * back so close lies within 1e-14 of the edge outside it). */
#define IC_TRACE_TOUCH_GAP 1e-7

/* relative to a NURBS sheet's domain width: a parameter this close to a
 * knot stands on that knot line (docs/nurbs.md). Two sheets of one curve
 * reach a common knot line within rounding of each other (measured 9e-16
 * of the width on the Enneper patch); landing on one then puts the other
 * on it too, rather than a second point 1e-15 further. */
#define IC_TRACE_KNOT_SNAP_REL 1e-13

/* relative (of a parameter's domain width): how far from a degenerate
 * point of a parametrisation (a sphere's pole) a tangential point found
 * there is classified. The normal exists there (|R_u x R_v| about this
 * times |R_v|^2, far above IC_SURFACE_DEGENERATE) and the normals of the
 * two surfaces differ by about this much, well within the relaxed 1e-3 of
 * an approximate point; the point itself is kept where it was found. */
#define IC_TRACE_POLE_NUDGE_REL 1e-6

/* units in the last place of L: how well a located tangential point's place
 * is known at best (the locator stops at steps of 1e-15 of the unknowns'
 * size); coefficients a shift this small makes are no contact terms
 * Not pinned: /10 is overridden by the measured place radius (a few ulps at
 * best); x10 (3.6e-14 L) drops a quadratic coefficient only where a second
 * zero lies within 1e-13 L of the contact, beyond any test's resolution. */
#define IC_TRACE_PLACE_ULPS 16

/* relative (of L): points of a curve nearer than this to a singular point
 * of a surface (a cone's apex) are dropped: the normal vanishes there and
 * their apparatus errs by about eps (L/d)^2, 1e-8 at this distance.
 * The torsion errs more, by about eps (L/d)^3: 1e-5 here, 0.1 at a tenth.
 * Pinned both ways (the cone cut through its apex by a cylinder: the
 * torsion near the apex; the length and the curve joined through it). */
#define IC_TRACE_SINGULAR_CLEARANCE 1.5e-4

/* relative (of L): two singular points closer than IC_TRACE_SAME_EXACT L
 * are one (located points agree to 1e-12 L); an approximate one (a curve
 * end that could not be located: the march stops about 2e-6 L before a
 * branch point) is the same as any within IC_TRACE_SAME_APPROX L.
 * Not pinned. EXACT x10: distinct points 1e-9 L apart are below the
 * tracer's resolution anyway (curves nearer than IC_TRACE_ON_CURVE are
 * one); /10: one point located from two curve ends agrees to 1e-15 L.
 * APPROX /10 decides only whether the two ends at a near-tangency, where no
 * tangential point exists, make one approximate point or two; x10 would
 * merge an unlocatable end with another point within 1e-3 L: no input has
 * such a pair. */
#define IC_TRACE_SAME_EXACT 1e-10
#define IC_TRACE_SAME_APPROX 1e-4

/* relative (of L): how far from a curve's last point the point it stops
 * before is sought: on the collinear normals (a branch point, about 2e-6 L
 * ahead where the surfaces curve by about 1/L; 1e-5 / (2 k) at a saddle of
 * curvature k, 1e-4 at k = 0.05), and by the degenerate locator (a tacnode's end stops about 2e-3
 * away at L = 1, where Gauss-Newton is ill-conditioned along the curve).
 * Pinned: END /10 (a flat saddle's branch point 3e-5 L ahead), DEGENERATE
 * /10 (test_trace_examples: the tacnode). END x10: a farther Gauss-Newton
 * point is checked again (a branch point with nearly tangent branches goes
 * to the degenerate locator) and DEGENERATE x10 admits a farther point only
 * where no nearer one classifies: no input changes. */
#define IC_TRACE_END_REACH 1e-4
#define IC_TRACE_DEGENERATE_REACH 5e-3

/* relative (of L): the grid cell of the curve index (curve_index.c), a
 * spatial hash of the traced segments. Only speed hangs on it: where the
 * index cannot answer from its cells, ic_curve_index_near says so (-1) and
 * every curve is scanned, so any cell size gives the same answers.
 * Not pinned: only time. A segment is entered in every cell that its box,
 * widened by its sagitta, meets, and a query visits every cell of its
 * ball's box (more than 4096: it scans), so a segment within the bound
 * shares a visited cell. x10 and /10: the 1,378 golden documents
 * unchanged; the egg-crate of 7,938 loops (eggcrate-k100) takes 39 s of
 * CPU at x10 and 9 minutes at /10 instead of 15 s. */
#define IC_TRACE_INDEX_CELL (1.0 / 128)

/* chords (of the absolute chord-height bound, opt.chord): the least gap
 * the joining bridges where two curve ends meet at a degenerate point of a
 * parametrization (a sphere patch's pole: both ends left the domain there);
 * the joining bridges up to two last steps each side as well (join.c), so
 * this floor decides only where the last steps are shorter. A start point
 * within it of such an end starts no curve (candidates.c: a sliver of the
 * same curve).
 * Pinned x10 (a loop 0.03 beside a line's end at a domain edge: its start
 * points dropped). /10 only moves where a curve starts: no join of the
 * tests or the bundled cases is decided by the floor (Viviani's gaps at
 * the poles, 0.028 and 0.004, lie within two last steps, 0.069), and start
 * points 5 to 50 chords from a pole's curve end start the same curve from
 * there (golden: 28 documents differ, those of viviani, its NURBS twin and
 * sphere-cylinder-branch: one curve each, lengths within 8e-12). */
#define IC_TRACE_POLE_GAP_CHORDS 50.0

/* chords: a start candidate the locator refused (deferred: at a pole, say)
 * is listed as a failure only when no traced curve or recorded point passes
 * within this many chord heights of it, after the joining has bridged the
 * arcs meeting at the pole.
 * Not pinned: every deferred candidate of the tests and the bundled cases
 * (the poles of the parametric Viviani spheres and of
 * sphere-cylinder-branch) lies on the bridge across its pole, 0 from it
 * once the bridge's sagitta is allowed for, so any radius lists none; it
 * decides only for another curve or point 0.2 to 20 chords from an
 * unlocatable point, which no test or bundled case has (golden unchanged
 * both ways). */
#define IC_TRACE_DEFERRED_CHORDS 2.0

/* The march's step control (march.c, step). */
/* count: halvings of a step that failed before the march gives up on it;
 * 2^-60 takes the longest step (0.05 L) below the smallest one (1e-13 L)
 * with room, so min_step ends the halving first.
 * Pinned /10 (six halvings: the flat saddle, the equal cylinders, the
 * Whitney umbrella and the tangential arcs of test_trust fail). x10 cannot
 * matter: h < min_step ends the loop within log2(max_step / min_step) = 39
 * halvings at the defaults (38 at most tried in every test and bundled
 * case); only max_step above 2^60 min_step reaches 60 (golden unchanged). */
#define IC_TRACE_STEP_HALVINGS 60
/* relative (of L + |x|): near a tangential point a step shorter than this
 * ends the march there (the tangential point is then located) instead of
 * halving on to min_step: steps this short resolve nothing at doubles'
 * precision around |x|.
 * Pinned x10 (test_trust: the Whitney umbrella's double curve ends short,
 * 1.4e-9 of its length). /10 only adds points: the march creeps on by
 * halved steps toward where the normals' angle falls below the local
 * analysis's threshold, and /10 adds 1 to 9 points, each within 5e-10 of
 * an old one (3e-7 at the offset 1e3 of viviani-1e3-offset), every other
 * point within 1e-13 and every length within 2e-16 but the Whitney
 * umbrella's (6e-11), whose approximate pinch point lands 4e-11 instead of
 * 1.3e-10 from the origin (golden: 130 documents differ, by these points). */
#define IC_TRACE_TANGENTIAL_MIN_STEP 1e-10
/* fraction of the step h: the corrected point must advance at least this
 * far along the tangent, else the step is retried shorter (a corrector that
 * slid back along the curve, or onto another branch).
 * Pinned x10 (no step advances 5 h: every trace test but contact_place
 * fails or runs past 2 minutes). /10 cannot matter: the predicted point
 * advances h (1 - kappa^2 h^2 / 6 + ...) and the accepted correction is
 * below h / 2 but for steps under 2e3 tol (2e-8 L); the tests have five
 * such, advancing 0.16 h to 0.5 h by tangential points, and accepting them
 * changes no result (golden unchanged). */
#define IC_TRACE_STEP_ADVANCE 0.5
/* The largest correction accepted, max(TOLS tol, OF_STEP h): the predictor
 * of order K errs by about the truncation tolerance tol per step, so a
 * correction a thousand times larger means the corrector jumped (to
 * another branch or sheet); TOLS tol is the bound of steps below 1e-5 L,
 * OF_STEP h of longer ones. Used by both correctors (the transversal march
 * and a tangential curve's).
 * Not pinned, either way: they decide only where the predictor is
 * poor, and there only the sampling. TOLS x10 and /10: by the Whitney
 * umbrella's pinch point and in tangent-sphere-cylinder-domain (golden: 17
 * documents differ, theirs: 4 to 11 points added or moved, lengths within
 * 6e-11, the approximate pinch point 4e-11 or 1.6e-10 from the origin
 * instead of 1.3e-10). OF_STEP x10 and /10 (56 and 97 documents): the
 * Whitney umbrella likewise, and on NURBS patches x10 leaves 1 to 3 points
 * fewer, /10 adds 1 to 19 or resamples the curve, their lengths within
 * 3e-16. A case would need a jump to another branch by a correction
 * between the two bounds; no test or bundled case has one. */
#define IC_TRACE_CORRECTION_TOLS 1e3
#define IC_TRACE_CORRECTION_OF_STEP 1e-3

/* radians: the threshold of the normals' angle below which a point is
 * tangential, for the classification of a point known only approximately
 * (a curve end just off a tangential point, a candidate nudged off a pole;
 * ic_trace_add_special): relaxed from the local analysis's default because
 * such a point lies up to a step off the tangential point, where the angle
 * is already above the default threshold.
 * Pinned both ways (x10: a plane through a sphere patch's pole at 3e-3
 * rad, taken for a contact there; /10: a bead resting on the pole, whose
 * normals are 3.2e-4 apart where it is classified, lost). */
#define IC_TRACE_APPROX_TANGENTIAL_ANGLE 1e-3

#endif

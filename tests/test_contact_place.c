/* Isolated contacts of high order in the whole trace (the trust issue, item
 * 8): located to full precision and typed as the point analysis types them
 * at the true place, or, where the formula's rounding hides the place,
 * approximate with the report incomplete.
 *
 * Truth is by construction: each surface touches the other exactly at the
 * point c where the height difference is a sum of even powers of (x - c):
 * there is no other common point, and the type follows from the leading
 * form (docs/tangential.md): a positive definite form of degree m >= 3 is a
 * higher-order-contact without branches; x^2 + y^4 has Delta = 0 and an
 * even contact order along the kernel with the sign of an isolated point
 * (isolated-contact); a sphere on a plane is a Morse contact
 * (isolated-contact). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"
#include "traced_pair.h"

/* relative (of the box's diagonal L): the place of an exactly evaluated
 * contact. The locator stops at steps of 1e-15 of the unknowns' size and
 * the lengthened steps land within a few of them: the tier of located points
 * (harness.h), 1e-12 L, is far below the 1e-8 L beyond which a contact is
 * approximate, and far above rounding. */
#define PLACE_TOL TIER_LOCATED
/* relative (of L): an approximate contact is still the one near the truth
 * (the tracer merges approximate points within 1e-4 L) */
#define APPROX_TOL 1e-4

/* seconds of wall time per trace: the exact cases take under 0.3 s */
#define CASE_TIME_LIMIT 2.0
/* AddressSanitizer (make sanitize) runs the traces several times slower */
#ifdef __SANITIZE_ADDRESS__
#define SLOWDOWN 5.0
#else
#define SLOWDOWN 1.0
#endif

typedef struct {
    const char *name;
    const char *A[3]; /* implicit: A[0]; parametric: x, y, z */
    const char *B[3];
    double truth[3];
    const char *type;
    int may_be_approximate; /* the formula cancels: approximate is honest */
} contact_case;

static const double BOX[3][2] = {{-0.7, 1.3}, {-0.6, 1.4}, {-0.5, 1.5}};
static const double DOM[2][2] = {{-0.7, 1.3}, {-0.6, 1.4}};

static int make_surface(ic_surface **s, const char *const f[3], ic_error *err)
{
    if (!f[1])
        return ic_surface_new_implicit(s, f[0], NULL, 0, err) == IC_OK;
    const int per[2] = {0, 0};
    return ic_surface_new_parametric(s, f, NULL, NULL, 0, NULL, err) == IC_OK &&
           ic_surface_set_domain(*s, DOM, per, err) == IC_OK;
}

static int trace_case(traced *t, const contact_case *c)
{
    memset(t, 0, sizeof *t);
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    memcpy(opt.box, BOX, sizeof BOX);
    /* a formula that cancels leaves a blob of undecidable cells around its
     * contact, refined until the work limit: the time limit ends that
     * (the answer is incomplete either way); exact cases finish well within */
    opt.time_limit = CASE_TIME_LIMIT * SLOWDOWN;
    int ok = make_surface(&t->A, c->A, &err) && make_surface(&t->B, c->B, &err) &&
             ic_pair_new(&t->pair, t->A, t->B, &err) == IC_OK &&
             ic_trace(&t->res, t->pair, &opt, &err) == IC_OK;
    if (!ok)
        fprintf(stderr, "%s: %s\n", c->name, err.message);
    return ok;
}

static void check_case(const contact_case *c)
{
    traced t;
    if (!trace_case(&t, c)) {
        CHECK(0, "%s: traced", c->name);
        release(&t);
        return;
    }
    const double L = sqrt(2.0 * 2.0 * 3);
    const ic_trace_result *r = t.res;
    const int n = ic_trace_result_num_specials(r);
    CHECK(ic_trace_result_num_curves(r) == 0 && n == 1, "%s: %d curves, %d points (want 0, 1)",
          c->name, ic_trace_result_num_curves(r), n);
    if (n >= 1) {
        const ic_trace_special *s = ic_trace_result_special(r, 0);
        double d = 0;
        for (int k = 0; k < 3; k++)
            d = fmax(d, fabs(s->xyz[k] - c->truth[k]));
        const int complete = ic_trace_result_report(r)->tracer_complete;
        if (s->approximate) {
            CHECK(c->may_be_approximate && !complete && d <= APPROX_TOL * L,
                  "%s: approximate (complete %d) %.3g from the contact", c->name, complete, d);
        } else {
            CHECK(d <= PLACE_TOL * L, "%s: located %.3g from the contact (tolerance %.1g L)",
                  c->name, d, PLACE_TOL);
            CHECK(strcmp(ic_point_type_name(s->type), c->type) == 0 && s->nbranches == 0,
                  "%s: typed %s with %d branches (want %s)", c->name,
                  ic_point_type_name(s->type), s->nbranches, c->type);
            CHECK(complete, "%s: complete %d", c->name, complete);
        }
    }
    release(&t);
}

int main(void)
{
    static const contact_case cases[] = {
        {"x^4 + y^4 on z = 0", {"z - x^4 - y^4"}, {"z"}, {0, 0, 0}, "higher-order-contact", 0},
        {"order 4 off the origin",
         {"z - 0.1 - (x - 0.3)^4 - (y + 0.2)^4"},
         {"z - 0.1"},
         {0.3, -0.2, 0.1},
         "higher-order-contact",
         0},
        {"x^6 + y^6 on z = 0", {"z - x^6 - y^6"}, {"z"}, {0, 0, 0}, "higher-order-contact", 0},
        {"x^4 + x^2 y^2 + y^4 (a mixed quartic form)",
         {"z - 0.05 - (x - 0.2)^4 - (x - 0.2)^2*(y - 0.1)^2 - (y - 0.1)^4"},
         {"z - 0.05"},
         {0.2, 0.1, 0.05},
         "higher-order-contact",
         0},
        {"x^2 + y^4 (Delta = 0, isolated)", {"z - x^2 - y^4"}, {"z"}, {0, 0, 0}, "isolated-contact",
         0},
        {"a sphere on a plane (Morse)",
         {"x^2 + y^2 + (z - 0.5)^2 - 0.25"},
         {"z"},
         {0, 0, 0},
         "isolated-contact",
         0},
        {"parametric graph, order 4, on an implicit plane",
         {"u", "v", "(u - 0.25)^4 + (v - 0.5)^4"},
         {"z"},
         {0.25, 0.5, 0},
         "higher-order-contact",
         0},
        {"parametric graph, order 4, on a parametric plane",
         {"u", "v", "0.2 + (u + 0.25)^4 + (v - 0.5)^4"},
         {"u", "v", "0.2"},
         {-0.25, 0.5, 0.2},
         "higher-order-contact",
         0},
        /* (x - 0.3)^4 expanded: its terms cancel to about 1e-18 near 0.3, and
         * the place is known only to about (1e-18)^(1/3) */
        {"(x - 0.3)^4 expanded (the formula cancels)",
         {"z - (x^4 - 1.2*x^3 + 0.54*x^2 - 0.108*x + 0.0081) - y^4"},
         {"z"},
         {0.3, 0, 0},
         "higher-order-contact",
         1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_case(&cases[i]);
    return harness_finish("contact_place");
}

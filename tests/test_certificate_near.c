/*
 * Surfaces that nearly coincide (docs/tracing.md, "Second-order
 * exclusion"): two implicit surfaces a gap g of 1e-6 to 1e-12 apart over a
 * whole sheet. First-order forms exclude only cells of width about
 * sqrt(g) there, 1e10 cells for a unit sphere at g = 1e-9; the Taylor form
 * to second order of f_B - mu f_A separates quadrics in a few cells, and
 * the sum of the terms the two formulas share, each taken once, separates
 * any two written alike (tori, quartics). Truth by
 * construction: each pair below is nested (one surface strictly inside
 * the other), so the intersection is empty, and the answer must be
 * complete, proven by the certificate, with no curve and no point. Two
 * controls that do meet: spheres 1e-3 apart in radius with centres 3e-3
 * apart (a circle, traced and proven), and 1e-9 apart with centres 3e-9
 * apart (a circle at an angle of 3e-9: it must not be proven empty).
 */
#include <math.h>
#include <stdio.h>

#include "certify_harness.h"

typedef struct {
    const char *name, *A, *B, *box;
} near_case;

#define TYPED(t, rest) "{\"type\": \"" t "\", " rest "}"
#define CUBE "[[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]"
static const near_case NESTED[] = {
    {"spheres 1e-6 apart", "x^2 + y^2 + z^2 - 1", "x^2 + y^2 + z^2 - (1 + 1e-6)^2", CUBE},
    {"spheres 1e-9 apart", "x^2 + y^2 + z^2 - 1", "x^2 + y^2 + z^2 - (1 + 1e-9)^2", CUBE},
    {"spheres 1e-12 apart", "x^2 + y^2 + z^2 - 1", "x^2 + y^2 + z^2 - (1 + 1e-12)^2", CUBE},
    /* on |x| = 1, |x - 1e-10 e_x| <= 1 + 1e-10 < 1 + 1e-9: A strictly inside B */
    {"spheres 1e-9 apart, centres 1e-10 apart", "x^2 + y^2 + z^2 - 1",
     "(x - 1e-10)^2 + y^2 + z^2 - (1 + 1e-9)^2", CUBE},
    {"spheres 1e-9 apart about (3, -2, 1)", "(x - 3)^2 + (y + 2)^2 + (z - 1)^2 - 1",
     "(x - 3)^2 + (y + 2)^2 + (z - 1)^2 - (1 + 1e-9)^2", "[[1.5, 4.5], [-3.5, -0.5], [-0.5, 2.5]]"},
    {"ellipsoids 2e-9 apart in level", "x^2/4 + y^2 + z^2/9 - 1", "x^2/4 + y^2 + z^2/9 - 1 - 2e-9",
     "[[-3, 3], [-2, 2], [-4, 4]]"},
    {"coaxial cylinders 1e-9 apart", "x^2 + y^2 - 1", "x^2 + y^2 - (1 + 1e-9)^2", CUBE},
    /* f_B = f_A - g, g > 0 (as compiled: the constants folded to doubles
     * still differ): the level sets f_A = 0 and f_A = g are disjoint, and
     * the Hessians vary over a cell, so only the terms the formulas share,
     * taken once, separate them */
    {"tori 1e-9 apart in level", "(sqrt(x^2 + y^2) - 2)^2 + z^2 - 0.25",
     "(sqrt(x^2 + y^2) - 2)^2 + z^2 - 0.25 - 1e-9", "[[-3, 3], [-3, 3], [-1, 1]]"},
    {"quartic blobs 1e-9 apart in level", "x^4 + y^4 + z^4 - 1", "x^4 + y^4 + z^4 - 1 - 1e-9",
     CUBE},
    {"quartic blobs scaled, 2e-9 apart in level", "2*(x^4 + y^4 + z^4) - 2",
     "2*(x^4 + y^4 + z^4) - 2 - 2e-9", CUBE},
    {"exp blobs 1e-9 apart in level", "exp(x) + y^2 + z^2 - 2", "exp(x) + y^2 + z^2 - 2 - 1e-9",
     "[[-2, 1.5], [-1.5, 1.5], [-1.5, 1.5]]"},
};
enum { NNESTED = sizeof NESTED / sizeof NESTED[0] };

/* The same with primitives (their quadratic forms' Hessians, placed). */
static const near_case PRIMITIVES[] = {
    {"sphere primitives 1e-9 apart", TYPED("sphere", "\"center\": [0.3, 0.1, -0.2], \"radius\": 1"),
     TYPED("sphere", "\"center\": [0.3, 0.1, -0.2], \"radius\": \"1 + 1e-9\""),
     "[[-1.5, 2], [-1.5, 1.5], [-1.5, 1.5]]"},
    {"cylinder primitives 1e-9 apart about (1, 1, 1)",
     TYPED("cylinder", "\"center\": [0, 0, 0], \"axis\": [1, 1, 1], \"radius\": 1"),
     TYPED("cylinder", "\"center\": [0, 0, 0], \"axis\": [1, 1, 1], \"radius\": \"1 + 1e-9\""),
     "[[-2, 2], [-2, 2], [-2, 2]]"},
};
enum { NPRIM = sizeof PRIMITIVES / sizeof PRIMITIVES[0] };

static void problem(const near_case *k, int formulas, char *json, size_t size)
{
    if (formulas)
        snprintf(json, size,
                 "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"%s\"}, "
                 "{\"type\": \"implicit\", \"f\": \"%s\"}], \"box\": %s}",
                 k->A, k->B, k->box);
    else
        snprintf(json, size, "{\"surfaces\": [%s, %s], \"box\": %s}", k->A, k->B, k->box);
}

static void sweep(const near_case *cases, int n, int formulas)
{
    for (int i = 0; i < n; i++) {
        char json[1024];
        problem(&cases[i], formulas, json, sizeof json);
        traced t;
        if (trace_json(&t, cases[i].name, json) == 0) {
            const ic_trace_report *rep = ic_trace_result_report(t.res);
            CHECK(rep->complete && rep->certificate.accepted &&
                      ic_trace_result_num_curves(t.res) == 0 &&
                      ic_trace_result_num_specials(t.res) == 0,
                  "%s: complete %d, accepted %d, %d curves, %d points (want proven empty)",
                  cases[i].name, rep->complete, rep->certificate.accepted,
                  ic_trace_result_num_curves(t.res), ic_trace_result_num_specials(t.res));
        }
        release(&t);
    }
}

/* |x| = 1 and |x - d e_x| = R meet in the plane x = (1 + d^2 - R^2) / (2 d),
 * a circle of radius sqrt(1 - x^2). */
static double circle_length(double d, double R)
{
    const double x = (1.0 + d * d - R * R) / (2.0 * d);
    return 4.0 * acos(0.0) * sqrt(1.0 - x * x); /* 2 pi r */
}

/* The problem traces one closed circle of length want, proven: 1e-10 is
 * the tracer's default tolerance, relative to the size (these are within
 * 1e-14). */
static void one_circle(const char *name, const char *json, double want)
{
    traced t;
    if (trace_json(&t, name, json) == 0) {
        const ic_trace_report *rep = ic_trace_result_report(t.res);
        const int n = ic_trace_result_num_curves(t.res);
        const double got = n == 1 ? ic_trace_result_curve(t.res, 0)->length : -1.0;
        CHECK(rep->complete && n == 1 && ic_trace_result_curve(t.res, 0)->closed &&
                  fabs(got - want) <= 1e-10 * want,
              "%s: complete %d, %d curves, length %.15g (want one closed circle of %.15g)", name,
              rep->complete, n, got, want);
    }
    release(&t);
}

static void controls(void)
{
    /* formulas alike but for one term: (x - 0.5)^2 and x^2 are not one
     * term, and the unit spheres about (0.5, 0, 0) and the origin meet in
     * the circle x = 0.25 of radius sqrt(15) / 4 */
    one_circle("spheres with one unlike term",
               "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"(x - 0.5)^2 + y^2 + z^2 - 1\"}, "
               "{\"type\": \"implicit\", \"f\": \"x^2 + y^2 + z^2 - 1\"}], \"box\": " CUBE "}",
               circle_length(0.5, 1.0));
    one_circle("spheres meeting at 1e-3",
               "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2 + y^2 + z^2 - 1\"}, "
               "{\"type\": \"implicit\", \"f\": \"(x - 3e-3)^2 + y^2 + z^2 - (1 + 1e-3)^2\"}], "
               "\"box\": " CUBE "}",
               circle_length(3e-3, 1.001));
    traced t;
    const char *grazing = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2 + y^2 + z^2 - "
                          "1\"}, {\"type\": \"implicit\", \"f\": \"(x - 3e-9)^2 + y^2 + z^2 - "
                          "(1 + 1e-9)^2\"}], \"box\": " CUBE "}";
    /* 2 s: the search gives up there after 30 s; an unsound exclusion
     * would prove it empty within the first few cells */
    if (trace_json_limited(&t, "spheres meeting at 3e-9", grazing, 2.0) == 0) {
        const ic_trace_report *rep = ic_trace_result_report(t.res);
        CHECK(!(rep->complete && ic_trace_result_num_curves(t.res) == 0),
              "spheres meeting at 3e-9 (a circle of length %.6g): proven empty",
              circle_length(3e-9, 1.0 + 1e-9));
    }
    release(&t);
}

int main(void)
{
    sweep(NESTED, NNESTED, 1);
    sweep(PRIMITIVES, NPRIM, 0);
    controls();
    return harness_finish("test_certificate_near");
}

/* Jets against truth computed offline at 60 digits by an independent method
 * (tests/truth/gen_jet_truth.py): every elementary function, products,
 * quotients and atan2, at two or three points each, in 1, 2 and 3
 * variables, orders 8, 12 and 16. */
#include <string.h>

#include "harness.h"
#include "intercurve/jet.h"

#define MAXN 4845

static int read_coefs(FILE *f, char tag, double *c, int n)
{
    char t[8];
    if (fscanf(f, "%7s", t) != 1 || t[0] != tag)
        return -1;
    for (int i = 0; i < n; i++)
        if (fscanf(f, "%lf", &c[i]) != 1)
            return -1;
    return 0;
}

/* Computes name(a[, b]) into r. */
static ic_status apply(const char *name, const char *param, double *r, const double *a,
                       const double *b, const ic_jet_space *sp, double *scratch)
{
    const double p = atof(param);
    if (!strcmp(name, "exp")) { ic_jet_exp(r, a, sp); return IC_OK; }
    if (!strcmp(name, "log")) return ic_jet_log(r, a, sp, NULL);
    if (!strcmp(name, "sqrt")) return ic_jet_sqrt(r, a, sp, NULL);
    if (!strcmp(name, "sin")) { ic_jet_sin(r, a, sp, scratch); return IC_OK; }
    if (!strcmp(name, "cos")) { ic_jet_cos(r, a, sp, scratch); return IC_OK; }
    if (!strcmp(name, "tan")) return ic_jet_tan(r, a, sp, scratch, NULL);
    if (!strcmp(name, "asin")) return ic_jet_asin(r, a, sp, scratch, NULL);
    if (!strcmp(name, "acos")) return ic_jet_acos(r, a, sp, scratch, NULL);
    if (!strcmp(name, "atan")) { ic_jet_atan(r, a, sp, scratch); return IC_OK; }
    if (!strcmp(name, "sinh")) { ic_jet_sinh(r, a, sp, scratch); return IC_OK; }
    if (!strcmp(name, "cosh")) { ic_jet_cosh(r, a, sp, scratch); return IC_OK; }
    if (!strcmp(name, "tanh")) { ic_jet_tanh(r, a, sp, scratch); return IC_OK; }
    if (!strcmp(name, "powr")) return ic_jet_pow_real(r, a, p, sp, scratch, NULL);
    if (!strcmp(name, "powi")) return ic_jet_pow_int(r, a, (long)p, sp, scratch, NULL);
    if (!strcmp(name, "mul")) { ic_jet_mul(r, a, b, sp); return IC_OK; }
    if (!strcmp(name, "div")) return ic_jet_div(r, a, b, sp, NULL);
    if (!strcmp(name, "atan2")) return ic_jet_atan2(r, a, b, sp, scratch, NULL);
    return IC_ERR_INVALID;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "tests/truth/jet_truth.txt";
    FILE *f = fopen(path, "r");
    if (!REQUIRE(f != NULL, "cannot open the truth file %s", path))
        return harness_finish("test_jet_truth");
    static double a[MAXN], b[MAXN], want[MAXN], got[MAXN];
    char line[256];
    int expected = -1;
    /* the header comment: "...; N cases" */
    if (!REQUIRE(fgets(line, sizeof line, f) != NULL, "%s: no header line", path)) {
        fclose(f);
        return harness_finish("test_jet_truth");
    }
    const char *semi = strrchr(line, ';');
    if (semi)
        expected = atoi(semi + 1);
    double worst = 0.0;
    int cases = 0;
    char name[32], param[32];
    int m, K;
    while (fscanf(f, " case %31s %d %d %31s", name, &m, &K, param) == 4) {
        ic_jet_space *sp = NULL;
        if (!REQUIRE(ic_jet_space_new(&sp, m, K, NULL) == IC_OK,
                     "case %s: jet space of %d variables, order %d", name, m, K))
            break;
        const int n = ic_jet_space_len(sp);
        const int binary = !strcmp(name, "mul") || !strcmp(name, "div") || !strcmp(name, "atan2");
        double *scratch = malloc(ic_jet_scratch_len(sp) * sizeof *scratch);
        if (!REQUIRE(!read_coefs(f, 'a', a, n) && !(binary && read_coefs(f, 'b', b, n)) &&
                         !read_coefs(f, 'r', want, n),
                     "malformed truth file at case %s", name) ||
            !REQUIRE(scratch != NULL, "case %s: no memory for the scratch", name)) {
            free(scratch);
            ic_jet_space_free(sp);
            break;
        }
        ic_status st = apply(name, param, got, a, binary ? b : NULL, sp, scratch);
        CHECK(st == IC_OK, "%s in %d vars order %d: status %d", name, m, K, st);
        /* in units of (d + 1) ulps of the largest coefficient up to degree d
         * (TIER_JET_TRUTH, harness.h) */
        double big = 0.0;
        for (int d = 0; d <= K; d++) {
            for (int i = ic_jet_degree_start(sp, d); i < ic_jet_degree_start(sp, d + 1); i++)
                big = fmax(big, fabs(want[i]));
            for (int i = ic_jet_degree_start(sp, d); i < ic_jet_degree_start(sp, d + 1); i++) {
                const double err = fabs(got[i] - want[i]) / (big * DBL_EPSILON * (d + 1));
                worst = fmax(worst, err);
                CHECK(err <= TIER_JET_TRUTH, "%s (%s) %d vars order %d, coefficient %d (degree %d): got "
                      "%.17g want %.17g (%.1f units)", name, param, m, K, i, d, got[i], want[i],
                      err);
            }
        }
        free(scratch);
        ic_jet_space_free(sp);
        cases++;
    }
    fclose(f);
    CHECK(cases == expected && cases > 0, "read %d cases, the file announces %d", cases, expected);
    printf("worst error: %.2f units of (d+1) eps x max |coefficient| (tolerance %g)\n", worst,
           TIER_JET_TRUTH);
    return harness_finish("test_jet_truth");
}

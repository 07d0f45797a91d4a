/* The length and plane-angle units of a STEP file (step_surface.h):
 * (LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.)), or a
 * CONVERSION_BASED_UNIT('INCH', #m) with #m = LENGTH_MEASURE_WITH_UNIT(
 * LENGTH_MEASURE(25.4), #mm). The unit a GLOBAL_UNIT_ASSIGNED_CONTEXT
 * names wins; without one, the first length unit in the file. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "step_surface.h"

typedef struct {
    const char *name;
    double factor;
    const char *symbol;
} si_prefix;

static const si_prefix PREFIXES[] = {
    {"EXA", 1e18, "E"},   {"PETA", 1e15, "P"},  {"TERA", 1e12, "T"},  {"GIGA", 1e9, "G"},
    {"MEGA", 1e6, "M"},   {"KILO", 1e3, "k"},   {"HECTO", 1e2, "h"},  {"DECA", 1e1, "da"},
    {"DECI", 1e-1, "d"},  {"CENTI", 1e-2, "c"}, {"MILLI", 1e-3, "m"}, {"MICRO", 1e-6, "u"},
    {"NANO", 1e-9, "n"},  {"PICO", 1e-12, "p"}, {"FEMTO", 1e-15, "f"}, {"ATTO", 1e-18, "a"},
};

/* Conversion-based units refer to other units: followed this deep at most. */
enum { MAX_UNIT_DEPTH = 4 };

/* SI_UNIT(prefix, name) of an instance whose unit part is `kind`: its
 * factor to the base unit (METRE or RADIAN), the symbol into out. 0, or -1
 * when it is not such a unit. */
static int si_unit(const ic_step_file *f, const ic_step_instance *in, const char *base,
                   const char *symbol, double *factor, char *out, size_t size)
{
    const int si = ic_step_part(f, in, "SI_UNIT");
    if (si < 0 || !ic_step_is(f, ic_step_param(f, si, 1), base))
        return -1;
    const int prefix = ic_step_param(f, si, 0);
    *factor = 1;
    snprintf(out, size, "%s", symbol);
    for (size_t k = 0; k < sizeof PREFIXES / sizeof PREFIXES[0]; k++)
        if (ic_step_is(f, prefix, PREFIXES[k].name)) {
            *factor = PREFIXES[k].factor;
            snprintf(out, size, "%s%s", PREFIXES[k].symbol, symbol);
        }
    return 0;
}

/* The unit of `kind` (LENGTH_UNIT, PLANE_ANGLE_UNIT) that instance #id is:
 * its size in the base unit and its name; 0, or -1. */
static int unit_of(const ic_step_file *f, int id, const char *kind, const char *base,
                   const char *symbol, double *factor, char *out, size_t size, int depth)
{
    const ic_step_instance *in = ic_step_find(f, id);
    if (!in || depth > MAX_UNIT_DEPTH || ic_step_part(f, in, kind) < 0)
        return -1;
    if (si_unit(f, in, base, symbol, factor, out, size) == 0)
        return 0;
    const int conv = ic_step_part(f, in, "CONVERSION_BASED_UNIT");
    if (conv < 0)
        return -1;
    char name[24];
    ic_step_text(f, ic_step_param(f, conv, 0), name, sizeof name);
    for (char *c = name; *c; c++)
        *c = (char)tolower((unsigned char)*c);
    /* the factor: a MEASURE_WITH_UNIT(value, unit) */
    const int ref = ic_step_param(f, conv, 1);
    const ic_step_instance *m =
        ref >= 0 && f->values[ref].kind == IC_STEP_REF ? ic_step_find(f, f->values[ref].u.ref) : NULL;
    double value, inner;
    char inner_name[24];
    const int unit_ref = m ? ic_step_param(f, m->part, 1) : -1;
    if (!m || m->complex || ic_step_number(f, ic_step_param(f, m->part, 0), &value) < 0 ||
        unit_ref < 0 || f->values[unit_ref].kind != IC_STEP_REF ||
        unit_of(f, f->values[unit_ref].u.ref, kind, base, symbol, &inner, inner_name,
                sizeof inner_name, depth + 1) < 0 ||
        !(value * inner > 0) || !isfinite(value * inner))
        return -1;
    *factor = value * inner;
    snprintf(out, size, "%s", name[0] ? name : "unnamed");
    return 0;
}

/* The first unit of `kind` in a GLOBAL_UNIT_ASSIGNED_CONTEXT, else in the file. */
static int find_unit(const ic_step_file *f, const char *kind, const char *base,
                     const char *symbol, double *factor, char *out, size_t size)
{
    for (int k = 0; k < f->ninst; k++) {
        const int ctx = ic_step_part(f, &f->inst[k], "GLOBAL_UNIT_ASSIGNED_CONTEXT");
        const int list = ic_step_param(f, ctx, 0);
        const int first = list >= 0 && f->values[list].kind == IC_STEP_LIST ? f->values[list].child : -1;
        for (int v = first; v >= 0; v = f->values[v].next) {
            if (f->values[v].kind == IC_STEP_REF &&
                unit_of(f, f->values[v].u.ref, kind, base, symbol, factor, out, size, 0) == 0)
                return 0;
        }
    }
    for (int k = 0; k < f->ninst; k++)
        if (unit_of(f, f->inst[k].id, kind, base, symbol, factor, out, size, 0) == 0)
            return 0;
    return -1;
}

void ic_step_find_units(const ic_step_file *f, ic_step_units *u)
{
    memset(u, 0, sizeof *u);
    if (find_unit(f, "LENGTH_UNIT", "METRE", "m", &u->metres, u->length, sizeof u->length) < 0) {
        u->metres = 0;
        u->length[0] = '\0';
    }
    char angle[24];
    if (find_unit(f, "PLANE_ANGLE_UNIT", "RADIAN", "rad", &u->radians, angle, sizeof angle) < 0)
        u->radians = 1;
}

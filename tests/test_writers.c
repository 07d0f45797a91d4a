/* The CSV, VTK and OBJ writers: each file is read back and compared with the
 * result it came from. Numbers must read back bit for bit (17 significant
 * digits round-trip a double exactly), so the comparisons are exact. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"
#include "traced_example.h"

/* Splits a CSV line in place into at most max fields; returns the count. */
static int split_csv(char *line, char **fields, int max)
{
    int n = 0;
    line[strcspn(line, "\n")] = '\0';
    for (char *p = line; n < max;) {
        fields[n++] = p;
        char *comma = strchr(p, ',');
        if (!comma)
            break;
        *comma = '\0';
        p = comma + 1;
    }
    return n;
}

/* The field holds exactly x (or is empty and x is undefined). */
static int field_is(const char *field, double x, int defined)
{
    if (!defined)
        return field[0] == '\0';
    char *end;
    const double v = strtod(field, &end);
    return *end == '\0' && end != field && v == x;
}

static void check_csv(const traced *t, const char *name)
{
    FILE *f = tmpfile();
    ic_error err;
    CHECK(f && ic_trace_write_csv(f, t->res, t->pair, &err) == IC_OK, "%s: CSV written", name);
    if (!f)
        return;
    rewind(f);
    char line[4096], *fld[32];
    CHECK(fgets(line, sizeof line, f) &&
              strcmp(line, "curve,s,x,y,z,u,v,p,q,tx,ty,tz,nx,ny,nz,bx,by,bz,kappa,tau,type\n") ==
                  0,
          "%s: the CSV header of docs/output-formats.md", name);
    int par[2];
    for (int s = 0; s < 2; s++)
        par[s] = ic_surface_get_kind(ic_pair_surface(t->pair, s)) == IC_PARAMETRIC;
    int bad = 0, rows = 0;
    for (int i = 0; i < ic_trace_result_num_curves(t->res); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t->res, i);
        for (int k = 0; k < c->npoints; k++, rows++) {
            const ic_trace_point *p = &c->points[k];
            if (!fgets(line, sizeof line, f) || split_csv(line, fld, 32) != 21) {
                bad++;
                continue;
            }
            const int fd = p->frame_defined;
            int ok = atoi(fld[0]) == i && field_is(fld[1], p->s, 1) &&
                     field_is(fld[18], p->kappa, 1) && field_is(fld[19], p->tau, fd) &&
                     strcmp(fld[20], ic_point_type_name(ic_trace_point_type(t->res, c, p))) == 0;
            for (int j = 0; j < 3; j++)
                ok = ok && field_is(fld[2 + j], p->xyz[j], 1) && field_is(fld[9 + j], p->t[j], 1) &&
                     field_is(fld[12 + j], p->n[j], fd) && field_is(fld[15 + j], p->b[j], fd);
            for (int j = 0; j < 4; j++)
                ok = ok && field_is(fld[5 + j], p->params[j / 2][j % 2], par[j / 2]);
            bad += !ok;
        }
    }
    for (int i = 0; i < ic_trace_result_num_specials(t->res); i++, rows++) {
        const ic_trace_special *sp = ic_trace_result_special(t->res, i);
        if (!fgets(line, sizeof line, f) || split_csv(line, fld, 32) != 21 || fld[0][0] ||
            !field_is(fld[2], sp->xyz[0], 1) || !field_is(fld[4], sp->xyz[2], 1) ||
            strcmp(fld[20], ic_point_type_name(sp->type)) != 0)
            bad++;
    }
    CHECK(bad == 0 && !fgets(line, sizeof line, f), "%s: %d CSV rows, %d differ from the result",
          name, rows, bad);
    fclose(f);
}

/* Reads "KEYWORD n ..." lines of the VTK file and checks the structure and
 * every coordinate; the point data arrays are checked for t and kappa. */
static void check_vtk(const traced *t, const char *name)
{
    FILE *f = tmpfile();
    ic_error err;
    CHECK(f && ic_trace_write_vtk(f, t->res, &err) == IC_OK, "%s: VTK written", name);
    if (!f)
        return;
    rewind(f);
    char line[256];
    int header = 1;
    for (int i = 0; i < 4; i++)
        header = header && fgets(line, sizeof line, f);
    CHECK(header && strcmp(line, "DATASET POLYDATA\n") == 0, "%s: a PolyData header", name);
    const int ns = ic_trace_result_num_specials(t->res), nc = ic_trace_result_num_curves(t->res);
    int npts = ns;
    for (int i = 0; i < nc; i++)
        npts += ic_trace_result_curve(t->res, i)->npoints;
    int n = -1, bad = 0;
    CHECK(fscanf(f, " POINTS %d double", &n) == 1 && n == npts, "%s: %d points of %d", name, n,
          npts);
    for (int i = 0; i < nc; i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t->res, i);
        for (int k = 0; k < c->npoints; k++) {
            double x[3];
            bad += fscanf(f, "%lf %lf %lf", &x[0], &x[1], &x[2]) != 3 ||
                   memcmp(x, c->points[k].xyz, sizeof x) != 0;
        }
    }
    for (int i = 0; i < ns; i++) {
        double x[3];
        bad += fscanf(f, "%lf %lf %lf", &x[0], &x[1], &x[2]) != 3 ||
               memcmp(x, ic_trace_result_special(t->res, i)->xyz, sizeof x) != 0;
    }
    CHECK(bad == 0, "%s: VTK coordinates, %d differ", name, bad);
    int a = -1, b = -1, idx;
    if (ns > 0) {
        CHECK(fscanf(f, " VERTICES %d %d", &a, &b) == 2 && a == ns && b == 2 * ns,
              "%s: one vertex per special point", name);
        for (int i = 0; i < ns; i++)
            bad += fscanf(f, "%d %d", &a, &idx) != 2 || a != 1 || idx != npts - ns + i;
    }
    CHECK(fscanf(f, " LINES %d %d", &a, &b) == 2 && a == nc && b == nc + npts - ns,
          "%s: one polyline per curve", name);
    for (int i = 0, first = 0; i < nc; i++) {
        const int m = ic_trace_result_curve(t->res, i)->npoints;
        bad += fscanf(f, "%d", &a) != 1 || a != m;
        for (int k = 0; k < m; k++)
            bad += fscanf(f, "%d", &idx) != 1 || idx != first + k;
        first += m;
    }
    CHECK(bad == 0 && fscanf(f, " POINT_DATA %d", &a) == 1 && a == npts,
          "%s: connectivity and point data size", name);
    int matched = -1; /* %n is set only if the whole literal matched */
    CHECK(fscanf(f, " VECTORS t double%n", &matched) == 0 && matched > 0, "%s: the t array", name);
    const ic_trace_point *p0 = &ic_trace_result_curve(t->res, 0)->points[0];
    double v[3];
    CHECK(fscanf(f, "%lf %lf %lf", &v[0], &v[1], &v[2]) == 3 && memcmp(v, p0->t, sizeof v) == 0,
          "%s: t of the first point", name);
    /* every array is announced once: t, n, b, kappa, tau, s, curve, traced */
    rewind(f);
    int arrays = 0;
    while (fgets(line, sizeof line, f))
        arrays += strncmp(line, "VECTORS ", 8) == 0 || strncmp(line, "SCALARS ", 8) == 0;
    CHECK(arrays == 8, "%s: 8 point data arrays, not %d", name, arrays);
    fclose(f);
}

static void check_obj(const traced *t, const char *name)
{
    FILE *f = tmpfile();
    ic_error err;
    CHECK(f && ic_trace_write_obj(f, t->res, &err) == IC_OK, "%s: OBJ written", name);
    if (!f)
        return;
    rewind(f);
    char line[1 << 16];
    int v = 0, l = 0, p = 0, bad = 0, expect = 1;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == 'v')
            v++;
        else if (line[0] == 'l') {
            const int m = ic_trace_result_curve(t->res, l++)->npoints;
            char *q = line + 1;
            for (int k = 0; k < m; k++)
                bad += strtol(q, &q, 10) != expect++;
            bad += strspn(q, " \n") != strlen(q);
        } else if (line[0] == 'p')
            bad += atoi(line + 1) != expect++, p++;
    }
    CHECK(bad == 0 && v == expect - 1 && l == ic_trace_result_num_curves(t->res) &&
              p == ic_trace_result_num_specials(t->res),
          "%s: OBJ %d vertices, %d polylines, %d points, %d bad indices", name, v, l, p, bad);
    fclose(f);
}

/* A full disk: the writers report IC_ERR_IO, not success. */
static void check_write_failure(const traced *t)
{
    FILE *f = fopen("/dev/full", "w");
    if (!REQUIRE(f != NULL, "cannot open /dev/full (the project builds on Linux)"))
        return;
    setvbuf(f, NULL, _IONBF, 0);
    ic_error err;
    CHECK(ic_trace_write_csv(f, t->res, t->pair, &err) == IC_ERR_IO && strstr(err.message, "CSV"),
          "a failed CSV write is reported: %s", err.message);
    CHECK(ic_trace_write_vtk(f, t->res, &err) == IC_ERR_IO, "a failed VTK write is reported");
    CHECK(ic_trace_write_obj(f, t->res, &err) == IC_ERR_IO, "a failed OBJ write is reported");
    fclose(f);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    /* implicit pair: one closed curve and a branch point; parametric
     * self-intersection: two open curves with both preimages */
    const char *examples[] = {"viviani-implicit.json", "enneper-self.json"};
    for (int e = 0; e < 2; e++) {
        traced t;
        if (trace_example(&t, dir, examples[e]) == 0) {
            check_csv(&t, examples[e]);
            check_vtk(&t, examples[e]);
            check_obj(&t, examples[e]);
            if (e == 0)
                check_write_failure(&t);
        }
        release(&t);
    }
    return harness_finish("test_writers");
}

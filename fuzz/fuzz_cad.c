/* libFuzzer target: the CAD reader (src/cad/cad.h) on arbitrary bytes, as
 * STEP or IGES, whichever they look like. The input is handed over in a
 * buffer of exactly its size, so a read past the end is caught. A listing
 * must succeed or fail with a status and a message; every surface listed as
 * readable must be a consistent description (the rules below), read alone
 * by its entity number to the same result, and every one listed as not
 * readable must say why. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cad/cad.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_error(ic_status st, const ic_error *err)
{
    if (st == IC_OK || err->code != st || err->message[0] == '\0')
        abort();
}

static void check_unit_vector(const double v[3])
{
    const double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(fabs(len - 1) < 1e-9))
        abort();
}

/* A NURBS patch: degrees, counts, nondecreasing knots, positive weights,
 * finite points, the domain within the knots. */
static void check_nurbs(const ic_cad_surface *s)
{
    const ic_nurbs *n = &s->nurbs;
    for (int d = 0; d < 2; d++) {
        if (n->degree[d] < 1 || n->degree[d] > IC_NURBS_MAX_DEGREE || n->count[d] <= n->degree[d])
            abort();
        for (int k = 1; k < n->count[d] + n->degree[d] + 1; k++)
            if (!(n->knots[d][k] >= n->knots[d][k - 1]))
                abort();
        if (!(s->domain[d][0] >= n->knots[d][n->degree[d]] &&
              s->domain[d][1] <= n->knots[d][n->count[d]] && s->domain[d][0] < s->domain[d][1]))
            abort();
    }
    const size_t np = (size_t)n->count[0] * (size_t)n->count[1];
    for (size_t k = 0; k < 3 * np; k++)
        if (!isfinite(n->points[k]))
            abort();
    for (size_t k = 0; n->weights && k < np; k++)
        if (!(n->weights[k] > 0))
            abort();
}

static void check_surface(const ic_cad_surface *s)
{
    if (!s->supported) {
        if (s->problem[0] == '\0')
            abort();
        return;
    }
    if (s->is_nurbs) {
        check_nurbs(s);
        return;
    }
    check_unit_vector(s->prim.axis);
    check_unit_vector(s->prim.ref_direction);
    for (int d = 0; d < 2; d++)
        if (!(s->domain[d][0] < s->domain[d][1]))
            abort();
}

static void check_read_alone(const char *text, size_t size, const ic_cad_surface *s)
{
    ic_cad_surface one;
    ic_error err;
    const ic_status st = ic_cad_read_buffer(text, size, IC_CAD_ANY, s->entity, &one, &err);
    if ((st == IC_OK) != s->supported)
        abort();
    if (st != IC_OK)
        check_error(st, &err);
    else if (one.is_nurbs != s->is_nurbs || strcmp(one.type, s->type) != 0)
        abort();
    ic_cad_surface_clear(&one);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size ? size : 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    ic_cad_surface *list = NULL;
    int n = 0;
    ic_error err;
    const ic_status st = ic_cad_list_buffer(text, size, IC_CAD_ANY, &list, &n, NULL, &err);
    if (st != IC_OK) {
        check_error(st, &err);
        if (list || n)
            abort();
    }
    for (int k = 0; k < n && k < 8; k++) { /* a few read alone: each is a whole parse */
        check_surface(&list[k]);
        check_read_alone(text, size, &list[k]);
    }
    for (int k = 8; k < n; k++)
        check_surface(&list[k]);
    ic_cad_list_free(list, n);
    free(text);
    return 0;
}

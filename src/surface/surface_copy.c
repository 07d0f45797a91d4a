/*
 * A surface's copy for another thread (trace/workers.c). Evaluating a
 * surface writes its workspaces and makes its jet spaces on first use, so
 * one surface must not be evaluated by two threads at once; a copy has the
 * same formula, primitive or NURBS patch (copied, so that each owns what it
 * frees) and workspaces of its own, and evaluates bit for bit as the
 * original does.
 */
#include "surface_copy.h"
#include "expr/expr_access.h"
#include "surface_internal.h"

#include <stdlib.h>
#include <string.h>

ic_status ic_surface_copy(ic_surface **out, const ic_surface *s, ic_error *err)
{
    *out = NULL;
    if (s->backend == BACKEND_CALLBACK) /* the caller's code may not be reentrant */
        return ic_error_set(err, IC_ERR_UNABLE, 0, "a callback surface is not copied");
    ic_surface *c = calloc(1, sizeof *c);
    if (!c)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory copying a surface");
    *c = *s;
    /* nothing of the original's own memory: made anew below */
    c->expr = NULL;
    c->nurbs = NULL;
    /* a NURBS patch's recognised shape is the original's (freed with it):
     * the copy recognises its own patch again should it be asked */
    c->net_shape = NULL;
    c->net_tried = 0;
    memset(c->spaces, 0, sizeof c->spaces);
    memset(c->plane_spaces, 0, sizeof c->plane_spaces);
    memset(c->work, 0, sizeof c->work);
    memset(c->work_len, 0, sizeof c->work_len);
    ic_status st = IC_OK;
    if (s->expr)
        st = ic_expr_copy(&c->expr, s->expr, err);
    if (st == IC_OK && s->nurbs)
        st = ic_nurbs_patch_copy(&c->nurbs, s->nurbs, err);
    if (st != IC_OK) {
        ic_surface_free(c);
        return st;
    }
    st = ic_surface_reserve(c, err); /* frees c when it fails */
    if (st == IC_OK)
        *out = c;
    return st;
}

/*
** The scopes of the vector writers (render/backends/backend.h,
** cf__scopes_t): the SVG writer's groups and the PDF writer's q/Q, and
** the first fault either meets.
*/
#include <math.h>
#include <stdio.h>

#include "backend.h"

void
cf__scopes_fault(cf__scopes_t *s, cf__svgw_fault_kind_t k, double v)
{
    s->bad = true;
    if (s->fault != CF__SVGW_FAULT_NONE)
        return;
    s->fault = k;
    s->bad_value = v;
    for (int d = s->depth; d-- > 0;)
        if (s->stack[d].name != NULL) {
            s->bad_name = s->stack[d].name;
            s->bad_index = s->stack[d].index;
            break;
        }
}

bool
cf__scopes_push(cf__scopes_t *s, bool group, bool opened, const char *name,
                size_t index)
{
    if (s->depth >= CF__SVGW_DEPTH) {
        cf__scopes_fault(s, CF__SVGW_FAULT_DEPTH, 0);
        return false;
    }
    s->stack[s->depth].group = group;
    s->stack[s->depth].opened = opened;
    s->stack[s->depth].name = group ? name : NULL;
    s->stack[s->depth].index = index;
    s->depth++;
    return true;
}

void
cf__scopes_end_group(cf__scopes_t *s, int floor, void (*pop)(void *w),
                     void *w)
{
    while (s->depth > floor) {
        bool g = s->stack[s->depth - 1].group;
        pop(w);
        if (g)
            break;
    }
}

cf_status_t
cf__scopes_diag(const cf__scopes_t *s, const char *format, const char *what,
                cf_diag_t *diag)
{
    char where[96] = "";
    switch (s->fault) {
    case CF__SVGW_FAULT_NUMBER:
        if (s->bad_name != NULL)
            snprintf(where, sizeof where, " of %.40s %zu", s->bad_name,
                     s->bad_index + 1);
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG,
                           s->bad_name != NULL ? (long)s->bad_index : -1,
                           "%s: a coordinate%s is %g, %s; %s holds numbers "
                           "within 1e9 bp", what, where, s->bad_value,
                           isfinite(s->bad_value) ? "too far from the page"
                                                  : "not a finite number",
                           format);
    case CF__SVGW_FAULT_GLYPHS:
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "%s: the outlines of a label's glyphs could not "
                           "be made (out of memory, or the font failed)",
                           what);
    case CF__SVGW_FAULT_DEPTH:
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s: groups nested deeper than %d", what,
                           CF__SVGW_DEPTH);
    case CF__SVGW_FAULT_NONE:
        break;
    }
    return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1, "out of memory writing "
                       "%s", what);
}

/*
** The pieces the label parser (render/labels/label-parse.c) and its
** constructions (render/labels/label-build.c) lay out with: errors, the extents
** of a piece, moves, rules, script fonts.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "label-impl.h"

cf_status_t
cf__lp_error(parser_t *p, size_t at, const char *what)
{
    char ex[80];
    if (p->st == CF_STATUS_OK) {
        cf__label_excerpt(p->s, p->len, at, ex, sizeof ex);
        p->st = cf_diag_set(p->diag, CF_STATUS_INVALID_ARG, (long)at,
                            "label \"%s\": %s at byte %zu", ex, what, at);
    }
    return p->st;
}

cf_status_t
cf__lp_nomem(parser_t *p)
{
    char ex[80];
    if (p->st == CF_STATUS_OK) {
        cf__label_excerpt(p->s, p->len, 0, ex, sizeof ex);
        p->st = cf_diag_set(p->diag, CF_STATUS_NO_MEMORY, -1,
                            "label \"%s\": out of memory", ex);
    }
    return p->st;
}

void
cf__lp_piece_init(piece_t *pc, cf_label_t *lab, double x)
{
    pc->first = pc->end = lab->count;
    pc->x0 = pc->x1 = x;
    pc->top = -INFINITY;
    pc->bottom = -INFINITY;
    pc->cls = CLS_NONE;
    pc->group = false;
    pc->ic = 0;
}

/* Recompute top/bottom of a piece from its runs. */
void
cf__lp_piece_ink(cf_label_t *lab, piece_t *pc, double y)
{
    size_t i;
    pc->top = -INFINITY;
    pc->bottom = -INFINITY;
    for (i = pc->first; i < pc->end; i++) {
        run_t *r = &lab->runs[i];
        if (r->ink[3] <= r->ink[1])
            continue;
        pc->top = fmax(pc->top, (r->y - y) - r->ink[1]);
        pc->bottom = fmax(pc->bottom, r->ink[3] - (r->y - y));
    }
    if (pc->top == -INFINITY)
        pc->top = pc->bottom = 0;
}

void
cf__lp_script_font(const font_t *f, font_t *out, cf_label_kind_t kind,
                   double base)
{
    *out = *f;
    out->level = f->level + 1;
    out->kind = kind;
    out->size = base * (out->level == 1 ? SCRIPT_RATIO : SCRIPT2_RATIO);
    if (out->level > 2)
        out->size = base * SCRIPT2_RATIO;
    out->text = false;
}

/* Move runs [first, end) by (dx, dy). */
void
cf__lp_move(cf_label_t *lab, size_t first, size_t end, double dx,
            double dy)
{
    size_t i;
    for (i = first; i < end; i++) {
        lab->runs[i].x += dx;
        lab->runs[i].y += dy;
    }
}

/* A rule of thickness th and width w, its bottom at (x, y), as a run
** without text; false when out of memory. */
bool
cf__lp_rule(parser_t *p, const font_t *f, double x, double y, double w,
         double th)
{
    run_t *r;
    if (isnan(cf__label_put_text(p->lab, f, x, y, "", 0))) {
        cf__lp_nomem(p);
        return false;
    }
    r = &p->lab->runs[p->lab->count - 1];
    r->rule_h = th;
    r->width = w;
    r->ascent = th;
    r->descent = 0;
    r->ink[0] = 0;
    r->ink[1] = -th;
    r->ink[2] = w;
    r->ink[3] = 0;
    p->lab->merge_ok = false;
    return true;
}

/* The group of pc (from run first) with what was put over it: one
** ordinary atom. */
void
cf__lp_over_group(cf_label_t *lab, piece_t *pc, size_t first, double y)
{
    pc->first = first;
    pc->end = lab->count;
    pc->cls = CLS_ORD;
    pc->group = true;
    pc->ic = 0;   /* a group has no italic correction (a single char has) */
    cf__lp_piece_ink(lab, pc, y);
}

/*
** The seam (render/backends/backend.h): a display list handed to a backend,
** one operation after the other, and the knockouts of label halos on a
** transparent page.
*/
#include "curvefig/core.h"
#include "backend.h"
#include "overlay-spec.h"

/* Which ops a pass draws: all; all but the knockout labels; or the
** knockout labels alone (with every group and clip, none of the ink). */
typedef enum pass { PASS_ALL, PASS_INK, PASS_KNOCKOUTS } pass_t;

/* The state of a play: the step, whether the page is transparent, and
** which open groups carry an overlay (bit d: the group at depth d). */
typedef struct play {
    unsigned step;
    bool transparent;
    unsigned long long overlay_bits;
    int depth;
} play_t;

/* A label with a halo (in the page's background colour) on a transparent
** page, on every page it is drawn on: its halo knocks out the ink under it.
** On one page of every step (step 0: PGF) a label that an
** overlay shows on some steps only is no knockout: the ink would be
** missing on the others. */
static bool
is_knockout(const play_t *pl, const cf__op_t *op)
{
    return op->kind == CF__OP_TEXT && pl->transparent
        && op->u.text.halo > 0
        && !(pl->step == 0 && pl->overlay_bits != 0);
}

static void
enter(play_t *pl, const cf__op_t *op)
{
    if (pl->depth < 64 && op->u.group.overlay != NULL)
        pl->overlay_bits |= 1ull << pl->depth;
    pl->depth++;
}

static void
leave(play_t *pl)
{
    if (pl->depth > 0 && --pl->depth < 64)
        pl->overlay_bits &= ~(1ull << pl->depth);
}

static void
draw_text(const play_t *pl, const cf__op_t *op, const cf__backend_t *be,
          void *ctx, pass_t pass)
{
    cf__text_op_t t = op->u.text;
    bool ko = is_knockout(pl, op);
    if (pass != PASS_ALL && (pass == PASS_KNOCKOUTS) != ko)
        return;
    /* a halo on a transparent page paints nothing: it is a knockout, or
    ** (no knockouts drawn) left out */
    if (pl->transparent)
        t.halo = 0;
    be->draw_text(ctx, &t);
}

/* A marker: whole to a backend that takes it so (the dump), else as the
** path and paint of render/dlist/marker.c. */
static void
draw_marker(const cf__op_t *op, const cf__backend_t *be, void *ctx)
{
    cf__marker_shape_t sh;
    cf__paint_t paint;
    if (be->draw_marker != NULL)
        be->draw_marker(ctx, &op->u.marker);
    else if (cf__marker_paint(&op->u.marker, &sh, &paint))
        be->draw_path(ctx, &sh.path, &paint);
}

/* A mesh: whole to a backend that draws mesh gradients, else each
** triangle's flat pieces as paths. */
static void
draw_mesh(const cf__dl_t *dl, const cf__op_t *op, const cf__backend_t *be,
          void *ctx)
{
    size_t n;
    const cf__mesh_tri_t *t = cf__dl_op_mesh(dl, op, &n);
    if (be->draw_mesh != NULL) {
        be->draw_mesh(ctx, t, n);
        return;
    }
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 4; k++) {
            unsigned char segs[4];
            double q[6], coords[6];
            cf__path_t path;
            cf__paint_t paint;
            cf__mesh_piece(&t[i], k, q);
            if (cf__flat_triangle(q, t[i].piece[k], 1.0, segs, coords, &path,
                                  &paint))
                be->draw_path(ctx, &path, &paint);
        }
}

static void
play_pass(const cf__dl_t *dl, size_t from, size_t to,
          const cf__backend_t *be, void *ctx, pass_t pass, play_t *pl)
{
    size_t i;
    for (i = from; i < to && i < dl->count; i++) {
        const cf__op_t *op = &dl->ops[i];
        cf__path_t path;
        switch (op->kind) {
        case CF__OP_GROUP:
            enter(pl, op);
            be->begin_group(ctx, op->u.group.name, op->u.group.index,
                           op->u.group.overlay);
            break;
        case CF__OP_END:
            leave(pl);
            be->end_group(ctx);
            break;
        case CF__OP_CLIP:
            be->clip(ctx, op->u.clip.has_rect, op->u.clip.rect);
            break;
        case CF__OP_UNCLIP:
            be->unclip(ctx);
            break;
        case CF__OP_PATH:
            if (pass == PASS_KNOCKOUTS)
                break;
            cf__dl_op_path(dl, op, &path);
            be->draw_path(ctx, &path, &op->u.path.paint);
            break;
        case CF__OP_MARKER:
            if (pass != PASS_KNOCKOUTS)
                draw_marker(op, be, ctx);
            break;
        case CF__OP_MESH:
            if (pass != PASS_KNOCKOUTS)
                draw_mesh(dl, op, be, ctx);
            break;
        case CF__OP_TEXT:
            draw_text(pl, op, be, ctx, pass);
            break;
        }
    }
}

void
cf__dl_play(const cf__dl_t *dl, size_t from, size_t to,
            const cf__backend_t *be, void *ctx)
{
    play_t pl = { 0, false, 0, 0 };
    play_pass(dl, from, to, be, ctx, PASS_ALL, &pl);
}

int
cf__dl_play_page(const cf__dl_t *dl, const cf__page_t *page,
                 const cf__backend_t *be, void *ctx)
{
    be->begin_page(ctx, page);
    cf__dl_play_step(dl, page, 0, be, ctx);
    return be->end_page(ctx);
}

/* The end of the group that starts at op i (one past its END). */
static size_t
group_end(const cf__dl_t *dl, size_t i)
{
    size_t e = i + 1;
    int depth = 1;
    while (e < dl->count && depth > 0) {
        if (dl->ops[e].kind == CF__OP_GROUP)
            depth++;
        else if (dl->ops[e].kind == CF__OP_END)
            depth--;
        e++;
    }
    return e;
}

static bool
hidden(const cf__op_t *op, unsigned k)
{
    return k != 0 && op->kind == CF__OP_GROUP
        && !cf__overlay_visible(op->u.group.overlay, k);
}

/* The ops shown on step k, one pass: a hidden group is skipped whole. */
static void
step_pass(const cf__dl_t *dl, unsigned k, const cf__backend_t *be,
          void *ctx, pass_t pass, bool transparent)
{
    play_t pl = { k, transparent, 0, 0 };
    size_t i = 0, from = 0;
    while (i < dl->count) {
        if (!hidden(&dl->ops[i], k)) {
            i++;
            continue;
        }
        /* a hidden group: play what came before it, skip to its END */
        play_pass(dl, from, i, be, ctx, pass, &pl);
        i = from = group_end(dl, i);
    }
    play_pass(dl, from, dl->count, be, ctx, pass, &pl);
}

/* The boxes of the knockout labels shown on step k (boxes NULL: count
** them): each label's ink grown by its halo. */
static size_t
knockouts(const cf__dl_t *dl, unsigned k, double (*boxes)[4])
{
    play_t pl = { k, true, 0, 0 };
    size_t i = 0, n = 0;
    while (i < dl->count) {
        const cf__op_t *op = &dl->ops[i];
        if (hidden(op, k)) {
            i = group_end(dl, i);
            continue;
        }
        if (op->kind == CF__OP_GROUP)
            enter(&pl, op);
        else if (op->kind == CF__OP_END)
            leave(&pl);
        else if (is_knockout(&pl, op)) {
            const cf__text_op_t *t = &op->u.text;
            if (boxes != NULL) {
                boxes[n][0] = t->ox + t->ink[0] - t->halo;
                boxes[n][1] = t->oy + t->ink[1] - t->halo;
                boxes[n][2] = t->ink[2] - t->ink[0] + 2 * t->halo;
                boxes[n][3] = t->ink[3] - t->ink[1] + 2 * t->halo;
            }
            n++;
        }
        i++;
    }
    return n;
}

void
cf__dl_play_step(const cf__dl_t *dl, const cf__page_t *page, unsigned k,
                 const cf__backend_t *be, void *ctx)
{
    bool transparent = page != NULL && !(page->background.a > 0);
    size_t n = transparent && be->knockout != NULL ? knockouts(dl, k, NULL)
                                                   : 0;
    double (*boxes)[4] = n > 0 ? cf_alloc_array(n, sizeof *boxes) : NULL;
    if (boxes == NULL) {
        /* none (or no memory for them: the labels are drawn without
        ** their halos) */
        step_pass(dl, k, be, ctx, PASS_ALL, transparent);
        return;
    }
    knockouts(dl, k, boxes);
    be->knockout(ctx, (const double (*)[4])boxes, n);
    step_pass(dl, k, be, ctx, PASS_INK, transparent);
    be->unclip(ctx);
    step_pass(dl, k, be, ctx, PASS_KNOCKOUTS, transparent);
    cf_free(boxes);
}

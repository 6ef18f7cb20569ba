/*
** The seam (render/backend.h): a display list handed to a backend, one
** operation after the other.
*/
#include "backend.h"
#include "overlay-spec.h"

void
cf__dl_play(const cf__dl_t *dl, size_t from, size_t to,
            const cf__backend_t *be, void *ctx)
{
    size_t i;
    for (i = from; i < to && i < dl->count; i++) {
        const cf__op_t *op = &dl->ops[i];
        cf__path_t path;
        switch (op->kind) {
        case CF__OP_GROUP:
            be->begin_group(ctx, op->u.group.name, op->u.group.index,
                           op->u.group.overlay);
            break;
        case CF__OP_END:
            be->end_group(ctx);
            break;
        case CF__OP_CLIP:
            be->clip(ctx, op->u.clip.has_rect, op->u.clip.rect);
            break;
        case CF__OP_UNCLIP:
            be->unclip(ctx);
            break;
        case CF__OP_PATH:
            cf__dl_op_path(dl, op, &path);
            be->draw_path(ctx, &path, &op->u.path.paint);
            break;
        case CF__OP_MARKER:
            be->draw_marker(ctx, &op->u.marker);
            break;
        case CF__OP_TEXT:
            be->draw_text(ctx, &op->u.text);
            break;
        }
    }
}

int
cf__dl_play_page(const cf__dl_t *dl, const cf__page_t *page,
                 const cf__backend_t *be, void *ctx)
{
    be->begin_page(ctx, page);
    cf__dl_play(dl, 0, dl->count, be, ctx);
    return be->end_page(ctx);
}

void
cf__dl_play_step(const cf__dl_t *dl, unsigned k, const cf__backend_t *be,
                 void *ctx)
{
    size_t i = 0, from = 0;
    if (k == 0) {
        cf__dl_play(dl, 0, dl->count, be, ctx);
        return;
    }
    while (i < dl->count) {
        const cf__op_t *op = &dl->ops[i];
        size_t e = i + 1;
        int depth = 1;
        if (op->kind != CF__OP_GROUP
            || cf__overlay_visible(op->u.group.overlay, k)) {
            i++;
            continue;
        }
        /* a hidden group: play what came before it, skip to its END */
        cf__dl_play(dl, from, i, be, ctx);
        while (e < dl->count && depth > 0) {
            if (dl->ops[e].kind == CF__OP_GROUP)
                depth++;
            else if (dl->ops[e].kind == CF__OP_END)
                depth--;
            e++;
        }
        i = from = e;
    }
    cf__dl_play(dl, from, dl->count, be, ctx);
}

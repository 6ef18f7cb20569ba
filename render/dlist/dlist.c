/*
** The display list (render/dlist/dlist.h): growable arrays of operations, path
** segments and their numbers.  An allocation failure sets dl->failed and
** makes later appends do nothing; the writer checks it once at the end.
*/
#include <math.h>
#include <string.h>

#include "dlist.h"
#include "grow.h"

static bool
grow(cf__dl_t *dl, void **arr, size_t *cap, size_t need, size_t elsize)
{
    void *p;
    if (dl->failed)
        return false;
    if (need <= *cap)
        return true;
    p = cf__grow_array(*arr, cap, need, elsize, 64);
    if (p == NULL) {
        dl->failed = true;
        return false;
    }
    *arr = p;
    return true;
}

void
cf__dl_init(cf__dl_t *dl)
{
    memset(dl, 0, sizeof *dl);
}

void
cf__dl_free(cf__dl_t *dl)
{
    cf_free(dl->ops);
    cf_free(dl->segs);
    cf_free(dl->coords);
    cf_free(dl->tris);
    cf__dl_init(dl);
}

void
cf__dl_reset(cf__dl_t *dl)
{
    dl->count = dl->nsegs = dl->ncoords = dl->ntris = 0;
    dl->path_seg0 = dl->path_coord0 = 0;
}

static cf__op_t *
push_op(cf__dl_t *dl, cf__op_kind_t kind)
{
    cf__op_t *op;
    if (!grow(dl, (void **)&dl->ops, &dl->cap, dl->count + 1, sizeof *op))
        return NULL;
    op = &dl->ops[dl->count++];
    memset(op, 0, sizeof *op);
    op->kind = kind;
    return op;
}

/* Whether the n numbers at v are finite; *bad the first that is not. */
static bool
all_finite(const double *v, size_t n, double *bad)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) {
            *bad = v[i];
            return false;
        }
    return true;
}

bool
cf__dl_finite_from(const cf__dl_t *dl, size_t op0, size_t coord0,
                   size_t tri0, double *bad)
{
    size_t i;
    /* (no coordinates yet: coords may be NULL, which takes no offset) */
    if (dl->ncoords > coord0
        && !all_finite(dl->coords + coord0, dl->ncoords - coord0, bad))
        return false;
    for (i = tri0; i < dl->ntris; i++)
        if (!all_finite(dl->tris[i].p, 6, bad))
            return false;
    for (i = op0; i < dl->count; i++) {
        const cf__op_t *op = &dl->ops[i];
        double v[4];
        if (op->kind == CF__OP_CLIP && op->u.clip.has_rect
            && !all_finite(op->u.clip.rect, 4, bad))
            return false;
        if (op->kind == CF__OP_MARKER) {
            v[0] = op->u.marker.x;
            v[1] = op->u.marker.y;
            if (!all_finite(v, 2, bad))
                return false;
        }
        if (op->kind == CF__OP_TEXT) {
            v[0] = op->u.text.ox;
            v[1] = op->u.text.oy;
            v[2] = op->u.text.px;
            v[3] = op->u.text.py;
            if (!all_finite(v, 4, bad))
                return false;
        }
    }
    return true;
}

void
cf__dl_group(cf__dl_t *dl, const char *name, size_t index)
{
    cf__op_t *op = push_op(dl, CF__OP_GROUP);
    if (op != NULL) {
        op->u.group.name = name;
        op->u.group.index = index;
        op->u.group.overlay = NULL;
        op->u.group.line = 0;
    }
}

void
cf__dl_end(cf__dl_t *dl)
{
    push_op(dl, CF__OP_END);
}

void
cf__dl_clip(cf__dl_t *dl, const double *rect)
{
    cf__op_t *op = push_op(dl, CF__OP_CLIP);
    if (op != NULL && rect != NULL) {
        op->u.clip.has_rect = true;
        memcpy(op->u.clip.rect, rect, sizeof op->u.clip.rect);
    }
}

void
cf__dl_unclip(cf__dl_t *dl)
{
    push_op(dl, CF__OP_UNCLIP);
}

/* ---- paths -------------------------------------------------------------- */

void
cf__dl_path_begin(cf__dl_t *dl)
{
    dl->path_seg0 = dl->nsegs;
    dl->path_coord0 = dl->ncoords;
}

static void
seg(cf__dl_t *dl, cf__seg_t kind, const double *v, size_t n)
{
    if (!grow(dl, (void **)&dl->segs, &dl->segcap, dl->nsegs + 1, 1)
        || !grow(dl, (void **)&dl->coords, &dl->coordcap, dl->ncoords + n,
                 sizeof *dl->coords))
        return;
    dl->segs[dl->nsegs++] = (unsigned char)kind;
    if (n > 0)
        memcpy(dl->coords + dl->ncoords, v, n * sizeof *v);
    dl->ncoords += n;
}

void
cf__dl_move(cf__dl_t *dl, double x, double y)
{
    double v[2] = { x, y };
    seg(dl, CF__SEG_MOVE, v, 2);
}

void
cf__dl_line(cf__dl_t *dl, double x, double y)
{
    double v[2] = { x, y };
    seg(dl, CF__SEG_LINE, v, 2);
}

void
cf__dl_curve(cf__dl_t *dl, double x1, double y1, double x2, double y2,
             double x3, double y3)
{
    double v[6] = { x1, y1, x2, y2, x3, y3 };
    seg(dl, CF__SEG_CURVE, v, 6);
}

void
cf__dl_rect(cf__dl_t *dl, double x, double y, double w, double h)
{
    double v[4] = { x, y, w, h };
    seg(dl, CF__SEG_RECT, v, 4);
}

void
cf__dl_arc(cf__dl_t *dl, double cx, double cy, double r, double a0,
           double a1)
{
    double v[5] = { cx, cy, r, a0, a1 };
    seg(dl, CF__SEG_ARC, v, 5);
}

void
cf__dl_close(cf__dl_t *dl)
{
    seg(dl, CF__SEG_CLOSE, NULL, 0);
}

void
cf__dl_path_paint(cf__dl_t *dl, const cf__paint_t *paint)
{
    cf__op_t *op;
    if (paint == NULL || (!paint->fill && !paint->stroke)
        || dl->nsegs == dl->path_seg0) {
        /* nothing drawn: forget the segments */
        dl->nsegs = dl->path_seg0;
        dl->ncoords = dl->path_coord0;
        return;
    }
    op = push_op(dl, CF__OP_PATH);
    if (op == NULL)
        return;
    op->u.path.seg0 = dl->path_seg0;
    op->u.path.nsegs = dl->nsegs - dl->path_seg0;
    op->u.path.coord0 = dl->path_coord0;
    op->u.path.paint = *paint;
    dl->path_seg0 = dl->nsegs;
    dl->path_coord0 = dl->ncoords;
}

void
cf__dl_op_path(const cf__dl_t *dl, const cf__op_t *op, cf__path_t *out)
{
    out->segs = dl->segs + op->u.path.seg0;
    out->coords = dl->coords + op->u.path.coord0;
    out->nsegs = op->u.path.nsegs;
}

/* ---- markers and text --------------------------------------------------- */

void
cf__dl_marker(cf__dl_t *dl, const cf__marker_op_t *m)
{
    cf__op_t *op;
    if (m->marker == CF_MARKER_NONE || !(0.5 * m->size > 0))
        return;
    op = push_op(dl, CF__OP_MARKER);
    if (op != NULL)
        op->u.marker = *m;
}

void
cf__dl_text(cf__dl_t *dl, const cf__text_op_t *t)
{
    cf__op_t *op = push_op(dl, CF__OP_TEXT);
    if (op != NULL)
        op->u.text = *t;
}

/* ---- meshes ------------------------------------------------------------- */

void
cf__dl_mesh_tri(cf__dl_t *dl, const cf__mesh_tri_t *t)
{
    cf__op_t *op = dl->count > 0 ? &dl->ops[dl->count - 1] : NULL;
    if (!grow(dl, (void **)&dl->tris, &dl->tricap, dl->ntris + 1,
              sizeof *dl->tris))
        return;
    if (op == NULL || op->kind != CF__OP_MESH
        || op->u.mesh.tri0 + op->u.mesh.ntri != dl->ntris) {
        op = push_op(dl, CF__OP_MESH);
        if (op == NULL)
            return;
        op->u.mesh.tri0 = dl->ntris;
    }
    dl->tris[dl->ntris++] = *t;
    op->u.mesh.ntri++;
}

const cf__mesh_tri_t *
cf__dl_op_mesh(const cf__dl_t *dl, const cf__op_t *op, size_t *n)
{
    *n = op->u.mesh.ntri;
    return dl->tris + op->u.mesh.tri0;
}

/* ---- from styles -------------------------------------------------------- */

void
cf__stroke_from_style(const cf_style_t *s, cf__stroke_t *out)
{
    memset(out, 0, sizeof *out);
    out->color = s->color;
    out->opacity = s->opacity;
    out->width = s->width;
    out->join = CF__JOIN_ROUND;
    out->cap = s->dash_count > 0 ? CF__CAP_BUTT : CF__CAP_ROUND;
    out->dash_count = s->dash_count;
    if (s->dash_count > 0)
        memcpy(out->dash, s->dash, s->dash_count * sizeof *s->dash);
}

void
cf__marker_from_style(const cf_style_t *s, cf_marker_t marker, double x,
                      double y, const double *dir, cf__marker_op_t *out)
{
    memset(out, 0, sizeof *out);
    out->marker = marker;
    out->x = x;
    out->y = y;
    out->has_dir = dir != NULL;
    if (dir != NULL) {
        out->dir[0] = dir[0];
        out->dir[1] = dir[1];
    }
    out->size = s->marker_size;
    out->width = s->width;
    out->color = s->marker_color;
    out->fill = s->fill;
    out->opacity = s->opacity;
}

/* ---- moving ------------------------------------------------------------- */

/* The numbers of a segment kind, and how many of them from the first are
** (x, y) pairs that move (the rest: sizes, radius, angles). */
static void
seg_numbers(unsigned char kind, size_t *n, size_t *moved)
{
    static const unsigned char count[] = { 2, 2, 6, 4, 5, 0 };
    static const unsigned char pairs[] = { 2, 2, 6, 2, 2, 0 };
    *n = kind < sizeof count ? count[kind] : 0;
    *moved = kind < sizeof pairs ? pairs[kind] : 0;
}

static void
append_path(cf__dl_t *dst, const cf__dl_t *src, const cf__op_t *op,
            double dx, double dy)
{
    cf__path_t p;
    size_t i, c = 0;
    cf__dl_op_path(src, op, &p);
    cf__dl_path_begin(dst);
    for (i = 0; i < p.nsegs; i++) {
        double v[6];
        size_t n, moved, j;
        seg_numbers(p.segs[i], &n, &moved);
        for (j = 0; j < n; j++)
            v[j] = p.coords[c + j] + (j < moved ? (j % 2 ? dy : dx) : 0);
        seg(dst, (cf__seg_t)p.segs[i], v, n);
        c += n;
    }
    cf__dl_path_paint(dst, &op->u.path.paint);
}

void
cf__dl_append_moved(cf__dl_t *dst, const cf__dl_t *src, double dx,
                    double dy)
{
    size_t i;
    if (src->failed)
        dst->failed = true;
    for (i = 0; i < src->count; i++) {
        const cf__op_t *op = &src->ops[i];
        cf__op_t *o;
        if (op->kind == CF__OP_PATH) {
            append_path(dst, src, op, dx, dy);
            continue;
        }
        if (op->kind == CF__OP_MESH) {
            size_t n;
            const cf__mesh_tri_t *t = cf__dl_op_mesh(src, op, &n);
            /* (after a mesh in dst it joins that one: the same paint) */
            for (size_t k = 0; k < n; k++) {
                cf__mesh_tri_t m = t[k];
                for (int c = 0; c < 3; c++) {
                    m.p[2 * c] += dx;
                    m.p[2 * c + 1] += dy;
                }
                cf__dl_mesh_tri(dst, &m);
            }
            continue;
        }
        o = push_op(dst, op->kind);
        if (o == NULL)
            return;
        *o = *op;
        if (op->kind == CF__OP_CLIP) {
            o->u.clip.rect[0] += dx;
            o->u.clip.rect[1] += dy;
        } else if (op->kind == CF__OP_MARKER) {
            o->u.marker.x += dx;
            o->u.marker.y += dy;
        } else if (op->kind == CF__OP_TEXT) {
            o->u.text.px += dx;
            o->u.text.py += dy;
            o->u.text.ox += dx;
            o->u.text.oy += dy;
        }
    }
}

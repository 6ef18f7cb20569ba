/*
** A shaped run's glyphs with cairo (render/backends/font-glyphs.h): the
** one place that turns the fonts' description of a run (render/labels/
** font.h) into cairo calls, whether pango or HarfBuzz shaped it.  The
** drawing repeats what pango's cairo renderer does for a one-line layout
** (pango 1.50, pangocairo-render.c), so that the calls, and so the bytes
** of every output, are the same: the current point read back from cairo
** (its 24.8 fixed point rounds it), each span drawn inside cairo_save and
** cairo_restore with its scaled font, its glyphs at base + offset / 1024
** in doubles, cairo_show_text_glyphs with the span's text and clusters
** where the surface keeps text (PDF), and the current point restored.
*/
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "font-glyphs.h"
#include "font-outlines.h"
#include "grow.h"

#define STACK_GLYPHS 64

static bool
drawn(unsigned id)
{
    return id != CF__FONT_GLYPH_EMPTY && !(id & CF__FONT_GLYPH_UNKNOWN);
}

/* The clusters of span s for cairo_show_text_glyphs, in the order of its
** text (pango's glyph item iterator): consecutive glyphs of one cluster
** value, the bytes up to the next cluster's, empty and unknown glyphs
** not counted.  The number of clusters. */
static int
span_clusters(const cf__font_glyphs_t *g, const cf__font_span_t *s,
              cairo_text_cluster_t *out)
{
    const cf__font_glyph_t *gl = g->glyphs + s->glyph;
    int n = (int)s->nglyphs, k = 0, i, step = s->backward ? -1 : 1;
    int start = s->backward ? n - 1 : 0;
    unsigned start_byte = 0;
    for (i = start; i >= 0 && i < n;) {
        unsigned c = gl[i].cluster, end_byte;
        int j = i, count = 0;
        while (j >= 0 && j < n && gl[j].cluster <= c) {
            if (drawn(gl[j].id))
                count++;
            j += step;
        }
        end_byte = j >= 0 && j < n ? gl[j].cluster : (unsigned)s->nbytes;
        out[k].num_bytes = (int)(end_byte - start_byte);
        out[k].num_glyphs = count;
        k++;
        start_byte = end_byte;
        i = j;
    }
    return k;
}

cairo_scaled_font_t *
cf__font_face_scaled(const cf__font_face_t *face)
{
    /* a face that makes its scaled font at need sets it under its lock:
    ** asked through that lock, never read here */
    if (face->make_scaled != NULL)
        return face->make_scaled(face);
    return face->scaled;
}

/* The span's glyphs' paths from the face's file, at the glyph origins
** cairo_glyph_path would take (each 24.8, rounded as cairo rounds): true
** when the face and every glyph were read (cr's path then holds them). */
static bool
own_span_path(cairo_t *cr, const cf__font_glyphs_t *g,
              const cf__font_span_t *s, double base_x, double base_y)
{
    size_t i;
    int x_position = 0;
    if (!cf__own_face(s->face) || !cf__own_identity(cr))
        return false;
    for (i = 0; i < s->nglyphs; i++) {
        const cf__font_glyph_t *gi = &g->glyphs[s->glyph + i];
        if (drawn(gi->id)) {
            double x = base_x + (double)(x_position + gi->x)
                                    / CF__FONT_SCALE;
            double y = gi->y == 0 ? base_y
                                  : base_y + (double)gi->y / CF__FONT_SCALE;
            if (cf__own_glyph_path(cr, s->face, gi->id, cf__own_fixed(x),
                                   cf__own_fixed(y)) != 0)
                return false;
        }
        x_position += gi->width;
    }
    return true;
}

/* Whether every glyph of the span reads from the face's file (checked
** before any is appended, so that a refusal leaves cr's path as it was). */
static bool
own_span_ok(const cf__font_glyphs_t *g, const cf__font_span_t *s)
{
    cairo_text_extents_t e;
    size_t i;
    for (i = 0; i < s->nglyphs; i++) {
        unsigned id = g->glyphs[s->glyph + i].id;
        if (drawn(id) && cf__own_glyph_extents(s->face, id, &e) != 0)
            return false;
    }
    return true;
}

static void
draw_span(cairo_t *cr, const cf__font_glyphs_t *g, const cf__font_span_t *s,
          double xo, double yo, bool path, bool clusters)
{
    cairo_glyph_t stack[STACK_GLYPHS], *cg = stack;
    cairo_text_cluster_t cstack[STACK_GLYPHS], *cc = cstack;
    cairo_scaled_font_t *sf;
    double base_x = xo + (double)s->x / CF__FONT_SCALE;
    double base_y = yo + (double)(g->baseline - s->shift) / CF__FONT_SCALE;
    size_t i;
    int count = 0, x_position = 0;
    cairo_save(cr);
    if (path && cf__own_face(s->face) && cf__own_identity(cr)
        && own_span_ok(g, s) && own_span_path(cr, g, s, base_x, base_y)) {
        cairo_restore(cr);
        return;
    }
    sf = cf__font_face_scaled(s->face);
    if (sf == NULL || cairo_scaled_font_status(sf) != CAIRO_STATUS_SUCCESS)
        goto done;   /* pango draws boxes there: such runs stay pango's */
    cairo_set_scaled_font(cr, sf);
    if (!path && s->face->show_options != NULL)
        cairo_set_font_options(cr, s->face->show_options);
    if (s->nglyphs > STACK_GLYPHS) {
        cg = cf_alloc_array(s->nglyphs, sizeof *cg);
        cc = cf_alloc_array(s->nglyphs, sizeof *cc);
        if (cg == NULL || cc == NULL)
            goto done;
    }
    for (i = 0; i < s->nglyphs; i++) {
        const cf__font_glyph_t *gi = &g->glyphs[s->glyph + i];
        if (drawn(gi->id)) {
            cg[count].index = gi->id;
            cg[count].x = base_x + (double)(x_position + gi->x)
                                       / CF__FONT_SCALE;
            cg[count].y = gi->y == 0 ? base_y
                                     : base_y + (double)gi->y
                                                    / CF__FONT_SCALE;
            count++;
        }
        x_position += gi->width;
    }
    if (path)
        cairo_glyph_path(cr, cg, count);
    else if (clusters)
        cairo_show_text_glyphs(cr, g->text + s->byte, (int)s->nbytes, cg,
                               count, cc, span_clusters(g, s, cc),
                               s->backward ? CAIRO_TEXT_CLUSTER_FLAG_BACKWARD
                                           : 0);
    else
        cairo_show_glyphs(cr, cg, count);
done:
    if (cg != stack)
        cf_free(cg);
    if (cc != cstack)
        cf_free(cc);
    cairo_restore(cr);
}

void
cf__font_glyphs_draw(cairo_t *cr, const cf__font_glyphs_t *g, bool path)
{
    bool had = cairo_has_current_point(cr), clusters;
    double xo, yo;
    size_t i;
    cairo_get_current_point(cr, &xo, &yo);
    clusters = !path
               && cairo_surface_has_show_text_glyphs(cairo_get_target(cr));
    for (i = 0; i < g->nspans; i++)
        draw_span(cr, g, &g->spans[i], xo, yo, path, clusters);
    if (had)
        cairo_move_to(cr, xo, yo);
    else
        cairo_new_sub_path(cr);
}

bool
cf__font_glyphs_unknown(const cf__font_glyphs_t *g)
{
    size_t i;
    for (i = 0; i < g->nglyphs; i++)
        if (g->glyphs[i].id != CF__FONT_GLYPH_EMPTY
            && (g->glyphs[i].id & CF__FONT_GLYPH_UNKNOWN))
            return true;
    return false;
}

double
cf__font_five_digits(double v)
{
    static const double p10[] = { 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7 };
    double a = fabs(v);
    char buf[32];
    /* 1e-3 <= a < 1e4, as nearly every outline's coordinate per bp: the
    ** comparisons with 0.1 and 0.01 are exact (no double lies between
    ** 1/10 and the double 0.1) */
    if (a >= 1e-3 && a < 1e4) {
        int e = a >= 1000 ? 3 : a >= 100 ? 2 : a >= 10 ? 1 : a >= 1 ? 0
              : a >= 0.1 ? -1 : a >= 0.01 ? -2 : -3;
        double k = p10[3 - e], sc = a * k;   /* 10^(4 - e), exact */
        double half = fabs(sc - floor(sc) - 0.5);
        /* a * k is within 1e-11 of the exact product: away from a tie
        ** and from the ends of [10^4, 10^5) it rounds as the exact value
        ** does, and r / k, one rounding of two exact numbers, is the
        ** double nearest the decimal, as strtod reads it */
        if (half > 1e-6 && sc > 10000.5 && sc < 99999.4) {
            double r = nearbyint(sc) / k;
            return v < 0 ? -r : r;
        }
    }
    snprintf(buf, sizeof buf, "%.5g", v);
    return strtod(buf, NULL);
}

/* cr's path (a glyph's, at the origin) handed to f per bp of size s,
** each coordinate to five digits; cr's path emptied; 0 or -1. */
static int
hand_out(cairo_t *cr, double s, void (*f)(void *u, char op, const double *v),
         void *u)
{
    cairo_path_t *path = cairo_copy_path(cr);
    int i, rc = path->status != CAIRO_STATUS_SUCCESS ? -1 : 0;
    cairo_new_path(cr);
    for (i = 0; rc == 0 && i < path->num_data;
         i += path->data[i].header.length) {
        static const char op[] = { 'M', 'L', 'C', 'Z' };
        const cairo_path_data_t *d = &path->data[i];
        double v[6];
        int k;
        for (k = 1; k < d->header.length && k <= 3; k++) {
            v[2 * k - 2] = cf__font_five_digits(d[k].point.x / s);
            v[2 * k - 1] = cf__font_five_digits(d[k].point.y / s);
        }
        f(u, op[d->header.type], v);
    }
    cairo_path_destroy(path);
    return rc;
}

int
cf__font_glyph_outline(cairo_t *cr, cairo_scaled_font_t *sf,
                       unsigned long id,
                       void (*f)(void *u, char op, const double *v), void *u)
{
    cairo_matrix_t fm;
    cairo_glyph_t g;
    double s;
    if (sf == NULL)
        return -1;
    /* the font's own scaled font: a scaled font of the same face made at
    ** another size moved the glyph paths of this one by 1/128 bp */
    cairo_scaled_font_get_font_matrix(sf, &fm);
    s = fm.yy != 0 ? fm.yy : 1;
    g.index = id;
    g.x = g.y = 0;
    cairo_set_scaled_font(cr, sf);
    cairo_new_path(cr);
    cairo_glyph_path(cr, &g, 1);
    return hand_out(cr, s, f, u);
}

/* cf__font_glyph_outline of the face's glyph: from its font file when
** it reads (the same path: font-outlines.h), else from its scaled font. */
static int
face_glyph_outline(cairo_t *cr, const cf__font_face_t *face,
                   unsigned long id,
                   void (*f)(void *u, char op, const double *v), void *u)
{
    int rc;
    if (!cf__own_face(face) || !cf__own_identity(cr))
        return cf__font_glyph_outline(cr, cf__font_face_scaled(face), id, f,
                                      u);
    cairo_new_path(cr);
    rc = cf__own_glyph_path(cr, face, id, 0, 0);
    if (rc != 0) {
        cairo_new_path(cr);
        return rc < 0 ? -1 : cf__font_glyph_outline(
                                 cr, cf__font_face_scaled(face), id, f, u);
    }
    return hand_out(cr, face->matrix[3] != 0 ? face->matrix[3] : 1, f, u);
}

/* A glyph's outline per bp, as cf__font_glyph_outline hands it out. */
typedef struct glyph_path {
    unsigned long id;
    size_t nops;
    char *ops;
    double *v;     /* 2 * (1, 1, 3 or 0) numbers an op */
} glyph_path_t;

typedef struct outline_cache {
    pthread_mutex_t lock;
    glyph_path_t *paths;
    size_t n, cap;
} outline_cache_t;

void *
cf__font_outline_cache_new(void)
{
    outline_cache_t *c = calloc(1, sizeof *c);
    if (c != NULL)
        pthread_mutex_init(&c->lock, NULL);
    return c;
}

typedef struct path_buf {
    glyph_path_t p;
    size_t nv, cap_ops, cap_v;
    bool failed;
} path_buf_t;

static void
collect(void *u, char op, const double *v)
{
    path_buf_t *b = u;
    size_t k = op == 'C' ? 6 : op == 'Z' ? 0 : 2;
    if (b->failed)
        return;
    if (b->p.nops == b->cap_ops) {
        char *t = realloc(b->p.ops, b->cap_ops ? 2 * b->cap_ops : 64);
        b->failed = t == NULL;
        if (t == NULL)
            return;
        b->p.ops = t;
        b->cap_ops = b->cap_ops ? 2 * b->cap_ops : 64;
    }
    if (b->nv + k > b->cap_v) {
        size_t cap = b->cap_v ? 2 * b->cap_v : 256;
        double *t = realloc(b->p.v, cap * sizeof *t);
        b->failed = t == NULL;
        if (t == NULL)
            return;
        b->p.v = t;
        b->cap_v = cap;
    }
    b->p.ops[b->p.nops++] = op;
    memcpy(b->p.v + b->nv, v, k * sizeof *v);
    b->nv += k;
}

/* Hand glyph id's outline per bp to f: from the cache when the face has
** one (filling it the first time), else from cairo. */
static int
glyph_outline_cached(cairo_t *cr, const cf__font_face_t *face,
                     unsigned long id,
                     void (*f)(void *u, char op, const double *v), void *u)
{
    outline_cache_t *c = face->outlines;
    const glyph_path_t *p = NULL;
    path_buf_t b;
    size_t i, nv = 0;
    if (c == NULL)
        return face_glyph_outline(cr, face, id, f, u);
    pthread_mutex_lock(&c->lock);
    for (i = 0; i < c->n && p == NULL; i++)
        if (c->paths[i].id == id)
            p = &c->paths[i];
    if (p == NULL) {
        memset(&b, 0, sizeof b);
        b.p.id = id;
        if (face_glyph_outline(cr, face, id, collect, &b) != 0
            || b.failed) {
            free(b.p.ops);
            free(b.p.v);
            pthread_mutex_unlock(&c->lock);
            return -1;
        }
        if (c->n == c->cap) {
            size_t cap = c->cap ? 2 * c->cap : 32;
            glyph_path_t *t = realloc(c->paths, cap * sizeof *t);
            if (t == NULL) {
                free(b.p.ops);
                free(b.p.v);
                pthread_mutex_unlock(&c->lock);
                return -1;
            }
            c->paths = t;
            c->cap = cap;
        }
        c->paths[c->n] = b.p;
        p = &c->paths[c->n++];
    }
    for (i = 0; i < p->nops; i++) {
        char op = p->ops[i];
        f(u, op, p->v + nv);
        nv += op == 'C' ? 6 : op == 'Z' ? 0 : 2;
    }
    pthread_mutex_unlock(&c->lock);
    return 0;
}

typedef struct place {
    cf__pathb_t *out;
    double ox, oy, size;  /* the glyph's origin, the run's size */
} place_t;

/* A point of a glyph's outline placed as render/labels/font-table.c
** places it (the same operations, so the same doubles). */
static void
placed(void *u, char op, const double *v)
{
    const place_t *p = u;
    int n = op == 'C' ? 3 : op == 'Z' ? 0 : 1, j;
    double xy[6];
    for (j = 0; j < n; j++) {
        xy[2 * j] = p->ox + v[2 * j] * p->size;
        xy[2 * j + 1] = p->oy + v[2 * j + 1] * p->size;
    }
    cf__pathb_add(p->out, op == 'M' ? CF__SEG_MOVE : op == 'L' ? CF__SEG_LINE
                          : op == 'C' ? CF__SEG_CURVE : CF__SEG_CLOSE, xy);
}

void
cf__font_glyphs_outline(cairo_t **cr, const cf__font_glyphs_t *g, double x,
                        double y, cf__pathb_t *out)
{
    place_t p;
    size_t i, k;
    if (*cr == NULL) {
        cairo_surface_t *s = cairo_recording_surface_create(
            CAIRO_CONTENT_ALPHA, NULL);
        *cr = cairo_create(s);
        cairo_surface_destroy(s);
    }
    p.out = out;
    p.size = g->size;
    for (i = 0; i < g->nspans; i++) {
        const cf__font_span_t *s = &g->spans[i];
        int gx = s->x;
        for (k = 0; k < s->nglyphs; k++) {
            const cf__font_glyph_t *gl = &g->glyphs[s->glyph + k];
            if (drawn(gl->id)) {
                p.ox = x + (double)(gx + gl->x) / CF__FONT_SCALE;
                p.oy = y + (double)(g->baseline - s->shift + gl->y)
                           / CF__FONT_SCALE;
                if (glyph_outline_cached(*cr, s->face, gl->id, placed, &p)
                    != 0)
                    out->failed = true;
            }
            gx += gl->width;
        }
    }
}

/* *dst (capacity *cap) holding src[0..n) and a NUL; false when out of
** memory. */
static bool
copy_text(char **dst, size_t *cap, const char *src, size_t n)
{
    char *t = cf__grow_array(*dst, cap, n + 1, 1, 64);
    if (t == NULL)
        return false;
    *dst = t;
    memcpy(t, src, n);
    t[n] = '\0';
    return true;
}

void
cf__font_glyphs_reset(cf__font_glyphs_buf_t *b, const cf__font_req_t *req,
                      const cf__font_shape_t *sh)
{
    b->failed = !copy_text(&b->text, &b->cap_text, req->text, req->len)
                || !copy_text(&b->family, &b->cap_family, req->family,
                              strlen(req->family));
    memset(&b->g, 0, sizeof b->g);
    b->g.family = b->failed ? "" : b->family;
    b->g.italic = req->italic;
    b->g.bold = req->bold;
    b->g.text = b->failed ? "" : b->text;
    b->g.len = b->failed ? 0 : req->len;
    b->g.shape = *sh;
    b->g.size = req->size;
    b->g.spans = b->spans;
    b->g.glyphs = b->glyphs;
}

void
cf__font_glyphs_span(cf__font_glyphs_buf_t *b, const cf__font_face_t *face,
                     size_t byte, size_t nbytes, int x)
{
    cf__font_span_t *s = cf__grow_array(b->spans, &b->cap_spans,
                                        b->g.nspans + 1, sizeof *s, 4);
    if (s == NULL) {
        b->failed = true;
        return;
    }
    b->spans = s;
    s += b->g.nspans++;
    s->face = face;
    s->glyph = b->g.nglyphs;
    s->nglyphs = 0;
    s->byte = byte;
    s->nbytes = nbytes;
    s->x = x;
    s->shift = 0;
    s->backward = false;
    b->g.spans = b->spans;
}

void
cf__font_glyphs_add(cf__font_glyphs_buf_t *b, const cf__font_glyph_t *glyph)
{
    cf__font_glyph_t *g;
    if (b->g.nspans == 0) {
        b->failed = true;
        return;
    }
    g = cf__grow_array(b->glyphs, &b->cap_glyphs, b->g.nglyphs + 1,
                       sizeof *g, 16);
    if (g == NULL) {
        b->failed = true;
        return;
    }
    b->glyphs = g;
    g[b->g.nglyphs++] = *glyph;
    b->spans[b->g.nspans - 1].nglyphs++;
    b->g.glyphs = b->glyphs;
}

void
cf__font_glyphs_fini(cf__font_glyphs_buf_t *b)
{
    cf_free(b->spans);
    cf_free(b->glyphs);
    cf_free(b->text);
    cf_free(b->family);
    memset(b, 0, sizeof *b);
}

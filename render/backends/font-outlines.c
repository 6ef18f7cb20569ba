/*
** A native face's glyphs from its font file (render/backends/
** font-outlines.h): each face's size and shape computed once from its
** font matrix as cairo-ft computes them, its file's outlines opened once
** a file and face index (render/fontfile/outline.h, mapped for the
** process's life, in the C library's heap like the faces), and each
** glyph's outline turned into cairo's path and extents.
*/
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "font-outlines.h"
#include "outline.h"

/* A face's set-up (face->own). */
typedef struct own {
    bool ok;
    cf__olface_t *file;
    cf__olsize_t size;            /* the face's, for the paths */
    cf__olsize_t em;              /* at the em size, for the metrics */
    double em_scale;              /* cairo-ft's unscaled font's then */
    cairo_matrix_t font_matrix;
    /* the extents found, a glyph once (a label's glyphs are measured in
    ** every layout tried) */
    struct seen {
        unsigned long id;
        cairo_text_extents_t e;
    } *seen;
    size_t nseen, cap_seen;
} own_t;

/* The files' outlines, one a file and face index. */
typedef struct file_entry {
    char *path;
    unsigned index;
    cf__olface_t *face;           /* NULL: the file gives none */
} file_entry_t;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static file_entry_t *files;
static size_t nfiles, cap_files;
static own_t refused;             /* the set-up of faces not handled */

static cf__olface_t *
file_of(const char *path, unsigned index)
{
    size_t i;
    cf__olface_t *f = NULL;
    for (i = 0; i < nfiles; i++)
        if (files[i].index == index && strcmp(files[i].path, path) == 0)
            return files[i].face;
    if (nfiles == cap_files) {
        size_t cap = cap_files ? 2 * cap_files : 8;
        file_entry_t *t = realloc(files, cap * sizeof *t);
        if (t == NULL)
            return NULL;
        files = t;
        cap_files = cap;
    }
    files[nfiles].path = strdup(path);
    if (files[nfiles].path == NULL)
        return NULL;
    if (cf__olface_open(path, index, &f) != 0)
        f = NULL;
    files[nfiles].index = index;
    files[nfiles].face = f;
    nfiles++;
    return f;
}

/* cairo-ft's _compute_transform and _cairo_ft_unscaled_font_set_scale
** for the scale (the font matrix, identity CTM). */
static bool
set_up(own_t *o, const cf__font_face_t *face)
{
    cairo_matrix_t scale, normalized, ctm;
    double det, x = 1, y = 0, major, minor, xs, ys;
    int64_t m[4];
    cairo_matrix_init(&o->font_matrix, face->matrix[0], face->matrix[1],
                      face->matrix[2], face->matrix[3], 0, 0);
    cairo_matrix_init_identity(&ctm);
    cairo_matrix_multiply(&scale, &o->font_matrix, &ctm);
    det = scale.xx * scale.yy - scale.yx * scale.xy;
    if (!isfinite(det))
        return false;
    if (det == 0) {
        xs = ys = 0;
    } else {
        cairo_matrix_transform_distance(&scale, &x, &y);
        major = hypot(x, y);
        if (det < 0)
            det = -det;
        minor = major != 0 ? det / major : 0.0;
        xs = major;
        ys = minor;
    }
    if (xs < 1.0)
        xs = 1.0;
    if (ys < 1.0)
        ys = 1.0;
    normalized = scale;
    cairo_matrix_scale(&normalized, 1.0 / xs, 1.0 / ys);
    /* FreeType's matrix (y up): xx, xy, yx, yy in 16.16 */
    m[0] = (int64_t)(normalized.xx * 65536.0);
    m[1] = -(int64_t)(normalized.xy * 65536.0);
    m[2] = -(int64_t)(normalized.yx * 65536.0);
    m[3] = (int64_t)(normalized.yy * 65536.0);
    cf__olface_size(o->file, (int64_t)(xs * 64.0 + .5),
                    (int64_t)(ys * 64.0 + .5), m, &o->size);
    /* the metrics: the glyph loaded at the em size, scale(upem, upem),
    ** whose basis vectors are upem long and whose shape is the identity
    ** but for the rounding of (1 / upem) * upem */
    {
        double u = cf__olface_units_per_em(o->file);
        cairo_matrix_t em;
        cairo_matrix_init_scale(&em, u, u);
        normalized = em;
        cairo_matrix_scale(&normalized, 1.0 / u, 1.0 / u);
        m[0] = (int64_t)(normalized.xx * 65536.0);
        m[1] = -(int64_t)(normalized.xy * 65536.0);
        m[2] = -(int64_t)(normalized.yx * 65536.0);
        m[3] = (int64_t)(normalized.yy * 65536.0);
        o->em_scale = u;
        cf__olface_size(o->file, (int64_t)(u * 64.0 + .5),
                        (int64_t)(u * 64.0 + .5), m, &o->em);
    }
    return true;
}

static const own_t *
own_of(const cf__font_face_t *face)
{
    own_t *o = __atomic_load_n(&face->own, __ATOMIC_ACQUIRE);
    if (o != NULL)
        return o;
    pthread_mutex_lock(&lock);
    o = face->own;
    if (o == NULL) {
        o = &refused;
        if (face->file != NULL && face->has_matrix && !face->emboldened) {
            own_t *n = calloc(1, sizeof *n);
            if (n != NULL) {
                n->file = file_of(face->file, face->index);
                n->ok = n->file != NULL && set_up(n, face);
                if (n->ok)
                    o = n;
                else
                    free(n);
            }
        }
        /* the face is the process's (a native face): its own is set once */
        __atomic_store_n(&((cf__font_face_t *)face)->own, (void *)o,
                         __ATOMIC_RELEASE);
    }
    pthread_mutex_unlock(&lock);
    return o;
}

bool
cf__own_face(const cf__font_face_t *face)
{
    return face != NULL && face->file != NULL && own_of(face)->ok;
}

int32_t
cf__own_fixed(double v)
{
    return (int32_t)(int64_t)nearbyint(v * 256.0);
}

bool
cf__own_identity(cairo_t *cr)
{
    cairo_matrix_t m;
    double dx = 0, dy = 0, sx = 1, sy = 1;
    cairo_surface_t *s = cairo_get_target(cr);
    cairo_get_matrix(cr, &m);
    cairo_surface_get_device_offset(s, &dx, &dy);
    cairo_surface_get_device_scale(s, &sx, &sy);
    return m.xx == 1 && m.yx == 0 && m.xy == 0 && m.yy == 1 && m.x0 == 0 &&
           m.y0 == 0 && dx == 0 && dy == 0 && sx == 1 && sy == 1;
}

/* A glyph's outline at size sz (o emptied first). */
static int
load(const own_t *w, unsigned long id, const cf__olsize_t *sz,
     cf__outline_t *o)
{
    if (id > 0xffffu)
        return 1;
    return cf__olface_glyph(w->file, (unsigned)id, sz, o);
}

typedef struct emit {
    cairo_t *cr;
    int32_t ox, oy;
    int32_t cx, cy;          /* the current point, the glyph's own */
} emit_t;

static double
at(int32_t v, int32_t o)
{
    return (double)((int64_t)v + o) / 256.0;
}

static void
move_to(emit_t *e, int64_t x, int64_t y)
{
    e->cx = (int32_t)(x * 4);
    e->cy = (int32_t)(y * 4);
    cairo_move_to(e->cr, at(e->cx, e->ox), at(e->cy, e->oy));
}

static void
line_to(emit_t *e, int64_t x, int64_t y)
{
    e->cx = (int32_t)(x * 4);
    e->cy = (int32_t)(y * 4);
    cairo_line_to(e->cr, at(e->cx, e->ox), at(e->cy, e->oy));
}

static void
cubic_to(emit_t *e, int32_t x1, int32_t y1, int32_t x2, int32_t y2,
         int32_t x3, int32_t y3)
{
    cairo_curve_to(e->cr, at(x1, e->ox), at(y1, e->oy), at(x2, e->ox),
                   at(y2, e->oy), at(x3, e->ox), at(y3, e->oy));
    e->cx = x3;
    e->cy = y3;
}

/* cairo-ft's _conic_to: the cubic of a quadratic arc, in 24.8 */
static void
conic_to(emit_t *e, int64_t cx, int64_t cy, int64_t x, int64_t y)
{
    int32_t qx = (int32_t)(cx * 4), qy = (int32_t)(cy * 4);
    int32_t x0 = e->cx, y0 = e->cy, x3 = (int32_t)(x * 4),
            y3 = (int32_t)(y * 4);
    int32_t x1 = (int32_t)(x0 + 2.0 / 3.0 * (qx - x0));
    int32_t y1 = (int32_t)(y0 + 2.0 / 3.0 * (qy - y0));
    int32_t x2 = (int32_t)(x3 + 2.0 / 3.0 * (qx - x3));
    int32_t y2 = (int32_t)(y3 + 2.0 / 3.0 * (qy - y3));
    cubic_to(e, x1, y1, x2, y2, x3, y3);
}

/* FT_Outline_Decompose of the y-inverted outline, into cairo's calls as
** cairo-ft's callbacks make them; 1 when FreeType would find the outline
** invalid (nothing may have been appended then: checked first). */
static int
decompose(const cf__outline_t *o, emit_t *e)
{
    size_t k, first = 0;
    /* check as FreeType checks, before anything is appended */
    for (k = 0; k < o->ncontours; k++) {
        size_t last = o->ends[k], i;
        if (last < first || last >= o->n || o->tags[first] == CF__OL_CUBIC)
            return 1;
        for (i = first; i <= last; i++)
            if (o->tags[i] == CF__OL_CUBIC &&
                (i + 1 > last || o->tags[i + 1] != CF__OL_CUBIC))
                return 1;
            else if (o->tags[i] == CF__OL_CUBIC)
                i++;
        first = last + 1;
    }
    first = 0;
    for (k = 0; k < o->ncontours; k++) {
        size_t last = o->ends[k], p = first, limit = last;
        int64_t sx = o->x[first], sy = -o->y[first];
        int64_t lx = o->x[last], ly = -o->y[last], vcx, vcy;
        bool closed = false;
        if (o->tags[first] == CF__OL_CONIC) {
            if (o->tags[last] == CF__OL_ON) {
                sx = lx;
                sy = ly;
                limit--;
            } else {
                sx = (sx + lx) / 2;
                sy = (sy + ly) / 2;
            }
            p--;   /* wraps for first == 0: incremented before use */
        }
        if (k > 0)
            cairo_close_path(e->cr);
        move_to(e, sx, sy);
        while (p != limit && !closed) {
            p++;
            if (o->tags[p] == CF__OL_ON) {
                line_to(e, o->x[p], -o->y[p]);
            } else if (o->tags[p] == CF__OL_CONIC) {
                vcx = o->x[p];
                vcy = -o->y[p];
                for (;;) {
                    int64_t vx, vy;
                    if (p == limit) {
                        conic_to(e, vcx, vcy, sx, sy);
                        closed = true;
                        break;
                    }
                    p++;
                    vx = o->x[p];
                    vy = -o->y[p];
                    if (o->tags[p] == CF__OL_ON) {
                        conic_to(e, vcx, vcy, vx, vy);
                        break;
                    }
                    if (o->tags[p] != CF__OL_CONIC)
                        return 1;   /* checked above: not reached */
                    conic_to(e, vcx, vcy, (vcx + vx) / 2, (vcy + vy) / 2);
                    vcx = vx;
                    vcy = vy;
                }
            } else {
                int32_t x1 = (int32_t)(o->x[p] * 4),
                        y1 = (int32_t)(-o->y[p] * 4),
                        x2 = (int32_t)(o->x[p + 1] * 4),
                        y2 = (int32_t)(-o->y[p + 1] * 4);
                p += 2;
                if (p <= limit && p != (size_t)-1) {
                    cubic_to(e, x1, y1, x2, y2, (int32_t)(o->x[p] * 4),
                             (int32_t)(-o->y[p] * 4));
                } else {
                    cubic_to(e, x1, y1, x2, y2, (int32_t)(sx * 4),
                             (int32_t)(sy * 4));
                    closed = true;
                }
            }
        }
        if (!closed)
            line_to(e, sx, sy);
        first = last + 1;
    }
    if (o->ncontours > 0)
        cairo_close_path(e->cr);
    return 0;
}

int
cf__own_glyph_path(cairo_t *cr, const cf__font_face_t *face,
                   unsigned long id, int32_t ox, int32_t oy)
{
    const own_t *w = own_of(face);
    cf__outline_t o;
    emit_t e;
    int r;
    if (!w->ok)
        return 1;
    memset(&o, 0, sizeof o);
    o.libc = true;   /* outside the library's count of blocks */
    r = load(w, id, &w->size, &o);
    if (r == 0) {
        e.cr = cr;
        e.ox = ox;
        e.oy = oy;
        e.cx = e.cy = 0;
        r = decompose(&o, &e);
    }
    cf__outline_fini(&o);
    return r;
}

static int glyph_extents(const own_t *w, unsigned long id,
                         cairo_text_extents_t *e);

int
cf__own_glyph_extents(const cf__font_face_t *face, unsigned long id,
                      cairo_text_extents_t *e)
{
    own_t *w = (own_t *)own_of(face);
    size_t i;
    int r;
    if (!w->ok)
        return 1;
    pthread_mutex_lock(&lock);
    for (i = 0; i < w->nseen; i++)
        if (w->seen[i].id == id) {
            *e = w->seen[i].e;
            pthread_mutex_unlock(&lock);
            return 0;
        }
    r = glyph_extents(w, id, e);
    if (r == 0) {
        if (w->nseen == w->cap_seen) {
            size_t cap = w->cap_seen ? 2 * w->cap_seen : 32;
            struct seen *t = realloc(w->seen, cap * sizeof *t);
            if (t != NULL) {
                w->seen = t;
                w->cap_seen = cap;
            }
        }
        if (w->nseen < w->cap_seen) {
            w->seen[w->nseen].id = id;
            w->seen[w->nseen++].e = *e;
        }
    }
    pthread_mutex_unlock(&lock);
    return r;
}

static int
glyph_extents(const own_t *w, unsigned long id, cairo_text_extents_t *e)
{
    cf__outline_t o;
    cairo_text_extents_t fs;
    double xf, yf, hm, wm, min_x = 0, max_x = 0, min_y = 0, max_y = 0;
    double left, right, top, bottom;
    bool first = true;
    int r;
    memset(&o, 0, sizeof o);
    o.libc = true;   /* outside the library's count of blocks */
    r = load(w, id, &w->em, &o);
    if (r != 0) {
        cf__outline_fini(&o);
        return r;
    }
    /* cairo-ft's glyph metrics, unhinted: loaded at the em size, in font
    ** space */
    xf = 1 / w->em_scale;
    yf = 1 / w->em_scale;
    fs.width = (double)(o.cbox[2] - o.cbox[0]) / 64.0 * xf;
    fs.height = (double)(o.cbox[3] - o.cbox[1]) / 64.0 * yf;
    fs.x_bearing = (double)o.cbox[0] / 64.0 * xf;
    fs.y_bearing = (double)(-o.cbox[3]) / 64.0 * yf;
    cf__outline_fini(&o);
    /* _cairo_scaled_glyph_set_metrics: the corners in user space */
    for (hm = 0.0; hm <= 1.0; hm += 1.0)
        for (wm = 0.0; wm <= 1.0; wm += 1.0) {
            double x = fs.x_bearing + fs.width * wm;
            double y = fs.y_bearing + fs.height * hm;
            cairo_matrix_transform_point(&w->font_matrix, &x, &y);
            if (first) {
                min_x = max_x = x;
                min_y = max_y = y;
                first = false;
            } else {
                if (x < min_x)
                    min_x = x;
                if (x > max_x)
                    max_x = x;
                if (y < min_y)
                    min_y = y;
                if (y > max_y)
                    max_y = y;
            }
        }
    /* cairo_scaled_font_glyph_extents of one glyph at 0, 0 */
    memset(e, 0, sizeof *e);
    if (max_x - min_x == 0 || max_y - min_y == 0)
        return 0;
    left = min_x + 0.0;
    right = left + (max_x - min_x);
    top = min_y + 0.0;
    bottom = top + (max_y - min_y);
    e->x_bearing = left - 0.0;
    e->y_bearing = top - 0.0;
    e->width = right - left;
    e->height = bottom - top;
    return 0;
}

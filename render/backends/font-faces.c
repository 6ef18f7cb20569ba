/*
** The faces and font sets of the native fonts (render/backends/
** font-faces.h), chosen as pango 1.50's fontconfig font map chooses them,
** so that the fonts, and so every glyph and number, are the same:
**   - a description's pattern: family list split at commas, slant
**     (roman or italic), weight (FcWeightFromOpenTypeDouble of 400 or
**     700), width normal, variable "don't care", 72 dpi, its size in
**     CF__FONT_SCALE units as pixel size / 1024 and point size, the
**     language; substituted by the configuration, by cairo's font options
**     (the renderer's: no hinting, metrics unhinted, grey antialiasing)
**     and by fontconfig's defaults;
**   - its fonts: fontconfig's best match first, then the fonts of its
**     trimmed sort from the second on (the sort made only when a font
**     after the first is asked for), each prepared for the pattern
**     (FcFontRenderPrepare), among the configuration's fonts of the
**     formats HarfBuzz reads (TrueType and CFF);
**   - a font's HarfBuzz font: the file's face, scale pixel size * 1024
**     over the pattern's matrix's scale factors, point size, synthetic
**     slant of the matrix, made when a run needs HarfBuzz
**     (cf__nface_hb); before, the face of the renderer's shaper
**     (render/fontfile/shape.h) with that scale and slant, whose tables
**     give the extents HarfBuzz would (when it is usable; a face it
**     cannot read has its HarfBuzz font made at once, as before); its
**     cairo scaled font: the pattern's face
**     (cairo_ft_font_face_create_for_pattern), the matrix (y down) times
**     the pixel size, identity device matrix, the renderer's options
**     (glyph positions not rounded, as a PDF's: see the_options);
**     the logical height of its glyphs: HarfBuzz's ascender and
**     descender (pango-cairo's glyph extents, metrics unhinted).
** Under the tool's own configuration (cf__nfaces_use_matcher) the match
** and the sort are the matcher's (render/backends/font-match.h), which
** gives the same faces with the same properties without fontconfig; a
** face's cairo font is then made from the file's FreeType face with the
** load flags and emboldening a pattern would give it (fm_font_face).
** A font with variation axes or font features from the configuration is
** marked unsupported: runs in it are pango's.  The caches live as long as
** the process, as pango's font map and fontconfig's do, in the C
** library's heap (not the library's allocator, whose count of live blocks
** they would otherwise stay in).
*/
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <fontconfig/fontconfig.h>
#include <hb-ot.h>

#include "font-cache.h"
#include "font-faces.h"
#include "font-glyphs.h"

/* What a face was made from, and the properties read from it once. */
struct cf__nface_src {
    FcPattern *pattern;      /* fontconfig's prepared pattern; NULL: the
                                matcher's face */
    FcCharSet *charset;
    cf__fm_face_t fm;
    FcMatrix matrix;         /* fontconfig's (y up) */
    double point, pixel;
    bool has_pixel;
};


struct cf__nfontset {
    char *family;
    bool italic, bold;
    int size;
    char lang[32];
    FcPattern *pattern;
    FcPattern *match;
    FcFontSet *sorted;     /* made at need */
    bool sort_failed;
    bool fm_matched;       /* the matcher's: its best, its sort */
    cf__fm_face_t fm_match;
    cf__fm_face_t *fm_sorted;
    size_t fm_nsorted;
    cf__nface_t **fonts;   /* prepared at need; NULL past the last */
    size_t nfonts, cap;
    bool ended;
};

typedef struct hb_face_entry {
    char *file;
    int index;
    hb_face_t *face;        /* made at need */
    FT_Face ft;             /* the matcher's faces' FreeType face, made at
                               need */
    cf__otface_t *own;      /* the shaper's face; NULL: not made */
} hb_face_entry_t;

/* One per process, as fontconfig's current configuration is. */
static pthread_mutex_t faces_lock = PTHREAD_MUTEX_INITIALIZER;
static cf__nfontset_t **sets;      /* one a description asked for */
static size_t nsets, cap_sets;
static cf__nface_t **faces;        /* one a prepared pattern */
static size_t nfaces, cap_faces;
static hb_face_entry_t *hb_faces;  /* one a font file and index */
static size_t nhb_faces, cap_hb_faces;

/* arr (n used of *cap elements of size bytes) with room for one more:
** arr itself, or arr reallocated (*cap set); NULL when out of memory
** (arr untouched). */
static void *
room(void *arr, size_t n, size_t *cap, size_t size)
{
    void *t;
    size_t c;
    if (n < *cap)
        return arr;
    c = *cap ? 2 * *cap : 16;
    t = realloc(arr, c * size);
    if (t != NULL)
        *cap = c;
    return t;
}
static FcFontSet *config_fonts;   /* the fonts HarfBuzz reads */
static const cf__fm_config_t *matcher;   /* NULL: fontconfig's */

void
cf__nfaces_use_matcher(const cf__fm_config_t *c)
{
    matcher = c;
}

bool
cf__nfaces_use_dirs(const cf__fm_source_t *dirs, size_t n,
                    const char *const *families, size_t nfamilies)
{
    cf_allocator_t prev;
    cf__fm_config_t *c;
    char cache[4096];
    int r;
    /* the process's default allocator (the C library's heap), as the
    ** caches here: the configuration lives as long as they do */
    cf_use_allocator(NULL, &prev);
    r = cf__fcache_config(dirs, n, families, nfamilies,
                          cf__fcache_path(cache, sizeof cache) ? cache : NULL,
                          &c, NULL, 0);
    cf_use_allocator(&prev, NULL);
    if (r != 0)
        return false;
    cf__nfaces_use_matcher(c);
    return true;
}

void
cf__nfaces_lock(void)
{
    pthread_mutex_lock(&faces_lock);
}

void
cf__nfaces_unlock(void)
{
    pthread_mutex_unlock(&faces_lock);
}

static bool
ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), m = strlen(tail);
    return n >= m && strcmp(s + n - m, tail) == 0;
}

/* Fonts HarfBuzz can shape (pango's filter: no WOFF, TrueType or CFF). */
static bool
supported_format(FcPattern *p)
{
    FcChar8 *file, *format;
    if (FcPatternGetString(p, FC_FILE, 0, &file) == FcResultMatch
        && (ends_with((const char *)file, ".woff")
            || ends_with((const char *)file, ".woff2")))
        return false;
    if (FcPatternGetString(p, FC_FONTFORMAT, 0, &format) != FcResultMatch)
        return false;
    return FcStrCmpIgnoreCase(format, (const FcChar8 *)"TrueType") == 0
           || FcStrCmpIgnoreCase(format, (const FcChar8 *)"CFF") == 0;
}

static FcFontSet *
the_config_fonts(void)
{
    int s, i;
    if (config_fonts != NULL)
        return config_fonts;
    config_fonts = FcFontSetCreate();
    if (config_fonts == NULL)
        return NULL;
    for (s = 0; s < 2; s++) {
        FcFontSet *set = FcConfigGetFonts(NULL, (FcSetName)s);
        if (set == NULL)
            continue;
        for (i = 0; i < set->nfont; i++)
            if (supported_format(set->fonts[i])) {
                FcPatternReference(set->fonts[i]);
                FcFontSetAdd(config_fonts, set->fonts[i]);
            }
    }
    return config_fonts;
}

static cairo_font_options_t *
renderer_options(void)
{
    cairo_font_options_t *fo = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    return fo;
}

/* A stream that refuses every byte: the surface read below for its
** options stops at its first write when it is destroyed. */
static cairo_status_t
no_output(void *closure, const unsigned char *data, unsigned int length)
{
    (void)closure;
    (void)data;
    (void)length;
    return CAIRO_STATUS_WRITE_ERROR;
}

/* The options of the faces' scaled fonts (face_opts): the renderer's,
** with glyph positions not rounded, as a PDF or PostScript surface asks
** (cairo's API cannot set that: they are read from a PDF surface).  Only
** rounding on changes a number, so the layout's numbers are those of the
** renderer's options alone; but a label shown on a PDF or PS surface,
** whose scaled font cairo makes from that surface's options and the
** renderer's, then finds this same scaled font in cairo's cache, its
** glyphs' metrics and outlines loaded, rather than making another that
** loads each glyph twice more (markova-2.17's PDF: 45 FreeType glyph
** loads before, 27 now).  A glyph is shown with the renderer's options
** (show_opts, cf__font_face_t.show_options), so that an image surface
** rounds its position as before. */
static cairo_font_options_t *face_opts, *show_opts;

static bool
the_options(void)
{
    cairo_surface_t *pdf;
    if (face_opts != NULL)
        return true;
    show_opts = renderer_options();
    face_opts = cairo_font_options_create();
    pdf = cairo_pdf_surface_create_for_stream(no_output, NULL, 1, 1);
    cairo_surface_get_font_options(pdf, face_opts);
    cairo_surface_destroy(pdf);
    cairo_font_options_merge(face_opts, show_opts);
    if (cairo_font_options_status(face_opts) == CAIRO_STATUS_SUCCESS
        && cairo_font_options_status(show_opts) == CAIRO_STATUS_SUCCESS)
        return true;
    cairo_font_options_destroy(face_opts);
    cairo_font_options_destroy(show_opts);
    face_opts = show_opts = NULL;
    return false;
}

static FcPattern *
make_pattern(const char *family, bool italic, bool bold, int size,
             const char *lang)
{
    const double dpi = 72.0;
    FcPattern *p = FcPatternBuild(
        NULL, FC_WEIGHT, FcTypeDouble,
        FcWeightFromOpenTypeDouble(bold ? 700 : 400), FC_SLANT,
        FcTypeInteger, italic ? FC_SLANT_ITALIC : FC_SLANT_ROMAN, FC_WIDTH,
        FcTypeInteger, FC_WIDTH_NORMAL, FC_VARIABLE, FcTypeBool, FcDontCare,
        FC_DPI, FcTypeDouble, dpi, FC_SIZE, FcTypeDouble,
        size * (72. / 1024. / dpi), FC_PIXEL_SIZE, FcTypeDouble,
        size / 1024., (char *)NULL);
    const char *f = family;
    cairo_font_options_t *fo;
    if (p == NULL)
        return NULL;
    while (true) {
        const char *comma = strchr(f, ',');
        size_t n = comma != NULL ? (size_t)(comma - f) : strlen(f);
        char name[256];
        if (n < sizeof name) {
            memcpy(name, f, n);
            name[n] = '\0';
            FcPatternAddString(p, FC_FAMILY, (const FcChar8 *)name);
        }
        if (comma == NULL)
            break;
        f = comma + 1;
    }
    FcPatternAddString(p, FC_LANG, (const FcChar8 *)lang);
    FcConfigSubstitute(NULL, p, FcMatchPattern);
    fo = renderer_options();
    cairo_ft_font_options_substitute(fo, p);
    cairo_font_options_destroy(fo);
    FcDefaultSubstitute(p);
    return p;
}

FcPattern *
cf__nfaces_pattern(const char *family, bool italic, bool bold, int size,
                   const char *lang)
{
    return make_pattern(family, italic, bold, size, lang);
}

/* A new set of the description, its best font found (fontconfig's or
** the matcher's); NULL when out of memory.  sets has room for it. */
static cf__nfontset_t *
new_set(const char *family, bool italic, bool bold, int size,
        const char *lang)
{
    cf__nfontset_t *s = calloc(1, sizeof *s);
    FcFontSet *fonts = NULL;
    FcResult res;
    if (s == NULL || (s->family = malloc(strlen(family) + 1)) == NULL
        || (matcher == NULL
            && ((fonts = the_config_fonts()) == NULL
                || (s->pattern = make_pattern(family, italic, bold, size,
                                              lang)) == NULL))) {
        if (s != NULL)
            free(s->family);
        free(s);
        return NULL;
    }
    strcpy(s->family, family);
    strcpy(s->lang, lang);
    s->italic = italic;
    s->bold = bold;
    s->size = size;
    if (matcher != NULL)
        s->fm_matched = cf__fm_match(matcher, family, italic, bold, size,
                                     lang, &s->fm_match) == 0;
    else
        s->match = FcFontSetMatch(NULL, &fonts, 1, s->pattern, &res);
    sets[nsets++] = s;
    return s;
}

cf__nfontset_t *
cf__nfontset_get(const char *family, bool italic, bool bold, int size,
                 const char *lang)
{
    cf__nfontset_t *s;
    size_t i;
    for (i = 0; i < nsets; i++) {
        s = sets[i];
        if (s->italic == italic && s->bold == bold && s->size == size
            && strcmp(s->family, family) == 0 && strcmp(s->lang, lang) == 0)
            return s;
    }
    if (strlen(lang) >= sizeof s->lang)
        return NULL;
    {
        cf__nfontset_t **t = room(sets, nsets, &cap_sets, sizeof *sets);
        if (t == NULL)
            return NULL;
        sets = t;
    }
    return new_set(family, italic, bold, size, lang);
}

/* The entry of a font file and index (the shaper's face opened), NULL
** when out of memory; valid until the next entry is made. */
static hb_face_entry_t *
entry_of(const char *file, int index)
{
    size_t i;
    hb_face_entry_t *e;
    for (i = 0; i < nhb_faces; i++)
        if (hb_faces[i].index == index && strcmp(hb_faces[i].file, file) == 0)
            return &hb_faces[i];
    e = room(hb_faces, nhb_faces, &cap_hb_faces, sizeof *hb_faces);
    if (e == NULL)
        return NULL;
    hb_faces = e;
    e = &hb_faces[nhb_faces];
    e->file = malloc(strlen(file) + 1);
    if (e->file == NULL)
        return NULL;
    strcpy(e->file, file);
    e->index = index;
    e->face = NULL;
    e->ft = NULL;
    e->own = malloc(cf__otface_size());
    if (e->own != NULL)
        cf__otface_open_at(e->own, file, (unsigned)index);
    nhb_faces++;
    return e;
}

/* The HarfBuzz face of a font file (pango's: the file's blob). */
static hb_face_t *
hb_face_of(const char *file, int index)
{
    hb_face_entry_t *e = entry_of(file, index);
    hb_blob_t *blob;
    if (e == NULL)
        return NULL;
    if (e->face == NULL) {
        blob = hb_blob_create_from_file(file);
        e->face = hb_face_create(blob, (unsigned)index);
        hb_blob_destroy(blob);
    }
    return e->face;
}

/* The product of the pattern's matrices (fontconfig's, y up). */
static FcMatrix
pattern_matrix(const FcPattern *p)
{
    FcMatrix m, *v;
    int i;
    FcMatrixInit(&m);
    for (i = 0; FcPatternGetMatrix(p, FC_MATRIX, i, &v) == FcResultMatch; i++)
        FcMatrixMultiply(&m, &m, v);
    return m;
}

/* pango's scale and slant of the face's HarfBuzz font
** (pango_fc_font_create_hb_font), and its point size. */
static void
face_scale(const cf__nface_t *f, cf__otscale_t *sc, double *point_size)
{
    const FcMatrix *m = &f->src->matrix;
    /* pango's font matrix: y down */
    double xx = m->xx, yx = -m->yx, xy = m->xy, yy = -m->yy;
    double major = sqrt(xx * xx + yx * yx), minor, det;
    double pixel = f->src->pixel, x0, y0, x1, y1, slant;
    if (major != 0) {
        det = xx * yy - yx * xy;
        if (det < 0)
            det = -det;
        minor = det / major;
    } else {
        minor = 0;
    }
    x0 = xy;   /* (0, 1) and (1, 0) through the matrix */
    y0 = yy;
    x1 = xx;
    y1 = yx;
    slant = (x0 * x1 + y0 * y1) / (x0 * x0 + y0 * y0);
    sc->x_scale = (int)(pixel * 1024 * (1. / (1. / major)));
    sc->y_scale = (int)(pixel * 1024 * (1. / (1. / minor)));
    sc->slant = (float)slant;
    *point_size = f->src->point;
}

/* pango's HarfBuzz font of the face (pango_fc_font_create_hb_font). */
static void
make_hb_font(cf__nface_t *f, hb_face_t *face)
{
    cf__otscale_t sc;
    double point;
    face_scale(f, &sc, &point);
    f->hb = hb_font_create(face);
    hb_font_set_scale(f->hb, sc.x_scale, sc.y_scale);
    hb_font_set_ptem(f->hb, (float)point);
    hb_font_set_synthetic_slant(f->hb, sc.slant);
}

hb_font_t *
cf__nface_hb(cf__nface_t *f)
{
    hb_face_t *hbf;
    if (f->hb != NULL)
        return f->hb;
    hbf = hb_face_of(f->face.file, (int)f->face.index);
    if (hbf != NULL)
        make_hb_font(f, hbf);
    return f->hb;
}

bool
cf__nface_has_char(const cf__nface_t *f, unsigned c)
{
    if (f->src->pattern == NULL)
        return cf__fm_font_has(f->src->fm.font, c);
    return f->src->charset != NULL && FcCharSetHasChar(f->src->charset, c);
}

/* The face's extents and whether it has variations, from the shaper's
** face when it reads the file, else from HarfBuzz's font made now. */
static bool
face_metrics(cf__nface_t *f, const char *file, int index)
{
    hb_face_entry_t *e = entry_of(file, index);
    hb_font_extents_t ext;
    double point;
    int asc, desc, gap;
    if (e == NULL)
        return false;
    if (e->own != NULL && cf__otface_usable(e->own)) {
        face_scale(f, &f->own_scale, &point);
        if (cf__otface_h_extents(e->own, f->own_scale.y_scale, &asc, &desc,
                                 &gap)) {
            /* a usable face has no fvar: no variation axes */
            f->own = e->own;
            f->ext_y = -asc;
            f->ext_height = asc - desc;
            return true;
        }
    }
    if (cf__nface_hb(f) == NULL)
        return false;
    f->unsupported = f->unsupported
                     || hb_ot_var_get_axis_count(hb_face_of(file, index)) > 0;
    hb_font_get_h_extents(f->hb, &ext);
    f->ext_y = -ext.ascender;
    f->ext_height = ext.ascender - ext.descender;
    return true;
}

/* The font matrix cf__nface_scaled gives the scaled font (y down, times
** the pixel size, gravity south), known without making it: the PDF
** writer's, and the glyphs read from the file (font-outlines.h). */
static void
font_matrix(cf__nface_t *f)
{
    cairo_matrix_t fm, gravity, m;
    const FcMatrix *fc = &f->src->matrix;
    double size = f->src->pixel;
    if (!f->src->has_pixel)
        return;
    cairo_matrix_init(&fm, fc->xx, -fc->yx, -fc->xy, fc->yy, 0., 0.);
    cairo_matrix_scale(&fm, size, size);
    cairo_matrix_init_rotate(&gravity, 0);   /* gravity south */
    cairo_matrix_multiply(&m, &fm, &gravity);
    f->face.matrix[0] = m.xx;
    f->face.matrix[1] = m.yx;
    f->face.matrix[2] = m.xy;
    f->face.matrix[3] = m.yy;
    f->face.has_matrix = true;
}

/* The face's scaled font made when drawing through cairo needs it
** (cf__font_face_t.make_scaled), outside the faces' lock. */
static void *
make_scaled(const cf__font_face_t *face)
{
    cf__nface_t *f = (cf__nface_t *)((char *)face
                                     - offsetof(cf__nface_t, face));
    cairo_scaled_font_t *sf;
    cf__nfaces_lock();
    sf = cf__nface_scaled(f);
    cf__nfaces_unlock();
    return sf;
}

/* The face of src (whose pattern, if any, it takes), its key and metrics
** made; NULL when out of memory (src's pattern destroyed). */
static cf__nface_t *
add_face(cf__nface_src_t *src, const char *file, int index,
         const char *family, int slant, double weight, int width,
         const char *psname, bool emboldened, bool unsupported)
{
    cf__nface_t *f;
    cf__nface_t **grown = room(faces, nfaces, &cap_faces, sizeof *faces);
    cf__nface_src_t *kept;
    if (grown != NULL)
        faces = grown;
    if (grown == NULL || (f = calloc(1, sizeof *f)) == NULL) {
        if (src->pattern != NULL)
            FcPatternDestroy(src->pattern);
        return NULL;
    }
    if ((kept = malloc(sizeof *kept)) == NULL) {
        if (src->pattern != NULL)
            FcPatternDestroy(src->pattern);
        free(f);
        return NULL;
    }
    *kept = *src;
    f->src = kept;
    f->unsupported = unsupported;
    f->face.file = file;    /* the pattern's or the matcher's, kept */
    f->face.index = (unsigned)index;
    if (!face_metrics(f, file, index)) {
        if (kept->pattern != NULL)
            FcPatternDestroy(kept->pattern);
        free(kept);
        free(f);
        return NULL;
    }
    /* the face without its size, as pango describes a font */
    snprintf(f->key, sizeof f->key, "%s|%d|%g|%d", family, slant, weight,
             width);
    f->face.key = f->key;
    f->face.outlines = cf__font_outline_cache_new();
    f->face.psname = psname;
    f->face.emboldened = emboldened;
    font_matrix(f);
    f->face.make_scaled = make_scaled;
    faces[nfaces++] = f;
    return f;
}

static cf__nface_t *
new_face(FcPattern *prepared)
{
    cf__nface_src_t src;
    FcChar8 *file, *fam, *feat, *ps = NULL;
    FcCharSet *cs;
    FcBool bold = FcFalse;
    int index = 0, slant = 0, width = 100;
    size_t i;
    double weight = 80;
    bool unsupported;
    for (i = 0; i < nfaces; i++)
        if (faces[i]->src->pattern != NULL
            && FcPatternEqual(faces[i]->src->pattern, prepared)) {
            FcPatternDestroy(prepared);
            return faces[i];
        }
    if (FcPatternGetString(prepared, FC_FILE, 0, &file) != FcResultMatch) {
        FcPatternDestroy(prepared);
        return NULL;
    }
    memset(&src, 0, sizeof src);
    src.pattern = prepared;
    FcPatternGetInteger(prepared, FC_INDEX, 0, &index);
    if (FcPatternGetCharSet(prepared, FC_CHARSET, 0, &cs) == FcResultMatch)
        src.charset = cs;
    src.matrix = pattern_matrix(prepared);
    if (FcPatternGetDouble(prepared, FC_SIZE, 0, &src.point) != FcResultMatch)
        src.point = 13.;
    src.has_pixel = FcPatternGetDouble(prepared, FC_PIXEL_SIZE, 0, &src.pixel)
                    == FcResultMatch;
    if (!src.has_pixel) {
        double dpi;
        if (FcPatternGetDouble(prepared, FC_DPI, 0, &dpi) != FcResultMatch)
            dpi = 72.;
        src.pixel = src.point * dpi / 72.;
    }
    unsupported =
        index != (index & 0xffff)
        || FcPatternGetString(prepared, FC_FONT_FEATURES, 0, &feat)
               == FcResultMatch
        || FcPatternGetString(prepared, FC_FONT_VARIATIONS, 0, &feat)
               == FcResultMatch;
    if (FcPatternGetString(prepared, FC_FAMILY, 0, &fam) != FcResultMatch)
        fam = (FcChar8 *)"";
    FcPatternGetInteger(prepared, FC_SLANT, 0, &slant);
    FcPatternGetDouble(prepared, FC_WEIGHT, 0, &weight);
    FcPatternGetInteger(prepared, FC_WIDTH, 0, &width);
    FcPatternGetString(prepared, FC_POSTSCRIPT_NAME, 0, &ps);
    FcPatternGetBool(prepared, FC_EMBOLDEN, 0, &bold);
    return add_face(&src, (const char *)file, index, (const char *)fam, slant,
                    weight, width, (const char *)ps, bold == FcTrue,
                    unsupported);
}

static bool
same_fm(const cf__fm_face_t *a, const cf__fm_face_t *b)
{
    return a->font == b->font && a->family == b->family
           && a->slant == b->slant && a->weight == b->weight
           && a->width == b->width && a->embolden == b->embolden
           && a->sheared == b->sheared && a->size == b->size
           && a->pixel_size == b->pixel_size && a->dpi == b->dpi;
}

/* The face of the matcher's fm. */
static cf__nface_t *
new_fm_face(const cf__fm_face_t *fm)
{
    cf__nface_src_t src;
    size_t i;
    for (i = 0; i < nfaces; i++)
        if (faces[i]->src->pattern == NULL && same_fm(&faces[i]->src->fm, fm))
            return faces[i];
    memset(&src, 0, sizeof src);
    src.fm = *fm;
    FcMatrixInit(&src.matrix);
    if (fm->sheared)
        src.matrix.xy = 0.2;
    src.point = fm->size;
    src.pixel = fm->pixel_size;
    src.has_pixel = true;
    /* a font taken from the cache unseen: its file is looked at now, when
    ** it is drawn (a file changed in place is read again, and the cache
    ** written anew at the next run) */
    cf__fm_font_verify(fm->font);
    return add_face(&src, fm->font->file, (int)fm->font->meta.index,
                    fm->family, fm->slant, fm->weight, (int)fm->width,
                    fm->font->meta.psname, fm->embolden, false);
}

/* The set's sort, made when a font after the first is needed (most
** texts find all their characters in the best match). */
static FcFontSet *
sorted(cf__nfontset_t *s)
{
    FcFontSet *fonts = the_config_fonts();
    FcResult res;
    if (s->sorted == NULL && !s->sort_failed && fonts != NULL) {
        s->sorted = FcFontSetSort(NULL, &fonts, 1, s->pattern, FcTrue, NULL,
                                  &res);
        s->sort_failed = s->sorted == NULL;
    }
    return s->sorted;
}

/* The matcher's sort, made at need alike; false when out of memory. */
static bool
fm_sorted(cf__nfontset_t *s)
{
    cf_allocator_t prev;
    if (s->fm_sorted != NULL || s->sort_failed)
        return s->fm_sorted != NULL;
    cf_use_allocator(NULL, &prev);   /* as cf__nfaces_use_dirs */
    s->sort_failed = cf__fm_sort(matcher, s->family, s->italic, s->bold,
                                 s->size, s->lang, &s->fm_sorted,
                                 &s->fm_nsorted) != 0;
    cf_use_allocator(&prev, NULL);
    return s->fm_sorted != NULL;
}

/* The k-th face of the set from the matcher; NULL past its last or when
** out of memory. */
static cf__nface_t *
fm_font(cf__nfontset_t *s, size_t k)
{
    if (k == 0)
        return s->fm_matched ? new_fm_face(&s->fm_match) : NULL;
    if (!fm_sorted(s) || k >= s->fm_nsorted)
        return NULL;
    return new_fm_face(&s->fm_sorted[k]);
}

cf__nface_t *
cf__nfontset_font(cf__nfontset_t *s, int i)
{
    while ((size_t)i >= s->nfonts && !s->ended) {
        FcPattern *p = NULL;
        cf__nface_t **t, *face = NULL;
        size_t k = s->nfonts;
        if (matcher != NULL) {
            face = fm_font(s, k);
        } else if (k == 0 && s->match != NULL) {
            FcPatternReference(s->match);
            p = s->match;
        } else if (sorted(s) != NULL && k < (size_t)s->sorted->nfont) {
            p = FcFontRenderPrepare(NULL, s->pattern, s->sorted->fonts[k]);
        }
        /* grown only for a font to add, and kept as soon as grown: a
        ** block moved by realloc when the list had ended there was lost
        ** (s->fonts left to the freed one), and a failed growth had
        ** doubled cap all the same */
        t = s->fonts;
        if ((p != NULL || face != NULL) && k == s->cap) {
            size_t nc = s->cap ? 2 * s->cap : 8;
            t = realloc(s->fonts, nc * sizeof *t);
            if (t != NULL) {
                s->fonts = t;
                s->cap = nc;
            }
        }
        if ((p == NULL && face == NULL) || t == NULL) {
            if (p != NULL)
                FcPatternDestroy(p);
            s->ended = true;
            break;
        }
        t[k] = face != NULL ? face : new_face(p);
        if (t[k] == NULL) {
            s->ended = true;
            break;
        }
        s->nfonts++;
    }
    return (size_t)i < s->nfonts ? s->fonts[i] : NULL;
}

/* The cairo font face of a matcher's face: the file's FreeType face
** (one a file and index, as cairo's unscaled font of a pattern is), with
** the load flags a pattern of the request's options gives cairo (no
** embedded bitmaps: hinting is off) and its emboldening.  cairo merges
** them with the scaled font's options to the same flags (no bitmaps, no
** hinting), so that the glyphs are those of cairo_ft_font_face_create_
** for_pattern, without fontconfig.  An emboldened face asks for no
** hinting in its load flags too (the same merged flags), so that cairo's
** cache of faces never hands one face to both. */
static cairo_font_face_t *
fm_font_face(const cf__nface_t *f)
{
    static FT_Library library;
    hb_face_entry_t *e = entry_of(f->face.file, (int)f->face.index);
    cairo_font_face_t *ff;
    if (e == NULL)
        return NULL;
    if (e->ft == NULL) {
        if (library == NULL && FT_Init_FreeType(&library) != 0) {
            library = NULL;
            return NULL;
        }
        if (FT_New_Face(library, e->file, e->index, &e->ft) != 0) {
            e->ft = NULL;
            return NULL;
        }
    }
    ff = cairo_ft_font_face_create_for_ft_face(
        e->ft, FT_LOAD_NO_BITMAP
                   | (f->src->fm.embolden ? FT_LOAD_NO_HINTING : 0));
    if (f->src->fm.embolden)
        cairo_ft_font_face_set_synthesize(ff, CAIRO_FT_SYNTHESIZE_BOLD);
    return ff;
}

cairo_scaled_font_t *
cf__nface_scaled(cf__nface_t *f)
{
    cairo_font_face_t *ff;
    cairo_matrix_t m, ctm;
    if (f->scaled != NULL)
        return f->scaled;
    if (!f->face.has_matrix)
        return NULL;
    cairo_matrix_init(&m, f->face.matrix[0], f->face.matrix[1],
                      f->face.matrix[2], f->face.matrix[3], 0., 0.);
    cairo_matrix_init_identity(&ctm);
    if (!the_options())
        return NULL;
    ff = f->src->pattern != NULL
             ? cairo_ft_font_face_create_for_pattern(f->src->pattern)
             : fm_font_face(f);
    if (ff == NULL)
        return NULL;
    f->scaled = cairo_scaled_font_create(ff, &m, &ctm, face_opts);
    cairo_font_face_destroy(ff);
    if (cairo_scaled_font_status(f->scaled) != CAIRO_STATUS_SUCCESS) {
        cairo_scaled_font_destroy(f->scaled);
        f->scaled = NULL;
    }
    f->face.scaled = f->scaled;
    f->face.show_options = show_opts;
    return f->scaled;
}

bool
cf__nface_scalable(const cf__nface_t *f)
{
    return f->scaled != NULL || f->face.has_matrix;
}

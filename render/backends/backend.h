/*
** The seam between the layout and the output devices: a backend is a
** struct of functions that receive a page and the operations of a display
** list (render/dlist/dlist.h) in order, as matplotlib's RendererBase receives
** draw_path, draw_markers and draw_text.  A new backend (PGF/TikZ, a
** browser canvas) is one more of these; the model and the layout do not
** change.
**
** Backends:
**   cairo (render/backends/backend-cairo.c): PS, EPS and PNG surfaces;
**   pdf writer (render/backends/backend-pdfw.c, pdf-doc.c): every PDF
**     figure;
**   dump  (render/backends/backend-dump.c): one line of text per operation,
**     deterministic, for tests;
**   pgf   (render/backends/backend-pgf.c): a pgfpicture for TeX, labels as TeX
**     source;
**   svg writer (render/backends/backend-svgw.c): every SVG (files, the
**     live view, overlay animations, the course pages' module);
**   measure (render/backends/measure.c): the layout's ink questions.
** Drawing backends receive markers as paths (render/dlist/marker.c), and
** meshes as flat pieces unless they draw mesh gradients (cairo, the PDF
** writer).
*/
#ifndef CURVEFIG_RENDER_BACKEND_H
#define CURVEFIG_RENDER_BACKEND_H

#include "buffer.h"
#include "dlist.h"

/* The page a display list is drawn on. */
typedef struct cf__page {
    double width, height;      /* bp */
    cf_color_t background;     /* a = 0: none */
    bool raster;               /* whole pixels: the background covers the
                                  partly covered last row and column */
    double label_size;         /* the theme's label size, bp (0: 10 TeX
                                  pt): PGF sets it at the document's */
    unsigned first_step, last_step;   /* overlay steps (render/overlay-
                                  spec.h): 0, 0 every operation on one
                                  page; else one page per step of
                                  first..last with the groups shown on it */
    const char *lang;          /* the language of its text (BCP 47), NULL:
                                  unsaid (docs/accessibility.md) */
} cf__page_t;

typedef struct cf__backend {
    const char *name;
    void (*begin_page)(void *ctx, const cf__page_t *page);
    /* overlay: a beamer overlay specification, NULL on every step */
    void (*begin_group)(void *ctx, const char *name, size_t index,
                        const char *overlay);
    void (*end_group)(void *ctx);
    void (*clip)(void *ctx, bool has_rect, const double rect[4]);
    void (*unclip)(void *ctx);
    void (*draw_path)(void *ctx, const cf__path_t *path,
                      const cf__paint_t *paint);
    /* NULL in a backend that draws (cairo, PGF, the SVG writer, the
    ** measuring one): a marker comes as a path (draw_path) with every
    ** stroke property set (render/dlist/marker.c); a backend that
    ** describes the display list (the dump) takes the marker whole. */
    void (*draw_marker)(void *ctx, const cf__marker_op_t *marker);
    void (*draw_text)(void *ctx, const cf__text_op_t *text);
    /* Finish the page; nonzero when the device failed. */
    int (*end_page)(void *ctx);
    /* Clip to the page minus n boxes (x y w h each), until the next
    ** unclip: the knockouts of the labels with a halo on a transparent
    ** page (render/dlist/dlist.h).  NULL: the backend draws no knockouts. */
    void (*knockout)(void *ctx, const double (*boxes)[4], size_t n);
    /* A mesh (render/dlist/dlist.h): n opaque triangles with a colour at
    ** each corner, painted in order, as a mesh gradient.  NULL: the seam
    ** hands the backend each triangle's four flat pieces instead, as
    ** paths (render/dlist/mesh.c), the same for every such backend. */
    void (*draw_mesh)(void *ctx, const cf__mesh_tri_t *tris, size_t n);
} cf__backend_t;

/* Hand ops [from, to) of dl to a backend (no begin_page / end_page). */
void cf__dl_play(const cf__dl_t *dl, size_t from, size_t to,
                 const cf__backend_t *be, void *ctx);
/* The ops of dl shown on overlay step k of page: a group whose overlay
** leaves k out is skipped whole (k 0: every op).  On a transparent page
** (page->background.a 0) a label halo of the background colour paints
** nothing: it is a knockout.  When there are knockouts and the backend
** draws them, the other ops are drawn first inside be->knockout of their
** boxes, then those labels (with their groups and clips, so overlays and
** clipping still hold). */
void cf__dl_play_step(const cf__dl_t *dl, const cf__page_t *page,
                      unsigned k, const cf__backend_t *be, void *ctx);
/* A whole page: begin_page, every op, end_page (its result). */
int cf__dl_play_page(const cf__dl_t *dl, const cf__page_t *page,
                     const cf__backend_t *be, void *ctx);

/* ---- the cairo backend -------------------------------------------------- */

/* Its functions; ctx is a cairo_t * set up by the caller (surface,
** scale).  begin_page paints the background. */
extern const cf__backend_t cf__cairo_backend;

/* Ink extents (page bp: x0 y0 x1 y1) of ops [from, to) of dl, drawn on a
** recording surface; nonzero when cairo failed. */
int cf__cairo_ink(const cf__dl_t *dl, size_t from, size_t to,
                  double ink[4]);

/* ---- the dump backend --------------------------------------------------- */

/* Its functions; ctx is a cf__dump_t. */
typedef struct cf__dump {
    char *text;          /* NUL-terminated; cf_free */
    size_t len, cap;
    bool failed;
} cf__dump_t;

extern const cf__backend_t cf__dump_backend;

/* ---- the PGF backend ---------------------------------------------------- */

/* Its functions; ctx is a cf__pgf_t with out (empty) and title (NULL or
** a line for the comment at the top) set and the rest zero; release it
** with cf__pgf_fini.  end_page fails when out ran out of memory or a
** coordinate lies beyond CF__PGF_MAX_BP (bad_value: the first). */
#define CF__PGF_MAX_BP 16000.0   /* TeX's largest dimension: 16322 bp */
/* Labels of the theme's size (the page's label_size, else this: 10 TeX
** pt) are set at the document's size; others scaled by their ratio to
** it (\scalebox). */
#define CF__PGF_BASE_SIZE (10.0 * 72.0 / 72.27)
struct cf__buf;
typedef struct cf__pgf {
    struct cf__buf *out;
    const char *title;
    const char *desc;              /* NULL or the long description, comment
                                      lines after the title's */
    double width, height;
    double base;                   /* label size set at the document's */
    int depth;                     /* groups open */
    unsigned long long overlays;   /* bit k: group k has an overlay */
    bool range_error;
    double bad_value;
    void *glyphs;                  /* cairo_t * for outlines of labels */
} cf__pgf_t;

extern const cf__backend_t cf__pgf_backend;
void cf__pgf_fini(cf__pgf_t *g);

/* ---- the SVG writer ----------------------------------------------------- */

/* Its functions; ctx is a cf__svgw_t with out (empty), outline and
** outline_ctx set and the rest zero (title, caption, uses and glyph_path
** optional).  outline appends to d the SVG path data of the glyphs (and
** fraction rules) of label t at its origin (t->ox, t->oy), in page units;
** nonzero when it failed.  With uses (natively), a label is instead its
** glyphs: uses appends a cf__svgw_use_t to `uses` for each glyph (its
** outline's number, 1 and up, the same for the same glyph of the same
** font, and its origin on the page) and the path data of the fraction
** rules to `rules`; 1 when it cannot (a glyph missing from its font:
** then outline), other nonzero when it failed.  glyph_path appends the
** path data of outline `id` at the origin; the document holds each
** outline used once, in <defs>.  end_page fails when out ran out of
** memory, a number was not finite or beyond 1e9 bp, a label's glyphs
** could not be outlined or groups nested deeper than CF__SVGW_DEPTH:
** cf__svgw_fault says which. */
#define CF__SVGW_DEPTH 64
typedef enum cf__svgw_fault_kind {
    CF__SVGW_FAULT_NONE,         /* else out of memory */
    CF__SVGW_FAULT_NUMBER,       /* the first: bad_value, in bad_name's
                                    element bad_index (NULL: none) */
    CF__SVGW_FAULT_GLYPHS,
    CF__SVGW_FAULT_DEPTH
} cf__svgw_fault_kind_t;
typedef struct cf__svgw_use {
    unsigned id;
    double x, y;
} cf__svgw_use_t;

/* The scopes a vector writer (the SVG and the PDF writer,
** render/backends/writer-scopes.c) has open: elements' groups and clip
** scopes, each noting whether it wrote its opening (<g>, q), an
** element's name and index (for a fault); and the writer's first fault
** (bad: any, out of memory when fault is NONE). */
typedef struct cf__scopes {
    struct cf__scope {
        bool group;              /* an element's group, else a clip scope */
        bool opened;             /* it wrote its opening */
        const char *name;        /* an element's: its name and index */
        size_t index;
    } stack[CF__SVGW_DEPTH];
    int depth;
    bool bad;
    cf__svgw_fault_kind_t fault;
    double bad_value;
    const char *bad_name;
    size_t bad_index;
} cf__scopes_t;

/* Fault k (a number: v) of the innermost element open, the first kept. */
void cf__scopes_fault(cf__scopes_t *s, cf__svgw_fault_kind_t k, double v);
/* Open a scope (a group named name, index when group); false, a fault,
** when CF__SVGW_DEPTH are open. */
bool cf__scopes_push(cf__scopes_t *s, bool group, bool opened,
                     const char *name, size_t index);
/* end_group: pop (which closes the innermost scope and takes it off)
** the scopes opened since the innermost group, then it, keeping the
** first `floor` (the page's). */
void cf__scopes_end_group(cf__scopes_t *s, int floor,
                          void (*pop)(void *w), void *w);
/* Why the writer of a `format` ("SVG", "PDF") failed, for a document
** called `what` ("svg", "frame 3 of the animated svg"): into diag
** (CF_STATUS_INVALID_ARG for a number or groups too deep, else
** CF_STATUS_NO_MEMORY), its status. */
cf_status_t cf__scopes_diag(const cf__scopes_t *s, const char *format,
                            const char *what, cf_diag_t *diag);

typedef struct cf__svgw {
    struct cf__buf *out;
    int (*outline)(void *outline_ctx, const cf__text_op_t *t,
                   struct cf__buf *d);
    void *outline_ctx;
    const char *title, *caption;   /* <title> and <desc>, may be NULL */
    int (*uses)(void *outline_ctx, const cf__text_op_t *t,
                struct cf__buf *uses, struct cf__buf *rules);
    int (*glyph_path)(void *outline_ctx, unsigned id, struct cf__buf *d);
    /* the writer's own */
    cf__scopes_t sc;
    unsigned clips;
    struct cf__buf body, *dst;   /* the drawing, written after the <defs> */
    unsigned char *used;         /* used[id]: outline id is used */
    size_t nused;
} cf__svgw_t;

extern const cf__backend_t cf__svgw_backend;

/* Why end_page of w failed, for a document called `what`: its scopes'
** fault (cf__scopes_diag). */
cf_status_t cf__svgw_fault(const cf__svgw_t *w, const char *what,
                           cf_diag_t *diag);

/* ---- the PDF writer ---------------------------------------------------- */

/* Its functions; ctx is a cf__pdfw_t with outline and outline_ctx set (as
** the SVG writer's: a label's outlines as SVG path data), glyphs
** optional, and the rest zero.  Each begin_page .. end_page is one page
** of the document (an overlay step); cf__pdfw_document then writes the
** whole document, and cf__pdfw_fini releases the writer.  end_page fails
** as the SVG writer's does (cf__pdfw_fault says why, with the SVG
** writer's words).
** With glyphs, a label is text: glyphs appends a cf__pdfw_glyph_t to
** `glyphs` for each of its glyphs and x y w h (4 doubles) to `rules` for
** each fraction rule; 1 when the label cannot be text (a face without a
** font file, or emboldened by cairo; a glyph missing from its font):
** then its outlines; other nonzero when it failed.  Each font file's face
** is embedded once, subset (render/fontfile/fontfile.h); a face the
** subsetter refuses makes cf__pdfw_document answer 1: play the pages
** again (cf__pdfw_restart), its labels then as outlines. */
#define CF__PDFW_DEPTH CF__SVGW_DEPTH
typedef struct cf__pdfw_gs {
    double fill[3], stroke[3];   /* colours set (-1: unknown) */
    int ca, CA;                  /* alpha resources set (-1: 1, unset) */
    double width;                /* -1: unknown */
    int cap, join;               /* -1: unknown */
    bool dashed;                 /* a dash is set */
} cf__pdfw_gs_t;
typedef struct cf__pdfw_glyph {
    const char *file;            /* its face's font file and index */
    unsigned index;
    const char *psname;          /* NULL, or the face's PostScript name */
    double m[4];                 /* its font matrix (xx yx xy yy, cairo's:
                                    em, y down, to the page's bp) */
    unsigned gid;
    double x, y;                 /* its origin on the page */
    const char *text;            /* the characters of the cluster it */
    size_t len;                  /* begins (len 0: none) */
} cf__pdfw_glyph_t;
struct cf__pdfw_font;
typedef struct cf__pdfw {
    int (*outline)(void *outline_ctx, const cf__text_op_t *t,
                   struct cf__buf *d);
    void *outline_ctx;
    int (*glyphs)(void *outline_ctx, const cf__text_op_t *t,
                  struct cf__buf *glyphs, struct cf__buf *rules);
    bool probe;                  /* a face is tried (subset with the glyph
                                    it is first used for) then, not only
                                    at the end: for pages that cannot be
                                    played again (an animation's frames) */
    /* the writer's own */
    double width, height;        /* the page's (every page's), bp */
    const char *lang;
    struct cf__buf content;      /* the page being drawn, uncompressed */
    struct cf__pdfw_page {
        struct cf__buf content;  /* its content stream, uncompressed */
        bool translucent;        /* it paints with an opacity below 1:
                                    a transparency group */
    } *pages;
    size_t npages, pages_cap;
    bool translucent;            /* the page being drawn's */
    struct cf__pdfw_shading {
        double box[4];           /* the vertices' range: x0 y0 x1 y1 */
        struct cf__buf data;     /* the vertices, uncompressed */
    } *shadings;                 /* each mesh's: /ShN */
    size_t nshadings, shadings_cap;
    double *alphas;              /* the distinct opacities: /aN /AN */
    size_t nalphas, alphas_cap;
    struct cf__pdfw_font *fonts; /* each face's: /FN (pdf-fonts.c) */
    size_t nfonts, fonts_cap;
    cf__scopes_t sc;             /* the scopes open (opened: wrote q) */
    struct {
        double clip[4];          /* the visible box before it */
        cf__pdfw_gs_t gs;        /* the graphics state before it */
    } saved[CF__PDFW_DEPTH];     /* saved[k]: of scope k */
    double clip[4];              /* the visible box: x0 y0 x1 y1 */
    cf__pdfw_gs_t gs;            /* the graphics state in the stream */
} cf__pdfw_t;

extern const cf__backend_t cf__pdfw_backend;

/* The document of w's pages (render/backends/pdf-doc.c) into out (empty):
** info (title and caption as /Title and /Subject, may be NULL; date, the
** creation and modification date as "YYYY-MM-DDTHH:MM:SSZ"), the tagged
** structure (docs/accessibility.md), the fonts, the classic xref table;
** the same bytes for the same pages.  0; 1 when a font was refused (out
** empty: cf__pdfw_restart, then play the pages again); -1 out of memory
** (out empty). */
int cf__pdfw_document(cf__pdfw_t *w, const char *title,
                      const char *caption, const char *date,
                      struct cf__buf *out);
void cf__pdfw_fini(cf__pdfw_t *w);
/* w without its pages, ready for them again; the fonts refused stay so. */
void cf__pdfw_restart(cf__pdfw_t *w);
/* Why end_page of w failed, as cf__svgw_fault. */
cf_status_t cf__pdfw_fault(const cf__pdfw_t *w, cf_diag_t *diag);

/* The accessible text of an SVG document (docs/accessibility.md): the
** attributes of its <svg> element (role="img", aria-labelledby naming
** its <title> and <desc>, xml:lang), and those elements.  The ids are
** made from the text (a hash), so that SVGs put inline in one page keep
** distinct ids.  0, or -1 when out of memory. */
int cf__svgw_a11y_attrs(struct cf__buf *out, const char *title,
                        const char *desc, const char *lang);
int cf__svgw_a11y_head(struct cf__buf *out, const char *title,
                       const char *desc);

/* A number of SVG path data or attributes: at most 3 decimals (1/1000
** bp), no trailing zeros; -1 when not finite or beyond 1e9 (nothing
** written), or out of memory. */
int cf__svg_put_num(struct cf__buf *b, double v);

/* The outline function of the SVG writer with cairo (render/backends/
** glyph-outline.c): outline_ctx a cf__glyph_outliner_t, zero at first,
** released with cf__glyph_outliner_fini. */
typedef struct cf__glyph_outliner {
    void *cr;                /* cairo_t * of a 1x1 surface, made at need */
} cf__glyph_outliner_t;

int cf__glyph_outline(void *outliner, const cf__text_op_t *t,
                      struct cf__buf *d);
void cf__glyph_outliner_fini(cf__glyph_outliner_t *g);
/* A cairo path (a cairo_path_t *) as SVG path data appended to d: 0, or
** -1 when the path holds an error or out of memory. */
int cf__svg_path_data(const void *cairo_path, struct cf__buf *d);

#endif

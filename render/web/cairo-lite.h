/*
** Internals of the cairo stand-in of the WebAssembly module, shared by
** cairo-lite.c (surfaces, state, paths, clips) and cairo-fill.c (the
** rasteriser: fills, strokes, paints, ink boxes).
*/
#ifndef CURVEFIG_WASM_CAIRO_LITE_H
#define CURVEFIG_WASM_CAIRO_LITE_H

#include "cairo.h"

#define PI 3.14159265358979323846
#define SUB 4                 /* sub-scanlines a pixel */
#define TOL 0.1               /* flattening tolerance, device pixels */
#define DEPTH 32

enum { IMAGE, RECORDING };

struct _cairo_surface {
    int kind;
    int w, h, stride;
    unsigned char *data;
    double ink[4];
    int has_ink;
    cairo_status_t status;
};

typedef struct { double xx, yx, xy, yy, x0, y0; } mat_t;

typedef struct gstate {
    mat_t m;
    double alpha;
    cairo_surface_t *src;
    double src_x, src_y;
    cairo_operator_t op;
    double width;
    cairo_line_cap_t cap;
    cairo_line_join_t join;
    double dash[16];
    int ndash;
    int has_clip;
    double clip[4];           /* device x0 y0 x1 y1 */
} gstate_t;

typedef struct { double x, y; } pt_t;

/* growable arrays of points and of edges */
typedef struct { pt_t *p; int n, cap; } pts_t;
typedef struct { double x0, y0, x1, y1; int dir; } edge_t;
typedef struct { edge_t *e; int n, cap; double box[4]; int failed; } poly_t;

struct _cairo {
    cairo_surface_t *target;
    gstate_t st[DEPTH];
    int depth;
    cairo_path_data_t *path;
    int n, cap;
    int has_cp;
    double cpx, cpy, spx, spy;   /* device: current point, subpath start */
    cairo_status_t status;
};

static inline gstate_t *
gs(cairo_t *cr)
{
    return &cr->st[cr->depth];
}

static inline void
path_clear(cairo_t *cr)
{
    cr->n = 0;
    cr->has_cp = 0;
}

#endif

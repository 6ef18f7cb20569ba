/*
** A backend that sees only the labels (render/backends/backend-text.h).
*/
#include "backend-text.h"

static void nop_page(void *ctx, const cf__page_t *pg)
{
    (void)ctx;
    (void)pg;
}
static void nop_group(void *ctx, const char *n, size_t i, const char *o)
{
    (void)ctx;
    (void)n;
    (void)i;
    (void)o;
}
static void nop(void *ctx) { (void)ctx; }
static void nop_clip(void *ctx, bool h, const double r[4])
{
    (void)ctx;
    (void)h;
    (void)r;
}
static void nop_path(void *ctx, const cf__path_t *pa, const cf__paint_t *q)
{
    (void)ctx;
    (void)pa;
    (void)q;
}
static void nop_marker(void *ctx, const cf__marker_op_t *m)
{
    (void)ctx;
    (void)m;
}
static int nop_end(void *ctx) { (void)ctx; return 0; }

cf__backend_t
cf__text_backend(const char *name,
                 void (*draw_text)(void *ctx, const cf__text_op_t *t))
{
    cf__backend_t be = { name, nop_page, nop_group, nop, nop_clip, nop,
                         nop_path, nop_marker, draw_text, nop_end, NULL,
                         NULL };
    return be;
}

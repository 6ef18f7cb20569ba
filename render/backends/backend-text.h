/*
** A backend that sees only the labels of a display list (render/backends/
** backend-text.c): for the glyph data of a course page and the places of
** the labels.
*/
#ifndef CURVEFIG_RENDER_BACKEND_TEXT_H
#define CURVEFIG_RENDER_BACKEND_TEXT_H

#include "backend.h"

/* A backend named name whose text operations go to draw_text and whose
** other operations do nothing. */
cf__backend_t cf__text_backend(const char *name,
                               void (*draw_text)(void *ctx,
                                                 const cf__text_op_t *t));

#endif

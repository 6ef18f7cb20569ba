/*
** PDF strings (render/backends/pdf-strings.c) for the PDF writer's
** document: a literal string, and a text string in UTF-16BE.
*/
#ifndef CURVEFIG_RENDER_PDF_STRINGS_H
#define CURVEFIG_RENDER_PDF_STRINGS_H

#include "buffer.h"

/* s (ASCII) as a literal string: ( ) \ escaped, other bytes outside
** printable ASCII as \ooo.  0, or -1 out of memory. */
int cf__pdf_put_string(cf__buf_t *b, const char *s);

/* A text string: <FEFF...> of UTF-8 text a, then (when b is neither NULL
** nor empty) a space and b, as UTF-16BE (a byte that starts no valid
** UTF-8 sequence as U+FFFD).  0, or -1 out of memory. */
int cf__pdf_put_text(cf__buf_t *out, const char *a, const char *b);

/* The UTF-16BE hex digits of UTF-8 text [s, s + n), as above. */
int cf__pdf_put_utf16(cf__buf_t *out, const char *s, size_t n);

#endif

/*
** The places of a figure's labels as JSON (render/output/output-private.h):
** what the layout chose, read off the display list that is drawn, so that
** the tool and the browser module can be compared number for number
** (tests/wasm/places.py).  Numbers with 17 significant digits: the same
** double after a round trip through any JSON reader.
*/
#include <stdio.h>
#include <string.h>

#include "backend-text.h"
#include "output-private.h"

typedef struct places {
    cf__buf_t *out;
    size_t n;
    bool bad;
} places_t;

static void
put(places_t *p, const char *s, size_t n)
{
    if (cf__buf_append(p->out, s, n) != 0)
        p->bad = true;
}

static void
put_num(places_t *p, const char *key, double v)
{
    char b[64];
    int n = snprintf(b, sizeof b, ", \"%s\": %.17g", key, v);
    put(p, b, (size_t)n);
}

static void
text_op(void *ctx, const cf__text_op_t *t)
{
    places_t *p = ctx;
    const char *s = t->source != NULL ? t->source : "";
    char b[16];
    if (p->n++ > 0)
        put(p, ", ", 2);
    put(p, "{\"text\": \"", 10);
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            b[0] = '\\';
            b[1] = (char)c;
            put(p, b, 2);
        } else if (c < 0x20) {
            put(p, b, (size_t)snprintf(b, sizeof b, "\\u%04x", c));
        } else {
            put(p, s, 1);
        }
    }
    put(p, "\"", 1);
    put(p, b, (size_t)snprintf(b, sizeof b, ", \"place\": %d",
                               (int)t->place));
    put_num(p, "x", t->ox);
    put_num(p, "y", t->oy);
    put_num(p, "anchor_x", t->px);
    put_num(p, "anchor_y", t->py);
    put(p, "}", 1);
}



int
cf__label_places(const cf__dl_t *dl, const cf__page_t *page, cf__buf_t *out)
{
    places_t p = { out, 0, false };
    const cf__backend_t places_backend = cf__text_backend("label places",
                                                          text_op);
    put(&p, "[", 1);
    cf__dl_play_page(dl, page, &places_backend, &p);
    put(&p, "]", 1);
    return p.bad ? -1 : 0;
}

/*
** The animated SVG of an animation's frames (output-private.h): one
** document, every frame a group shown in turn by a SMIL <animate> of its
** visibility, looping.  The frames are drawn by the SVG writer (render/
** backends/backend-svgw.c) with one glyph table, so that a glyph has one
** number in every frame and its outline is written once, in the
** document's <defs>; the other ids of frame K (its clips) get the prefix
** "fK-".  Each frame's animation names only its own times (hidden, shown
** from its start to its end, hidden), so the document grows by the
** frames, not by their square.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "output-private.h"

static int
put(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

#define find cf__bytes_find

/* The symbols of [p, end) (the frame's <defs>) that defs lacks, added. */
static int
take_defs(cf__svg_anim_t *a, const unsigned char *p, const unsigned char *end)
{
    static const char open[] = "<symbol overflow=\"visible\" id=\"g";
    const unsigned char *s, *e;
    while ((s = find(p, end, open)) != NULL) {
        unsigned long id = strtoul((const char *)s + sizeof open - 1, NULL,
                                   10);
        e = find(s, end, "</symbol>");
        if (e == NULL)
            return -1;
        e += strlen("</symbol>");
        if (id >= a->nhave) {
            size_t cap = a->nhave;
            unsigned char *h = cf__grow_array(a->have, &cap, id + 1, 1, 64);
            if (h == NULL)
                return -1;
            memset(h + a->nhave, 0, cap - a->nhave);
            a->have = h;
            a->nhave = cap;
        }
        if (!a->have[id]) {
            a->have[id] = 1;
            if (cf__buf_append(&a->defs, s, (size_t)(e - s)) != 0
                || put(&a->defs, "\n") != 0)
                return -1;
        }
        p = e;
    }
    return 0;
}

cf_status_t
cf__svg_anim_add(cf__svg_anim_t *a, const cf__dl_t *dl,
                 const cf__page_t *page, unsigned step, double seconds,
                 cf_diag_t *diag)
{
    cf__page_t pg = *page;
    cf__svgw_t w;
    cf__buf_t doc;
    const unsigned char *t0, *t1, *b1, *body;
    char prefix[24];
    double *start;
    int r;
    memset(&w, 0, sizeof w);
    memset(&doc, 0, sizeof doc);
    pg.first_step = pg.last_step = step;
    w.out = &doc;
    cf__svg_glyphs_attach(&a->sg, &w);
    cf__svgw_backend.begin_page(&w, &pg);
    cf__dl_play_step(dl, &pg, step, &cf__svgw_backend, &w);
    r = cf__svgw_backend.end_page(&w);
    if (r != 0) {
        char what[64];
        cf__buf_free(&doc);
        snprintf(what, sizeof what, "frame %zu of the animated svg",
                 a->n + 1);
        return cf__svgw_fault(&w, what, diag);
    }
    if (cf__svg_split(&doc, &t0, &t1, &b1) != 0)
        r = -1;
    start = r == 0 ? cf__grow_array(a->start, &a->cap, a->n + 1,
                                    sizeof *a->start, 64)
                   : NULL;
    if (start == NULL) {
        cf__buf_free(&doc);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing frame %zu of the "
                           "animated svg", a->n + 1);
    }
    a->start = start;
    while (t1 < b1 && *t1 == '\n')
        t1++;
    body = t1;
    if (b1 - t1 > 7 && memcmp(t1, "<defs>\n", 7) == 0) {
        const unsigned char *d1 = find(t1, b1, "</defs>\n");
        if (d1 == NULL || take_defs(a, t1, d1) != 0)
            r = -1;
        else
            body = d1 + strlen("</defs>\n");
    }
    if (r == 0 && a->n == 0)
        r = cf__buf_append(&a->head, t0, (size_t)(t1 - t0));
    snprintf(prefix, sizeof prefix, "f%zu-", a->n);
    /* the frame's group and its animation come at finish */
    if (r == 0) {
        char open[64];
        snprintf(open, sizeof open, "\n<!--frame %zu-->\n", a->n);
        r = put(&a->body, open);
    }
    if (r == 0)
        r = cf__svg_put_prefixed(&a->body, body, b1, prefix, true);
    cf__buf_free(&doc);
    if (r != 0 || a->body.failed || a->defs.failed || a->head.failed)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing the animated svg");
    a->start[a->n++] = a->total;
    a->total += seconds;
    return CF_STATUS_OK;
}

/* The group opening frame k and its animation. */
static int
put_group(cf__buf_t *b, const cf__svg_anim_t *a, size_t k, size_t still)
{
    char s[200];
    double t0 = a->start[k] / a->total;
    double t1 = k + 1 < a->n ? a->start[k + 1] / a->total : 1;
    snprintf(s, sizeof s, "<g id=\"frame-%zu\" visibility=\"%s\">", k,
             k == still ? "visible" : "hidden");
    if (put(b, s) != 0)
        return -1;
    if (a->n < 2)
        return put(b, "\n");
    if (put(b, "<animate attributeName=\"visibility\" calcMode=\"discrete\" "
               "repeatCount=\"indefinite\" ") != 0)
        return -1;
    if (k == 0)
        snprintf(s, sizeof s, "values=\"visible;hidden\" keyTimes=\"0;%.6g\"",
                 t1);
    else if (k + 1 == a->n)
        snprintf(s, sizeof s, "values=\"hidden;visible\" keyTimes=\"0;%.6g\"",
                 t0);
    else
        snprintf(s, sizeof s, "values=\"hidden;visible;hidden\" "
                 "keyTimes=\"0;%.6g;%.6g\"", t0, t1);
    if (put(b, s) != 0)
        return -1;
    snprintf(s, sizeof s, " dur=\"%.6gs\"/>\n", a->total);
    return put(b, s);
}

cf_status_t
cf__svg_anim_finish(cf__svg_anim_t *a, size_t still, const char *title,
                    const char *caption, cf__buf_t *out, cf_diag_t *diag)
{
    const unsigned char *p, *end;
    size_t k = 0;
    int r = 0;
    memset(out, 0, sizeof *out);
    if (a->n == 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "an animated svg without frames");
    r = cf__buf_append(out, a->head.data, a->head.size);
    if (r == 0 && (title != NULL || caption != NULL))
        r = put(out, "\n<title>") != 0
            || cf__svg_put_escaped(out, title != NULL ? title : caption) != 0
            || put(out, "</title>") != 0;
    if (r == 0 && caption != NULL)
        r = put(out, "\n<desc>") != 0 || cf__svg_put_escaped(out, caption) != 0
            || put(out, "</desc>") != 0;
    if (r == 0 && a->defs.size > 0)
        r = put(out, "\n<defs>\n") != 0
            || cf__buf_append(out, a->defs.data, a->defs.size) != 0
            || put(out, "</defs>") != 0;
    /* each frame's marker replaced by the end of the one before and its
    ** own group */
    p = a->body.data;
    end = p + a->body.size;
    while (r == 0 && p < end) {
        const unsigned char *m = find(p, end, "\n<!--frame ");
        const unsigned char *next = m != NULL ? find(m + 1, end, "\n<!--frame ")
                                              : NULL;
        const unsigned char *close;
        if (m == NULL)
            break;
        close = find(m, end, "-->\n");
        if (close == NULL) {
            r = -1;
            break;
        }
        close += 4;
        r = put(out, "\n") != 0 || put_group(out, a, k, still) != 0
            || cf__buf_append(out, close,
                              (size_t)((next != NULL ? next : end) - close))
                   != 0
            || put(out, "</g>") != 0;
        k++;
        p = next != NULL ? next : end;
    }
    if (r == 0)
        r = put(out, "\n</svg>\n");
    if (r != 0 || out->failed || k != a->n) {
        cf__buf_free(out);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing the animated svg");
    }
    return CF_STATUS_OK;
}

void
cf__svg_anim_free(cf__svg_anim_t *a)
{
    cf__svg_glyphs_fini(&a->sg);
    cf__buf_free(&a->head);
    cf__buf_free(&a->defs);
    cf__buf_free(&a->body);
    cf_free(a->have);
    cf_free(a->start);
    memset(a, 0, sizeof *a);
}

/*
** The animated SVG of a figure with overlay steps: the SVG of every step
** (the SVG writer, render/output/formats.c), one group each, shown in turn
** by a SMIL <animate> of its visibility, looping: the frames are exactly
** the step pictures the other formats give.  The ids of each frame
** (glyphs, clips) get the prefix "sK-" so that the frames do not clash.
** A viewer that does not play SMIL shows the last step.
*/
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "output-private.h"

/* Seconds each step stays on the screen. */
#define STEP_SECONDS 1.5

static int
put(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

/* The first needle in [h, end), or NULL. */
#define find cf__bytes_find

int
cf__svg_put_escaped(cf__buf_t *b, const char *s)
{
    for (; *s != '\0'; s++) {
        const char *r = *s == '<' ? "&lt;" : *s == '>' ? "&gt;"
                      : *s == '&' ? "&amp;" : *s == '"' ? "&quot;" : NULL;
        if ((r != NULL ? put(b, r) : cf__buf_append(b, s, 1)) != 0)
            return -1;
    }
    return 0;
}

int
cf__svg_put_prefixed(cf__buf_t *b, const unsigned char *p,
                     const unsigned char *end, const char *prefix,
                     bool glyphs_shared)
{
    static const char *const refs[] = { "id=\"", "url(#", "href=\"#" };
    while (p < end) {
        const unsigned char *best = NULL;
        size_t blen = 0;
        for (size_t i = 0; i < sizeof refs / sizeof refs[0]; i++) {
            const unsigned char *q = find(p, end, refs[i]);
            if (q != NULL && (best == NULL || q < best)) {
                best = q;
                blen = strlen(refs[i]);
            }
        }
        if (best == NULL)
            return cf__buf_append(b, p, (size_t)(end - p));
        if (cf__buf_append(b, p, (size_t)(best - p + blen)) != 0)
            return -1;
        /* a glyph's outline (gN) of a shared <defs> keeps its name */
        if (!(glyphs_shared && best + blen + 1 < end && best[blen] == 'g'
              && best[blen + 1] >= '0' && best[blen + 1] <= '9')
            && put(b, prefix) != 0)
            return -1;
        p = best + blen;
    }
    return 0;
}

int
cf__svg_split(const cf__buf_t *doc, const unsigned char **tag0,
          const unsigned char **tag1, const unsigned char **body1)
{
    const unsigned char *end = doc->data + doc->size, *s, *gt, *close = NULL;
    const unsigned char *q;
    s = find(doc->data, end, "<svg");
    gt = s != NULL ? memchr(s, '>', (size_t)(end - s)) : NULL;
    if (gt == NULL)
        return -1;
    for (q = gt; (q = find(q, end, "</svg>")) != NULL; q++)
        close = q;
    if (close == NULL)
        return -1;
    *tag0 = s;
    *tag1 = gt + 1;
    *body1 = close;
    return 0;
}

static int
put_animation(cf__buf_t *b, unsigned k, unsigned n)
{
    char num[64];
    unsigned j;
    snprintf(num, sizeof num, "<g id=\"step-%u\" visibility=\"%s\">\n", k,
             k == n ? "visible" : "hidden");
    if (put(b, num) != 0
        || put(b, "<animate attributeName=\"visibility\" "
                  "calcMode=\"discrete\" repeatCount=\"indefinite\" "
                  "values=\""))
        return -1;
    for (j = 1; j <= n; j++)
        if (put(b, j > 1 ? ";" : "") != 0
            || put(b, j == k ? "visible" : "hidden") != 0)
            return -1;
    if (put(b, "\" keyTimes=\"") != 0)
        return -1;
    for (j = 0; j < n; j++) {
        snprintf(num, sizeof num, "%s%.6g", j > 0 ? ";" : "",
                 (double)j / n);
        if (put(b, num) != 0)
            return -1;
    }
    snprintf(num, sizeof num, "\" dur=\"%gs\"/>\n", STEP_SECONDS * n);
    return put(b, num);
}

cf_status_t
cf__svg_steps(const cf__dl_t *dl, const cf__page_t *page, unsigned steps,
              const char *title, const char *caption, cf__buf_t *out,
              cf_diag_t *diag)
{
    unsigned k;
    int r = 0;
    memset(out, 0, sizeof *out);
    for (k = 1; k <= steps && r == 0; k++) {
        cf__page_t pg = *page;
        cf__buf_t doc;
        const unsigned char *t0, *t1, *b1;
        char prefix[16];
        cf_status_t st;
        pg.first_step = pg.last_step = k;
        memset(&doc, 0, sizeof doc);
        st = cf__format_render(CF_FORMAT_SVG, dl, &pg, 72, NULL, NULL, &doc,
                               diag);
        if (st != CF_STATUS_OK) {
            cf__buf_free(out);
            return st;
        }
        if (cf__svg_split(&doc, &t0, &t1, &b1) != 0) {
            cf__buf_free(&doc);
            cf__buf_free(out);
            return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                               "svg: the document of step %u has no "
                               "<svg> element", k);
        }
        if (k == 1) {
            r = cf__buf_append(out, doc.data, (size_t)(t1 - 1 - doc.data));
            if (r == 0 && title != NULL)
                r = cf__svgw_a11y_attrs(out, title, caption, page->lang);
            if (r == 0)
                r = put(out, ">\n");
            if (r == 0 && title != NULL)
                r = cf__svgw_a11y_head(out, title, caption);
        }
        snprintf(prefix, sizeof prefix, "s%u-", k);
        if (r == 0)
            r = put_animation(out, k, steps);
        if (r == 0)
            r = cf__svg_put_prefixed(out, t1, b1, prefix, false);
        if (r == 0)
            r = put(out, "</g>\n");
        cf__buf_free(&doc);
    }
    if (r == 0)
        r = put(out, "</svg>\n");
    if (r != 0 || out->failed) {
        cf__buf_free(out);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing the animated svg");
    }
    return CF_STATUS_OK;
}

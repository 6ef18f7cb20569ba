/*
** What cairo's tag API cannot write into a tagged PDF, added to the bytes
** it wrote (docs/accessibility.md, "PDF").  cairo 1.16 writes the
** structure tree of the tags it is given (StructTreeRoot, a Document
** element holding a Figure element, the marked content of every page
** and the ParentTree) and /MarkInfo << /Marked true >> in the catalog,
** but takes no attributes for structure elements: no /Alt on the Figure,
** and it has no call for the document's /Lang.  This adds, in cairo
** 1.16's own layout (one object per "N 0 obj", a classic xref table of
** 20-byte entries, no object streams):
**   /Alt (the alt text and the description, UTF-16BE) to every Figure
**   element, /Lang and /ViewerPreferences << /DisplayDocTitle true >> to
**   the catalog,
** and moves every xref offset and startxref by the bytes inserted before
** it.  Bytes of any other layout are left as they are (1): the PDF stays
** valid, only without the /Alt.
*/
#include <stdio.h>
#include <string.h>

#include "output-private.h"

#define FIGURE "<< /Type /StructElem\n   /S /Figure\n"
#define CATALOG "<< /Type /Catalog\n"
#define MAX_INSERTS 64

typedef struct insert {
    size_t at;
    const cf__buf_t *text;
} insert_t;

const unsigned char *
cf__bytes_find(const unsigned char *h, const unsigned char *end,
               const char *needle)
{
    size_t m = strlen(needle);
    for (; h + m <= end; h++)
        if (*h == (unsigned char)needle[0] && memcmp(h, needle, m) == 0)
            return h;
    return NULL;
}

#define find cf__bytes_find

static int
put(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

/* Code point at s (advancing it), U+FFFD for a byte that starts no valid
** UTF-8 sequence. */
static unsigned
next_cp(const unsigned char **s)
{
    const unsigned char *p = *s;
    unsigned c = p[0], n = c < 0x80 ? 0 : c >= 0xf0 && c < 0xf5 ? 3
                                     : c >= 0xe0 ? 2 : c >= 0xc2 ? 1 : 9;
    if (n == 9) {
        (*s)++;
        return c < 0x80 ? c : 0xfffd;
    }
    c = n == 0 ? c : c & (0x3fu >> n);
    for (unsigned i = 1; i <= n; i++) {
        if ((p[i] & 0xc0) != 0x80) {
            *s = p + 1;
            return 0xfffd;
        }
        c = (c << 6) | (p[i] & 0x3fu);
    }
    *s = p + n + 1;
    return c;
}

static int
put_unit(cf__buf_t *b, unsigned u)
{
    char hex[8];
    snprintf(hex, sizeof hex, "%04X", u & 0xffffu);
    return put(b, hex);
}

/* "   /Alt <FEFF...>\n": text as a UTF-16BE string. */
static int
alt_entry(cf__buf_t *b, const char *alt, const char *desc)
{
    const char *parts[3] = { alt, desc != NULL && desc[0] != '\0' ? " " : "",
                             desc != NULL ? desc : "" };
    int r = put(b, "   /Alt <FEFF");
    for (int k = 0; k < 3; k++) {
        const unsigned char *s = (const unsigned char *)parts[k];
        while (*s != '\0' && r == 0) {
            unsigned c = next_cp(&s);
            if (c >= 0x10000) {
                c -= 0x10000;
                r = put_unit(b, 0xd800 + (c >> 10))
                    || put_unit(b, 0xdc00 + (c & 0x3ff));
            } else {
                r = put_unit(b, c);
            }
        }
    }
    return r || put(b, ">\n") ? -1 : 0;
}

/* The bytes inserted before offset x. */
static size_t
shift(const insert_t *ins, size_t n, size_t x)
{
    size_t s = 0;
    for (size_t i = 0; i < n; i++)
        if (ins[i].at <= x)
            s += ins[i].text->size;
    return s;
}

static bool
digits(const unsigned char *p, size_t n, size_t *value)
{
    *value = 0;
    for (size_t i = 0; i < n; i++) {
        if (p[i] < '0' || p[i] > '9')
            return false;
        *value = *value * 10 + (size_t)(p[i] - '0');
    }
    return true;
}

/* The xref table at x (its entries from *first on, *count of them, each
** 20 bytes) and the startxref number's digits [*sx0, *sx1); false when
** not in the layout expected. */
static bool
parse_xref(const unsigned char *data, const unsigned char *end,
           const unsigned char *x, const unsigned char **first,
           size_t *count, const unsigned char **sx0,
           const unsigned char **sx1)
{
    const unsigned char *p = x + 5, *q;
    size_t start, n, at;
    if (p + 2 > end || p[0] != '0' || p[1] != ' ')
        return false;
    p += 2;
    for (q = p; q < end && *q >= '0' && *q <= '9'; q++)
        ;
    if (q == p || q >= end || *q != '\n' || !digits(p, (size_t)(q - p), &n))
        return false;
    p = q + 1;
    if ((size_t)(end - p) < 20 * n)
        return false;
    for (size_t i = 0; i < n; i++) {
        const unsigned char *e = p + 20 * i;
        if (!digits(e, 10, &start) || e[10] != ' ' || e[16] != ' '
            || (e[17] != 'n' && e[17] != 'f'))
            return false;
    }
    *first = p;
    *count = n;
    q = find(p + 20 * n, end, "startxref\n");
    if (q == NULL)
        return false;
    *sx0 = q + 10;
    for (q = *sx0; q < end && *q >= '0' && *q <= '9'; q++)
        ;
    *sx1 = q;
    return q > *sx0 && digits(*sx0, (size_t)(q - *sx0), &at)
        && at == (size_t)(x - data);
}

static int
rewrite(const cf__buf_t *pdf, const insert_t *ins, size_t nins,
        const unsigned char *xref, const unsigned char *first, size_t count,
        const unsigned char *sx0, const unsigned char *sx1, cf__buf_t *out)
{
    const unsigned char *p = pdf->data, *end = pdf->data + pdf->size;
    size_t k = 0;
    char num[32];
    int r = 0;
    /* the objects, with the entries inserted */
    while (r == 0 && p < first) {
        const unsigned char *stop = k < nins ? pdf->data + ins[k].at : first;
        if (stop > first)
            stop = first;
        r = cf__buf_append(out, p, (size_t)(stop - p));
        p = stop;
        if (r == 0 && k < nins && p == pdf->data + ins[k].at) {
            r = cf__buf_append(out, ins[k].text->data, ins[k].text->size);
            k++;
        }
    }
    /* the xref entries moved */
    for (size_t i = 0; i < count && r == 0; i++, p += 20) {
        size_t off;
        digits(p, 10, &off);
        if (p[17] == 'n')
            off += shift(ins, nins, off);
        snprintf(num, sizeof num, "%010zu", off);
        r = cf__buf_append(out, num, 10)
            || cf__buf_append(out, p + 10, 10);
    }
    if (r == 0)
        r = cf__buf_append(out, p, (size_t)(sx0 - p));
    snprintf(num, sizeof num, "%zu",
             (size_t)(xref - pdf->data) + shift(ins, nins, (size_t)(xref
                                                 - pdf->data)));
    if (r == 0)
        r = put(out, num) || cf__buf_append(out, sx1, (size_t)(end - sx1));
    return r != 0 || out->failed ? -1 : 0;
}

int
cf__pdf_tag(const cf__buf_t *pdf, const char *alt, const char *desc,
            const char *lang, cf__buf_t *out)
{
    const unsigned char *data = pdf->data, *end = data + pdf->size, *p, *x;
    const unsigned char *first, *sx0, *sx1, *cat;
    insert_t ins[MAX_INSERTS];
    cf__buf_t alt_text, cat_text;
    size_t nins = 0, count;
    int r;
    memset(out, 0, sizeof *out);
    if (alt == NULL || data == NULL)
        return 1;
    /* the last xref table, and one catalog before it */
    x = NULL;
    for (p = data; (p = find(p, end, "\nxref\n")) != NULL; p++)
        x = p + 1;
    cat = find(data, end, CATALOG);
    if (x == NULL || cat == NULL || cat > x
        || find(cat + 1, end, CATALOG) != NULL
        || !parse_xref(data, end, x, &first, &count, &sx0, &sx1))
        return 1;
    memset(&alt_text, 0, sizeof alt_text);
    memset(&cat_text, 0, sizeof cat_text);
    r = alt_entry(&alt_text, alt, desc);
    if (r == 0 && lang != NULL)
        r = put(&cat_text, "   /Lang (") || put(&cat_text, lang)
            || put(&cat_text, ")\n");
    if (r == 0)
        r = put(&cat_text, "   /ViewerPreferences << /DisplayDocTitle "
                           "true >>\n");
    if (r != 0 || alt_text.failed || cat_text.failed) {
        cf__buf_free(&alt_text);
        cf__buf_free(&cat_text);
        return -1;
    }
    /* the entries, sorted by where they go */
    ins[nins++] = (insert_t){ (size_t)(cat - data) + strlen(CATALOG),
                              &cat_text };
    for (p = data; nins < MAX_INSERTS && (p = find(p, x, FIGURE)) != NULL;
         p++)
        ins[nins++] = (insert_t){ (size_t)(p - data) + strlen(FIGURE),
                                  &alt_text };
    for (size_t i = 1; i < nins; i++)
        for (size_t k = i; k > 0 && ins[k - 1].at > ins[k].at; k--) {
            insert_t t = ins[k];
            ins[k] = ins[k - 1];
            ins[k - 1] = t;
        }
    if (nins < 2) {
        /* no Figure element: untagged */
        r = 1;
    } else {
        r = rewrite(pdf, ins, nins, x, first, count, sx0, sx1, out);
        if (r != 0)
            cf__buf_free(out);
    }
    cf__buf_free(&alt_text);
    cf__buf_free(&cat_text);
    return r;
}

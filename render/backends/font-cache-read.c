/*
** The fonts' metadata cache read (render/backends/font-cache.h): its
** bytes are untrusted (the file is the user's, anything may have been
** written there), so every length, offset, count, name and number is
** checked before it is used, the entries' structure at once and an
** entry's faces when the entry is used (cf__fcache_get_face, _skip_face)
** or, for cf__fcache_check, all of them; a directory record is checked
** against the entries it names (in range, consecutive, each a file
** directly in the directory, in the walk's order), so that a directory
** taken from the cache gives the files its walk would.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "font-cache-private.h"
#include "font-cache.h"



static double
get_f64(rd_t *r)
{
    uint64_t v = get_uint(r, 8);
    double d;
    memcpy(&d, &v, 8);
    return d;
}

/* Whether a[0..n) and b[0..n) are the same, ASCII case ignored (as
** cf__fmeta_same_ci compares). */
static bool
strncasecmp_ascii(const unsigned char *a, const char *b, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        unsigned char x = a[i], y = (unsigned char)b[i];
        if (x >= 'A' && x <= 'Z')
            x = (unsigned char)(x - 'A' + 'a');
        if (y >= 'A' && y <= 'Z')
            y = (unsigned char)(y - 'A' + 'a');
        if (x != y)
            return false;
    }
    return true;
}

/* A string of at most cap - 1 bytes, no NUL in it, into dst. */
static void
get_str8(rd_t *r, char *dst, size_t cap)
{
    size_t n = (size_t)get_uint(r, 1);
    const unsigned char *p = take(r, n);
    if (p == NULL || n >= cap || memchr(p, 0, n) != NULL) {
        r->bad = true;
        dst[0] = '\0';
        return;
    }
    memcpy(dst, p, n);
    dst[n] = '\0';
}

static bool
plausible(double v, double lo, double hi)
{
    return isfinite(v) && v >= lo && v <= hi;
}

/* One face: its fields checked, its ranges' bytes in bounds and *view
** (m->nranges pairs, m->ranges NULL), and when check the ranges
** themselves (cf__fm_ranges_valid; else when the face's coverage is
** first used: cf__fm_font_t).  0, or 1 (damaged). */
int
cf__fcache_get_face(rd_t *r, cf__fmeta_t *m, cf__flangset_t *ls,
         const unsigned char **view, bool check)
{
    size_t i, n, nl = cf__flangs_count();
    unsigned flags;
    const unsigned char *p;
    /* the fields set one by one: the names past nfamily are not read */
    m->ranges = NULL;
    m->nranges = 0;
    *view = NULL;
    m->index = (unsigned)get_uint(r, 4);
    m->nfamily = (unsigned)get_uint(r, 1);
    if (m->nfamily < 1 || m->nfamily > CF__FMETA_NAMES)
        r->bad = true;
    for (i = 0; i < m->nfamily && !r->bad; i++) {
        get_str8(r, m->family[i], sizeof m->family[i]);
        get_str8(r, m->familylang[i], sizeof m->familylang[i]);
    }
    get_str8(r, m->psname, sizeof m->psname);
    m->slant = (int)(int32_t)get_uint(r, 4);
    m->weight = get_f64(r);
    m->width = get_f64(r);
    flags = (unsigned)get_uint(r, 1);
    m->decorative = flags & 1;
    m->cff = flags & 2;
    m->has_codepages = flags & 4;
    m->has_size = flags & 8;
    m->size_lo = get_f64(r);
    m->size_hi = get_f64(r);
    m->fontversion = (int32_t)get_uint(r, 4);
    m->codepages[0] = (uint32_t)get_uint(r, 4);
    m->codepages[1] = (uint32_t)get_uint(r, 4);
    for (i = 0; i < 8; i++)
        ls->bits[i] = (uint32_t)get_uint(r, 4);
    n = (size_t)get_uint(r, 4);
    if (r->bad || m->index > 0xffff || flags > 15
        || (m->slant != CF__FMETA_SLANT_ROMAN
            && m->slant != CF__FMETA_SLANT_ITALIC
            && m->slant != CF__FMETA_SLANT_OBLIQUE)
        || !plausible(m->weight, 0, 1000) || !plausible(m->width, 0, 1000)
        || !plausible(m->size_lo, 0, 4000) || !plausible(m->size_hi, 0, 4000)
        || n > (r->len - r->pos) / 8 || (n == 0 && r->ranges == NULL)) {
        r->bad = true;
        return 1;
    }
    for (i = nl; i < 256; i++)
        if (ls->bits[i / 32] >> (i % 32) & 1) {
            r->bad = true;
            return 1;
        }
    if (n == 0) {
        /* the previous face's, checked when it was read */
        *view = r->ranges;
        m->nranges = r->nranges;
        return 0;
    }
    if ((p = take(r, 8 * n)) == NULL)
        return 1;
    if (check && !cf__fm_ranges_valid(p, n)) {
        r->bad = true;
        return 1;
    }
    r->ranges = *view = p;
    r->nranges = m->nranges = n;
    return 0;
}

/* Whether the face at r's position has one of the accepted families
** accept[0..n-1] (of lengths alen[]), read from its bytes (r's position
** unchanged; false when they are damaged: cf__fcache_get_face then says
** so). */
bool
cf__fcache_face_accepted(const rd_t *r, const char *const *accept,
                         const size_t *alen, size_t n)
{
    rd_t q = *r;
    size_t i, k, nf;
    q.pos += 4;
    nf = (size_t)get_uint(&q, 1);
    for (i = 0; i < nf && !q.bad; i++) {
        size_t len = (size_t)get_uint(&q, 1);
        const unsigned char *name = take(&q, len);
        if (name == NULL)
            return false;
        for (k = 0; k < n; k++)
            if (alen[k] == len && strncasecmp_ascii(name, accept[k], len))
                return true;
        take(&q, (size_t)get_uint(&q, 1));   /* its language */
    }
    return false;
}

/* A face not accepted: its bytes skipped, their structure checked (the
** families' and name's lengths, the ranges' count and bounds); 0, or 1
** (damaged). */
int
cf__fcache_skip_face(rd_t *r)
{
    size_t i, nf, n;
    const unsigned char *p;
    r->pos += 4;
    nf = (size_t)get_uint(r, 1);
    if (nf < 1 || nf > CF__FMETA_NAMES)
        r->bad = true;
    for (i = 0; i < 2 * nf + 1 && !r->bad; i++)
        take(r, (size_t)get_uint(r, 1));
    /* slant to the languages: 4 + 8 + 8 + 1 + 16 + 4 + 8 + 32 bytes */
    take(r, 81);
    n = (size_t)get_uint(r, 4);
    if (r->bad || (n == 0 && r->ranges == NULL)) {
        r->bad = true;
        return 1;
    }
    if (n == 0)
        return 0;
    if ((p = take(r, 8 * n)) == NULL)
        return 1;
    r->ranges = p;
    r->nranges = n;
    return 0;
}

/* The entries of r's cache, n of them, into e[0..n); false when one is
** damaged. */
static bool
get_entries(rd_t *ro, entry_t *e, size_t n, bool strict)
{
    rd_t r = *ro;
    const unsigned char *data = r.p;
    size_t len = r.len, i;
    for (i = 0; i < n; i++) {
        size_t start = r.pos, elen = (size_t)get_uint(&r, 4), k;
        rd_t er;
        if (r.bad || elen < 4 || !cf__ff_fits(start, elen, len))
            break;
        er.p = data + start;
        er.len = elen;
        er.pos = 4;
        er.bad = false;
        er.ranges = NULL;
        er.nranges = 0;
        e[i].blob = data + start;
        e[i].blob_len = elen;
        e[i].used = false;
        e[i].path_len = (size_t)get_uint(&er, 2);
        e[i].path = (const char *)take(&er, e[i].path_len);
        e[i].size = get_uint(&er, 8);
        e[i].sec = (int64_t)get_uint(&er, 8);
        e[i].nsec = (uint32_t)get_uint(&er, 4);
        e[i].status = (unsigned)get_uint(&er, 1);
        e[i].nfaces = 0;
        if (er.bad || e[i].path_len == 0
            || memchr(e[i].path, 0, e[i].path_len) != NULL
            || e[i].nsec >= 1000000000u || e[i].status > ST_NOT_FONT)
            break;
        if (e[i].status == ST_FACES) {
            e[i].nfaces = (unsigned)get_uint(&er, 2);
            e[i].faces_at = er.pos;
            if (e[i].nfaces == 0)
                break;
            for (k = 0; k < e[i].nfaces && !er.bad && strict; k++) {
                cf__fmeta_t m;
                cf__flangset_t ls;
                const unsigned char *view;
                cf__fcache_get_face(&er, &m, &ls, &view, true);
            }
            if (!strict)
                er.pos = elen;   /* its faces read when it is used */
        } else if (e[i].status == ST_REFUSED) {
            size_t wl = (size_t)get_uint(&er, 2);
            e[i].faces_at = er.pos;
            take(&er, wl);
        }
        if (er.bad || er.pos != elen)
            break;
        r.pos = start + elen;
    }
    ro->pos = r.pos;
    return i == n;
}

/* Whether a[0..al) comes before b[0..bl) as strcmp orders them (neither
** holds a NUL). */
static bool
path_before(const char *a, size_t al, const char *b, size_t bl)
{
    int c = memcmp(a, b, al < bl ? al : bl);
    return c < 0 || (c == 0 && al < bl);
}

/* Whether entry e is a file the walk of directory d lists: "d/name",
** name not empty, no dot file, no slash in it. */
static bool
in_dir(const entry_t *e, const dirrec_t *d)
{
    size_t dl = d->path_len;
    return e->path_len > dl + 1 && memcmp(e->path, d->path, dl) == 0
           && e->path[dl] == '/' && e->path[dl + 1] != '.'
           && memchr(e->path + dl + 1, '/', e->path_len - dl - 1) == NULL;
}

/* One directory record at r's position into *d, checked against the
** entries e[0..n) and the records before it, d[-k] for k in 1..nbefore
** (its run right after theirs, its path not theirs); false when
** damaged. */
static bool
get_dir(rd_t *r, const entry_t *e, size_t n, dirrec_t *d, size_t nbefore)
{
    size_t k, end = nbefore > 0 ? d[-1].first + d[-1].count : 0;
    unsigned flags;
    d->path_len = (size_t)get_uint(r, 2);
    d->path = (const char *)take(r, d->path_len);
    d->sec = (int64_t)get_uint(r, 8);
    d->nsec = (uint32_t)get_uint(r, 4);
    flags = (unsigned)get_uint(r, 1);
    d->settled = flags == 1;
    d->first = (size_t)get_uint(r, 4);
    d->count = (size_t)get_uint(r, 4);
    if (r->bad || d->path_len == 0
        || memchr(d->path, 0, d->path_len) != NULL
        || d->nsec >= 1000000000u || flags > 1 || d->first != end
        || d->first > n || d->count > n - d->first)
        return false;
    for (k = 1; k <= nbefore; k++)
        if (d[-(ptrdiff_t)k].path_len == d->path_len
            && memcmp(d[-(ptrdiff_t)k].path, d->path, d->path_len) == 0)
            return false;   /* a directory twice */
    for (k = d->first; k < d->first + d->count; k++)
        if (!in_dir(&e[k], d)
            || (k > d->first
                && !path_before(e[k - 1].path, e[k - 1].path_len,
                                e[k].path, e[k].path_len)))
            return false;
    return true;
}

long
cf__fcache_parse(const unsigned char *data, size_t len, parsed_t *out,
                 bool *oom, bool strict)
{
    rd_t r = { data, len, 0, false, NULL, 0 };
    size_t n, nd, i;
    entry_t *e;
    memset(out, 0, sizeof *out);
    *oom = false;
    if (data == NULL || len < CF__FCACHE_HEADER || len > CF__FCACHE_MAX
        || memcmp(data, CF__FCACHE_MAGIC, 8) != 0)
        return -1;
    r.pos = 8;
    if (get_uint(&r, 4) != CF__FCACHE_VERSION
        || get_uint(&r, 4) != cf__flangs_count())
        return -1;
    n = (size_t)get_uint(&r, 4);
    nd = (size_t)get_uint(&r, 4);
    if (get_uint(&r, 4) != len || n > len / 16
        || nd > len / CF__FCACHE_MIN_DIR)
        return -1;
    /* the entries, then the records: one allocation */
    e = cf_alloc_array(n + nd + 1,
                       sizeof(entry_t) > sizeof(dirrec_t) ? sizeof(entry_t)
                                                         : sizeof(dirrec_t));
    if (e == NULL) {
        *oom = true;
        return -1;
    }
    out->entries = e;
    out->dirs = (dirrec_t *)(void *)(e + n);
    if (!get_entries(&r, e, n, strict))
        goto damaged;
    for (i = 0; i < nd; i++)
        if (!get_dir(&r, e, n, &out->dirs[i], i))
            goto damaged;
    /* the runs cover the entries: every file is its directory's (a run
    ** one file short, a file of the cache no walk finds) */
    if (r.pos != len
        || (nd > 0 ? out->dirs[nd - 1].first + out->dirs[nd - 1].count : 0)
               != n)
        goto damaged;
    out->n = n;
    out->ndirs = nd;
    return (long)n;
damaged:
    cf_free(e);
    memset(out, 0, sizeof *out);
    return -1;
}

long
cf__fcache_check(const unsigned char *data, size_t len)
{
    parsed_t p;
    bool oom;
    long n = cf__fcache_parse(data, len, &p, &oom, true);
    cf_free(p.entries);
    return n;
}

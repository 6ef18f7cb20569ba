/*
** The fonts' metadata cache (render/backends/font-cache.h): the font
** directories walked as fontconfig walks them (files sorted, dot files
** skipped), each file's faces taken from the cache when its path, size
** and modification time are the cache's, else read (render/fontfile/
** fontmeta.h, fontlangs.h); the cache written anew when any was read or
** went away.  The cache is mapped, not copied: a run with a warm cache
** decodes only the accepted faces' fields, and their charsets are views
** of the mapping that the configuration keeps (checked at their first
** use: font-match.c), so that reading it costs a small part of a render
** (markova-2.17: 0.29 M instructions, of 8.6 M).
*/
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "buffer.h"
#include "curvefig/core.h"
#include "font-cache.h"
#include "grow.h"
#include "sfnt.h"

#define MAGIC "CFFACES"            /* with its NUL: 8 bytes */
#define VERSION 1u
#define HEADER 24u
#define MAX_CACHE (64u << 20)
#define FILE_NAME "faces.cache"

enum { ST_FACES = 0, ST_REFUSED = 1, ST_NOT_FONT = 2 };

/* ---- bytes out ---------------------------------------------------------- */

static void
put(cf__buf_t *b, const void *p, size_t n)
{
    cf__buf_append(b, p, n);   /* b->failed kept */
}

static void
put_uint(cf__buf_t *b, uint64_t v, int n)
{
    unsigned char t[8];
    int i;
    for (i = 0; i < n; i++)
        t[i] = (unsigned char)(v >> (8 * i));
    put(b, t, (size_t)n);
}

static void
put_f64(cf__buf_t *b, double d)
{
    uint64_t v;
    memcpy(&v, &d, 8);
    put_uint(b, v, 8);
}

static void
put_str8(cf__buf_t *b, const char *s)
{
    size_t n = strlen(s);
    put_uint(b, n, 1);
    put(b, s, n);
}

/* One face of a file; prev: the file's face before it (NULL for the
** first), whose ranges it refers to when they are the same (a count of
** 0: the faces of a collection mostly share their cmap). */
static void
put_face(cf__buf_t *b, const cf__fmeta_t *m, const cf__flangset_t *ls,
         const cf__fmeta_t *prev)
{
    unsigned i;
    put_uint(b, m->index, 4);
    put_uint(b, m->nfamily, 1);
    for (i = 0; i < m->nfamily; i++) {
        put_str8(b, m->family[i]);
        put_str8(b, m->familylang[i]);
    }
    put_str8(b, m->psname);
    put_uint(b, (uint32_t)m->slant, 4);
    put_f64(b, m->weight);
    put_f64(b, m->width);
    put_uint(b, (m->decorative ? 1u : 0) | (m->cff ? 2u : 0)
                    | (m->has_codepages ? 4u : 0) | (m->has_size ? 8u : 0),
             1);
    put_f64(b, m->size_lo);
    put_f64(b, m->size_hi);
    put_uint(b, (uint32_t)m->fontversion, 4);
    put_uint(b, m->codepages[0], 4);
    put_uint(b, m->codepages[1], 4);
    for (i = 0; i < 8; i++)
        put_uint(b, ls->bits[i], 4);
    if (prev != NULL && prev->nranges == m->nranges
        && memcmp(prev->ranges, m->ranges,
                  2 * m->nranges * sizeof *m->ranges) == 0) {
        put_uint(b, 0, 4);
        return;
    }
    put_uint(b, m->nranges, 4);
    for (i = 0; i < 2 * m->nranges; i++)
        put_uint(b, m->ranges[i], 4);
}

/* ---- bytes in ----------------------------------------------------------- */

typedef struct rd {
    const unsigned char *p;
    size_t len, pos;
    bool bad;
    const unsigned char *ranges;   /* the entry's last face's ranges (a */
    size_t nranges;                /* count of 0 refers to them) */
} rd_t;

static const unsigned char *
take(rd_t *r, size_t n)
{
    const unsigned char *p;
    if (r->bad || !cf__ff_fits(r->pos, n, r->len)) {
        r->bad = true;
        return NULL;
    }
    p = r->p + r->pos;
    r->pos += n;
    return p;
}

static inline uint64_t
get_uint(rd_t *r, int n)
{
    const unsigned char *p;
    uint64_t v = 0;
    int i;
    if (r->bad || !cf__ff_fits(r->pos, (size_t)n, r->len)) {
        r->bad = true;
        return 0;
    }
    p = r->p + r->pos;
    r->pos += (size_t)n;
    for (i = n - 1; i >= 0; i--)
        v = v << 8 | p[i];
    return v;
}

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
static int
get_face(rd_t *r, cf__fmeta_t *m, cf__flangset_t *ls,
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
** unchanged; false when they are damaged: get_face then says so). */
static bool
face_accepted(const rd_t *r, const char *const *accept, const size_t *alen,
              size_t n)
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
static int
skip_face(rd_t *r)
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

/* One entry of the cache, its fields found (the faces not decoded). */
typedef struct entry {
    const unsigned char *blob;   /* the whole entry */
    size_t blob_len;
    const char *path;            /* not NUL-terminated */
    size_t path_len;
    uint64_t size;
    int64_t sec;
    uint32_t nsec;
    unsigned status, nfaces;
    size_t faces_at;             /* in blob */
    bool used;
} entry_t;

/* The entries of the cache data[0..len) into *out (cf_free'd), each
** entry's fields checked, and when strict its faces (else each face is
** checked when the entry is used); their number, or -1 (damaged, or out
** of memory: *oom). */
static long
parse(const unsigned char *data, size_t len, entry_t **out, bool *oom,
      bool strict)
{
    rd_t r = { data, len, 0, false, NULL, 0 };
    size_t n, i;
    entry_t *e;
    *out = NULL;
    *oom = false;
    if (data == NULL || len < HEADER || len > MAX_CACHE
        || memcmp(data, MAGIC, 8) != 0)
        return -1;
    r.pos = 8;
    if (get_uint(&r, 4) != VERSION || get_uint(&r, 4) != cf__flangs_count())
        return -1;
    n = (size_t)get_uint(&r, 4);
    if (get_uint(&r, 4) != len || n > len / 16)
        return -1;
    e = cf_alloc_array(n + 1, sizeof *e);
    if (e == NULL) {
        *oom = true;
        return -1;
    }
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
                get_face(&er, &m, &ls, &view, true);
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
    if (i < n || r.pos != len) {
        cf_free(e);
        return -1;
    }
    *out = e;
    return (long)n;
}

long
cf__fcache_check(const unsigned char *data, size_t len)
{
    entry_t *e;
    bool oom;
    long n = parse(data, len, &e, &oom, true);
    cf_free(e);
    return n;
}

/* ---- the cache's directory and file ------------------------------------ */

bool
cf__fcache_path(char *buf, size_t cap)
{
    const char *x = getenv("XDG_CACHE_HOME"), *h = getenv("HOME");
    int n;
    if (x != NULL && x[0] == '/')
        n = snprintf(buf, cap, "%s/curvefig/" FILE_NAME, x);
    else if (h != NULL && h[0] == '/')
        n = snprintf(buf, cap, "%s/.cache/curvefig/" FILE_NAME, h);
    else
        return false;
    return n > 0 && (size_t)n < cap;
}

/* The directory of the cache file at path, opened (made mode 0700 first
** when make and it is missing, and its parent too): -1 when it is not
** one of the user's own, private and real. */
static int
open_dir(const char *path, bool make)
{
    char dir[4096];
    char *slash;
    struct stat st;
    int fd;
    if (strlen(path) >= sizeof dir)
        return -1;
    strcpy(dir, path);
    slash = strrchr(dir, '/');
    if (slash == NULL || slash == dir)
        return -1;
    *slash = '\0';
    if (make && mkdir(dir, 0700) != 0 && errno == ENOENT) {
        /* its parent (~/.cache) first */
        char *up = strrchr(dir, '/');
        if (up != NULL && up != dir) {
            *up = '\0';
            (void)mkdir(dir, 0700);
            *up = '/';
        }
        (void)mkdir(dir, 0700);
    }
    fd = open(dir, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return -1;
    if (fstat(fd, &st) != 0 || !S_ISDIR(st.st_mode)
        || st.st_uid != geteuid() || (st.st_mode & 022) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

/* The cache file mapped (NULL: none, or not a file of the user's). */
static void *
map_cache(int dfd, size_t *len)
{
    struct stat st;
    void *m;
    int fd = openat(dfd, FILE_NAME,
                    O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    *len = 0;
    if (fd < 0)
        return NULL;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)
        || st.st_uid != geteuid() || st.st_size < (off_t)HEADER
        || st.st_size > (off_t)MAX_CACHE) {
        close(fd);
        return NULL;
    }
    m = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (m == MAP_FAILED)
        return NULL;
    *len = (size_t)st.st_size;
    return m;
}

static void
random_name(char *out)
{
    static const char digits[] =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_";
    unsigned char b[12];
    size_t i;
    if (getrandom(b, sizeof b, GRND_NONBLOCK) != (ssize_t)sizeof b) {
        struct timespec ts;
        uint64_t v;
        clock_gettime(CLOCK_MONOTONIC, &ts);
        v = (uint64_t)ts.tv_nsec * 6364136223846793005u
            ^ (uint64_t)getpid() << 32 ^ (uint64_t)ts.tv_sec;
        for (i = 0; i < sizeof b; i++)
            b[i] = (unsigned char)(v >> (5 * i % 64));
    }
    for (i = 0; i < sizeof b; i++)
        out[i] = digits[b[i] & 63];
    out[sizeof b] = '\0';
}

/* Write data as the cache file of dfd: a new file renamed over it. */
static void
write_cache(int dfd, const unsigned char *data, size_t n)
{
    char tmp[40];
    size_t off = 0;
    int fd = -1, tries;
    memcpy(tmp, ".faces-", 7);
    for (tries = 0; fd < 0 && tries < 100; tries++) {
        random_name(tmp + 7);
        fd = openat(dfd, tmp,
                    O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                    0600);
        if (fd < 0 && errno != EEXIST)
            return;
    }
    if (fd < 0)
        return;
    while (off < n) {
        ssize_t w = write(fd, data + off, n - off);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            break;
        off += (size_t)w;
    }
    if (close(fd) != 0 || off < n
        || renameat(dfd, tmp, dfd, FILE_NAME) != 0)
        unlinkat(dfd, tmp, 0);
}

/* ---- the walk ----------------------------------------------------------- */

/* An entry of the cache to write: an old one, or bytes of fresh. */
typedef struct piece {
    const entry_t *old;
    size_t at, len;
} piece_t;

typedef struct walk {
    const char *const *accept;
    size_t naccept;
    size_t *alen;                /* their lengths */
    entry_t *old;                /* the cache's entries */
    size_t nold, cursor;
    cf__buf_t fresh;             /* the entries of the files read now */
    piece_t *pieces;             /* the cache to write, entry by entry */
    size_t npieces, cap_pieces;
    bool changed;
    cf__fm_font_t *fonts;        /* the accepted faces */
    size_t nfonts, cap;
    cf__fm_mapped_t *mapped;     /* the cache, which their views are of */
    bool viewed;                 /* some are */
    char *why;
    size_t why_cap;
    bool refused;
} walk_t;

static bool
accepted(const walk_t *w, const cf__fmeta_t *m)
{
    return cf__fm_accepts(m, w->accept, w->naccept);
}

/* Add a face (whose ranges the list takes, or whose charset is view: a
** view of the cache's bytes) of file path to the list. */
static int
add_font(walk_t *w, const char *path, cf__fmeta_t *m,
         const cf__flangset_t *ls, const unsigned char *view)
{
    size_t n = strlen(path) + 1;
    cf__fm_font_t *f = cf__grow_array(w->fonts, &w->cap, w->nfonts + 1,
                                      sizeof *f, 64);
    if (f == NULL) {
        cf__fmeta_fini(m);
        return -1;
    }
    w->fonts = f;
    f = &w->fonts[w->nfonts];
    memset(f, 0, sizeof *f);
    f->file = cf_malloc(n);
    if (f->file == NULL) {
        cf__fmeta_fini(m);
        return -1;
    }
    memcpy(f->file, path, n);
    f->meta = *m;
    f->langs = *ls;
    f->view = view;
    if (view != NULL) {
        f->mapped = w->mapped;
        w->viewed = true;
    }
    w->nfonts++;
    return 0;
}

/* The cache's entry of path as it is now, or NULL. */
static entry_t *
cached(walk_t *w, const char *path, const struct stat *st)
{
    size_t len = strlen(path), k;
    for (k = 0; k < w->nold; k++) {
        entry_t *e = &w->old[(w->cursor + k) % w->nold];
        if (e->path_len == len && memcmp(e->path, path, len) == 0) {
            if (e->used || e->size != (uint64_t)st->st_size
                || e->sec != (int64_t)st->st_mtim.tv_sec
                || e->nsec != (uint32_t)st->st_mtim.tv_nsec)
                return NULL;
            w->cursor = (w->cursor + k + 1) % w->nold;
            return e;
        }
    }
    return NULL;
}

/* Room for one more piece; false when out of memory. */
static bool
piece_room(walk_t *w)
{
    piece_t *t = cf__grow_array(w->pieces, &w->cap_pieces, w->npieces + 1,
                                sizeof *t, 128);
    if (t != NULL)
        w->pieces = t;
    return t != NULL;
}

/* The faces of a cached entry: 0, -1 (out of memory), 2 when it is
** damaged (the file is then read again). */
static int
from_entry(walk_t *w, const char *path, entry_t *e)
{
    rd_t r = { e->blob, e->blob_len, e->faces_at, false, NULL, 0 };
    size_t first = w->nfonts;
    unsigned k;
    int got = 0;
    if (e->status == ST_REFUSED) {
        size_t n = (size_t)get_uint(&r, 2);
        snprintf(w->why, w->why_cap, "%s: %.*s", path, (int)n,
                 (const char *)take(&r, n));
        w->refused = true;
    }
    if (!piece_room(w))
        return -1;
    for (k = 0; k < e->nfaces && got == 0; k++) {
        cf__fmeta_t m;
        cf__flangset_t ls;
        const unsigned char *view;
        /* a face accepted decoded, its ranges checked when its
        ** coverage is first used; the others only skipped */
        if (!face_accepted(&r, w->accept, w->alen, w->naccept)) {
            got = skip_face(&r);
            continue;
        }
        got = get_face(&r, &m, &ls, &view, false);
        if (got == 0 && add_font(w, path, &m, &ls, view) != 0)
            got = -1;
    }
    if (got == 0 && e->status == ST_FACES && r.pos != e->blob_len)
        got = 1;
    if (got != 0) {
        /* the faces taken from it given back */
        while (w->nfonts > first) {
            w->nfonts--;
            cf_free(w->fonts[w->nfonts].file);
            cf__fmeta_fini(&w->fonts[w->nfonts].meta);
        }
        return got < 0 ? -1 : 2;
    }
    e->used = true;
    w->pieces[w->npieces].old = e;
    w->pieces[w->npieces].at = w->pieces[w->npieces].len = 0;
    w->npieces++;
    return 0;
}

static void
entry_head(cf__buf_t *b, const char *path, const struct stat *st,
           unsigned status)
{
    put_uint(b, 0, 4);   /* its length, set when done */
    put_uint(b, strlen(path), 2);
    put(b, path, strlen(path));
    put_uint(b, (uint64_t)st->st_size, 8);
    put_uint(b, (uint64_t)(int64_t)st->st_mtim.tv_sec, 8);
    put_uint(b, (uint64_t)st->st_mtim.tv_nsec, 4);
    put_uint(b, status, 1);
}

/* The faces of a file read now, and its entry written. */
static int
from_file(walk_t *w, const char *path, const struct stat *st)
{
    void *map;
    size_t len, start = w->fresh.size, i;
    int err, r = 0;
    unsigned count, id;
    const char *bad;
    char fwhy[256];
    cf__fmeta_t *ms;
    cf__flangset_t *ls;
    w->changed = true;
    if (strlen(path) > 0xffff)
        return 0;
    bad = cf__ff_map_file(path, &map, &len, &err);
    if (bad != NULL) {
        snprintf(w->why, w->why_cap, "%s: %s", path, bad);
        w->refused = true;
        return 0;
    }
    count = cf__fmeta_count(map, len);
    if (count == 0 && len >= 4
        && (memcmp(map, "wOFF", 4) == 0 || memcmp(map, "wOF2", 4) == 0)) {
        snprintf(fwhy, sizeof fwhy, "font: a WOFF font");
        count = 0;
        r = 1;
    }
    ms = cf_calloc(count + 1, sizeof *ms);
    ls = cf_calloc(count + 1, sizeof *ls);
    if (ms == NULL || ls == NULL)
        r = -1;
    for (id = 0; id < count && r == 0; id++) {
        r = cf__fmeta_read(map, len, id, &ms[id], fwhy, sizeof fwhy);
        if (r == 0)
            cf__flangs_of(&ms[id], &ls[id]);
    }
    if (map != NULL)
        munmap(map, len);
    if (r >= 0) {
        entry_head(&w->fresh, path, st, r > 0 ? ST_REFUSED
                                      : count == 0 ? ST_NOT_FONT : ST_FACES);
        if (r > 0) {
            /* "font: why" from the reader: the reason after its name */
            const char *why = strncmp(fwhy, "font: ", 6) == 0 ? fwhy + 6
                                                              : fwhy;
            put_uint(&w->fresh, strlen(why), 2);
            put(&w->fresh, why, strlen(why));
            snprintf(w->why, w->why_cap, "%s: %s", path, why);
            w->refused = true;
        } else if (count > 0) {
            put_uint(&w->fresh, count, 2);
            for (i = 0; i < count; i++)
                put_face(&w->fresh, &ms[i], &ls[i],
                         i > 0 ? &ms[i - 1] : NULL);
        }
        if (!w->fresh.failed && piece_room(w)) {
            size_t n = w->fresh.size - start;
            for (i = 0; i < 4; i++)
                w->fresh.data[start + i] = (unsigned char)(n >> (8 * i));
            w->pieces[w->npieces].old = NULL;
            w->pieces[w->npieces].at = start;
            w->pieces[w->npieces].len = n;
            w->npieces++;
        } else {
            r = -1;
        }
    }
    /* a refused file's faces are not the configuration's */
    for (i = 0; i < count && ms != NULL && ls != NULL; i++) {
        if (r == 0 && !w->refused && accepted(w, &ms[i])) {
            if (add_font(w, path, &ms[i], &ls[i], NULL) != 0)
                r = -1;
        } else {
            cf__fmeta_fini(&ms[i]);
        }
    }
    cf_free(ms);
    cf_free(ls);
    return r < 0 ? -1 : 0;
}

/* The cache of the walk's pieces written (the header first); -1 when
** out of memory. */
static int
write_pieces(walk_t *w, const char *cache, int *dfd)
{
    cf__buf_t out = { NULL, 0, 0, 0 };
    unsigned char h[HEADER];
    size_t i, total = HEADER;
    for (i = 0; i < w->npieces; i++)
        total += w->pieces[i].old != NULL ? w->pieces[i].old->blob_len
                                          : w->pieces[i].len;
    if (total > MAX_CACHE)
        return 0;
    memcpy(h, MAGIC, 8);
    for (i = 0; i < 4; i++) {
        h[8 + i] = (unsigned char)(VERSION >> (8 * i));
        h[12 + i] = (unsigned char)(cf__flangs_count() >> (8 * i));
        h[16 + i] = (unsigned char)(w->npieces >> (8 * i));
        h[20 + i] = (unsigned char)(total >> (8 * i));
    }
    put(&out, h, HEADER);
    for (i = 0; i < w->npieces; i++) {
        const piece_t *pc = &w->pieces[i];
        if (pc->old != NULL)
            put(&out, pc->old->blob, pc->old->blob_len);
        else
            put(&out, w->fresh.data + pc->at, pc->len);
    }
    if (out.failed) {
        cf__buf_free(&out);
        return -1;
    }
    if (*dfd < 0)
        *dfd = open_dir(cache, true);
    if (*dfd >= 0)
        write_cache(*dfd, out.data, out.size);
    cf__buf_free(&out);
    return 0;
}

static int
by_path(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* One directory's files, sorted, each from the cache or read. */
static int
walk_dir(walk_t *w, const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    cf__buf_t paths = { NULL, 0, 0, 0 };   /* "dir/name\0" each */
    size_t *at = NULL, dl = strlen(dir);
    char **names = NULL;
    size_t n = 0, cap = 0, i;
    int r = 0;
    if (d == NULL) {
        snprintf(w->why, w->why_cap, "%s: cannot be read", dir);
        w->refused = true;
        return 0;
    }
    while ((e = readdir(d)) != NULL) {
        size_t nl = strlen(e->d_name) + 1;
        size_t *t;
        if (e->d_name[0] == '.')
            continue;
        t = cf__grow_array(at, &cap, n + 1, sizeof *t, 64);
        if (t == NULL) {
            r = -1;
            break;
        }
        at = t;
        at[n++] = paths.size;
        put(&paths, dir, dl);
        put(&paths, "/", 1);
        put(&paths, e->d_name, nl);
    }
    closedir(d);
    if (r == 0 && (paths.failed
                   || (names = cf_alloc_array(n + 1, sizeof *names)) == NULL))
        r = -1;
    for (i = 0; i < n && r == 0; i++)
        names[i] = (char *)paths.data + at[i];
    if (r == 0 && n > 0)
        qsort(names, n, sizeof *names, by_path);
    for (i = 0; i < n && r == 0; i++) {
        struct stat st;
        entry_t *c;
        if (stat(names[i], &st) != 0) {
            w->changed = true;   /* gone since it was listed */
        } else if (S_ISDIR(st.st_mode)) {
            snprintf(w->why, w->why_cap, "%s: a subdirectory", names[i]);
            w->refused = true;
        } else if ((c = cached(w, names[i], &st)) != NULL
                   && (r = from_entry(w, names[i], c)) != 2) {
            ;
        } else {
            r = from_file(w, names[i], &st);
        }
    }
    cf_free(names);
    cf_free(at);
    cf__buf_free(&paths);
    return r;
}

int
cf__fcache_config(const cf__fm_source_t *dirs, size_t ndirs,
                  const char *const *accept, size_t naccept,
                  const char *cache, cf__fm_config_t **out, char *why,
                  size_t why_cap)
{
    walk_t w;
    char buf[512];
    void *map = NULL;
    size_t len = 0, d, i;
    int dfd = -1, r = 0;
    long nold;
    bool oom;
    *out = NULL;
    memset(&w, 0, sizeof w);
    w.accept = accept;
    w.naccept = naccept;
    w.why = why != NULL && why_cap > 0 ? why : buf;
    w.why_cap = why != NULL && why_cap > 0 ? why_cap : sizeof buf;
    w.why[0] = '\0';
    w.alen = cf_alloc_array(naccept + 1, sizeof *w.alen);
    if (w.alen == NULL)
        return -1;
    for (i = 0; i < naccept; i++)
        w.alen[i] = strlen(accept[i]);
    if (cache != NULL && (dfd = open_dir(cache, false)) >= 0)
        map = map_cache(dfd, &len);
    nold = parse(map, len, &w.old, &oom, false);
    if (oom)
        r = -1;
    if (map != NULL && r == 0) {
        /* kept by the configuration while its fonts' views are of it */
        w.mapped = cf_calloc(1, sizeof *w.mapped);
        if (w.mapped == NULL) {
            munmap(map, len);
            r = -1;
        } else {
            w.mapped->map = map;
            w.mapped->len = len;
            w.mapped->cache = strdup(cache);   /* NULL: not removed */
        }
    } else if (map != NULL) {
        munmap(map, len);
    }
    w.nold = nold > 0 ? (size_t)nold : 0;
    w.changed = nold < 0;
    /* the walk goes on after a refusal, so that the cache keeps it */
    for (d = 0; d < ndirs && r == 0; d++) {
        struct stat st;
        if (stat(dirs[d].dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
            if (dirs[d].required) {
                snprintf(w.why, w.why_cap, "%s: no such directory",
                         dirs[d].dir);
                w.refused = true;
            }
            continue;
        }
        r = walk_dir(&w, dirs[d].dir);
    }
    for (i = 0; i < w.nold; i++)
        if (!w.old[i].used)
            w.changed = true;   /* a file gone */
    /* written whole: a walk stopped by a refusal is not */
    if (r == 0 && w.changed && cache != NULL)
        r = write_pieces(&w, cache, &dfd);
    cf__buf_free(&w.fresh);
    cf_free(w.pieces);
    cf_free(w.old);
    cf_free(w.alen);
    if (dfd >= 0)
        close(dfd);
    if (r != 0 || w.refused) {
        for (i = 0; i < w.nfonts; i++) {
            cf_free(w.fonts[i].file);
            cf__fmeta_fini(&w.fonts[i].meta);
        }
        cf_free(w.fonts);
        cf__fm_mapped_free(w.mapped);
        return r != 0 ? r : 1;
    }
    r = cf__fm_config_of(w.fonts, w.nfonts, accept, naccept, out, why,
                         why_cap);
    cf_free(w.fonts);
    if (r == 0 && w.viewed)
        cf__fm_config_keep(*out, w.mapped);
    else
        cf__fm_mapped_free(w.mapped);
    return r;
}

/*
** The fonts' metadata cache (render/backends/font-cache.h), its walk and
** its writing (its reading: font-cache-read.c): each font directory
** stat'ed, and taken from its record in the cache when its time is the
** record's and the record settled (fontconfig's rule: a file added,
** removed or renamed changes its directory's time), else walked as
** fontconfig walks it (files sorted, dot files skipped), each file's
** faces taken from the cache when its path, size and modification time
** are the cache's, else read (render/fontfile/fontmeta.h, fontlangs.h);
** the cache written anew when any was read or went away, or a
** directory's record changed.  The cache is mapped, not copied: a run
** with a warm cache decodes only the accepted faces' fields, and their
** charsets are views of the mapping that the configuration keeps
** (checked at their first use, with the file's size and time for a font
** of a directory taken from its record: font-match.c), so that reading
** it costs a small part of a render (markova-2.17: 0.29 M instructions,
** of 8.6 M) and a warm run one stat a directory.
*/
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
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
#include "font-cache-private.h"
#include "font-cache.h"
#include "grow.h"
#include "sfnt.h"

#define FILE_NAME CF__FCACHE_FILE

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
        || st.st_uid != geteuid()
        || st.st_size < (off_t)CF__FCACHE_HEADER
        || st.st_size > (off_t)CF__FCACHE_MAX) {
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
    parsed_t old;                /* the cache's entries and directories */
    size_t cursor;
    struct timespec now;         /* when the walk began */
    cf__buf_t fresh;             /* the entries of the files read now */
    piece_t *pieces;             /* the cache to write, entry by entry */
    size_t npieces, cap_pieces;
    dirrec_t *dirs;              /* and its directory records (their */
    size_t ndirs, cap_dirs;      /* paths the caller's) */
    bool changed;
    bool unwritable;             /* a directory the cache cannot record */
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
    size_t len = strlen(path), k, n = w->old.n;
    for (k = 0; k < n; k++) {
        entry_t *e = &w->old.entries[(w->cursor + k) % n];
        if (e->path_len == len && memcmp(e->path, path, len) == 0) {
            if (e->used || e->size != (uint64_t)st->st_size
                || e->sec != (int64_t)st->st_mtim.tv_sec
                || e->nsec != (uint32_t)st->st_mtim.tv_nsec)
                return NULL;
            w->cursor = (w->cursor + k + 1) % n;
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

/* The faces taken from a file since the list had first of them given
** back. */
static void
drop_fonts(walk_t *w, size_t first)
{
    while (w->nfonts > first) {
        w->nfonts--;
        cf_free(w->fonts[w->nfonts].file);
        cf__fmeta_fini(&w->fonts[w->nfonts].meta);
    }
}

/* The faces of a cached entry: 0, -1 (out of memory), 2 when it is
** damaged (the file is then read again).  unseen: the file was not
** looked at (its directory is the cache's), so that its faces carry the
** cache's size and time, compared with the file's when one is used
** (cf__fm_font_verify). */
static int
from_entry(walk_t *w, const char *path, entry_t *e, bool unseen)
{
    rd_t r = { e->blob, e->blob_len, e->faces_at, false, NULL, 0 };
    size_t first = w->nfonts, i;
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
        if (!cf__fcache_face_accepted(&r, w->accept, w->alen, w->naccept)) {
            got = cf__fcache_skip_face(&r);
            continue;
        }
        got = cf__fcache_get_face(&r, &m, &ls, &view, false);
        if (got == 0 && add_font(w, path, &m, &ls, view) != 0)
            got = -1;
    }
    if (got == 0 && e->status == ST_FACES && r.pos != e->blob_len)
        got = 1;
    if (got != 0) {
        drop_fonts(w, first);
        return got < 0 ? -1 : 2;
    }
    for (i = first; i < w->nfonts && unseen; i++) {
        w->fonts[i].unverified = true;
        w->fonts[i].size = e->size;
        w->fonts[i].sec = e->sec;
        w->fonts[i].nsec = e->nsec;
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

/* The header, of a cache of n entries and nd directory records, total
** bytes long. */
static void
put_header(cf__buf_t *b, size_t n, size_t nd, size_t total)
{
    put(b, CF__FCACHE_MAGIC, 8);
    put_uint(b, CF__FCACHE_VERSION, 4);
    put_uint(b, cf__flangs_count(), 4);
    put_uint(b, n, 4);
    put_uint(b, nd, 4);
    put_uint(b, total, 4);
}

static void
put_dir(cf__buf_t *b, const dirrec_t *d)
{
    put_uint(b, d->path_len, 2);
    put(b, d->path, d->path_len);
    put_uint(b, (uint64_t)d->sec, 8);
    put_uint(b, d->nsec, 4);
    put_uint(b, d->settled ? 1 : 0, 1);
    put_uint(b, d->first, 4);
    put_uint(b, d->count, 4);
}

/* The cache of the walk's pieces and directory records written (the
** header first); -1 when out of memory. */
static int
write_pieces(walk_t *w, const char *cache, int *dfd)
{
    cf__buf_t out = { NULL, 0, 0, 0 };
    size_t i, total = CF__FCACHE_HEADER;
    for (i = 0; i < w->npieces; i++)
        total += w->pieces[i].old != NULL ? w->pieces[i].old->blob_len
                                          : w->pieces[i].len;
    for (i = 0; i < w->ndirs; i++)
        total += CF__FCACHE_MIN_DIR - 1 + w->dirs[i].path_len;
    if (total > CF__FCACHE_MAX)
        return 0;
    put_header(&out, w->npieces, w->ndirs, total);
    for (i = 0; i < w->npieces; i++) {
        const piece_t *pc = &w->pieces[i];
        if (pc->old != NULL)
            put(&out, pc->old->blob, pc->old->blob_len);
        else
            put(&out, w->fresh.data + pc->at, pc->len);
    }
    for (i = 0; i < w->ndirs; i++)
        put_dir(&out, &w->dirs[i]);
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

/* One file of a directory: from known (its entry in the cache's record
** of the directory, the file not looked at) when given and whole, else
** as the walk finds it: from its entry when its size and time are the
** cache's, else read.  *whole set false when the file gives the cache no
** entry (gone since it was listed, a subdirectory, unreadable): the
** directory's record is then not settled, so that the next run walks it
** and finds the same. */
static int
one_file(walk_t *w, const char *path, entry_t *known, bool *whole)
{
    struct stat st;
    entry_t *c;
    size_t before = w->npieces;
    int r = 0;
    if (known != NULL && !known->used
        && (r = from_entry(w, path, known, true)) != 2)
        return r;
    if (stat(path, &st) != 0) {
        w->changed = true;   /* gone since it was listed */
    } else if (S_ISDIR(st.st_mode)) {
        snprintf(w->why, w->why_cap, "%s: a subdirectory", path);
        w->refused = true;
    } else if ((c = cached(w, path, &st)) != NULL
               && (r = from_entry(w, path, c, false)) != 2) {
        ;
    } else {
        r = from_file(w, path, &st);
    }
    if (w->npieces == before)
        *whole = false;
    return r;
}

/* A directory's files as its record in the cache has them, none looked
** at (the directory's time is the record's). */
static int
from_record(walk_t *w, const dirrec_t *d, bool *whole)
{
    size_t k, longest = 0;
    char *path;
    int r = 0;
    for (k = d->first; k < d->first + d->count; k++)
        if (w->old.entries[k].path_len > longest)
            longest = w->old.entries[k].path_len;
    if ((path = cf_malloc(longest + 1)) == NULL)
        return -1;
    for (k = d->first; k < d->first + d->count && r == 0; k++) {
        entry_t *e = &w->old.entries[k];
        memcpy(path, e->path, e->path_len);
        path[e->path_len] = '\0';
        r = one_file(w, path, e, whole);
    }
    cf_free(path);
    return r;
}

static int
by_path(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* One directory's files listed and sorted (dot files skipped), each
** from the cache or read. */
static int
walk_dir(walk_t *w, const char *dir, bool *whole)
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
        *whole = false;
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
    for (i = 0; i < n && r == 0; i++)
        r = one_file(w, names[i], NULL, whole);
    cf_free(names);
    cf_free(at);
    cf__buf_free(&paths);
    return r;
}

/* The cache's record of directory dir, or NULL. */
static const dirrec_t *
old_dir(const walk_t *w, const char *dir)
{
    size_t k, n = strlen(dir);
    for (k = 0; k < w->old.ndirs; k++)
        if (w->old.dirs[k].path_len == n
            && memcmp(w->old.dirs[k].path, dir, n) == 0)
            return &w->old.dirs[k];
    return NULL;
}

/* Whether a directory of time t is settled at the walk's time: 2 s or
** more before it, so that a file added since (at the walk's time or
** later) has given the directory another time even where a file
** system's times are coarse (FAT's are 2 s). */
static bool
settled(const walk_t *w, const struct timespec *t)
{
    int64_t s = (int64_t)w->now.tv_sec - (int64_t)t->tv_sec;
    return s > 2 || (s == 2 && w->now.tv_nsec >= t->tv_nsec);
}

static bool
same_record(const dirrec_t *a, const dirrec_t *b)
{
    return a->sec == b->sec && a->nsec == b->nsec
           && a->settled == b->settled && a->first == b->first
           && a->count == b->count;
}

/* The record of a directory walked now, and whether the cache's differs
** (the cache is then written anew).  A directory named twice is no
** cache's: the records' runs cover every entry once (font-cache-read.c),
** and its second walk's entries are its first's again. */
static int
add_dir(walk_t *w, const dirrec_t *rec, const dirrec_t *old)
{
    dirrec_t *t;
    size_t k;
    if (old == NULL || !same_record(old, rec))
        w->changed = true;
    for (k = 0; k < w->ndirs; k++)
        if (w->dirs[k].path_len == rec->path_len
            && memcmp(w->dirs[k].path, rec->path, rec->path_len) == 0) {
            w->unwritable = true;
            return 0;
        }
    t = cf__grow_array(w->dirs, &w->cap_dirs, w->ndirs + 1, sizeof *t, 8);
    if (t == NULL)
        return -1;
    w->dirs = t;
    w->dirs[w->ndirs++] = *rec;
    return 0;
}

/* One font directory (st: its stat): from the cache's record when the
** record is settled and the directory's time is the record's (fontconfig
** revalidates its caches so: a file added, removed or renamed changes
** its directory's time), else walked. */
static int
from_dir(walk_t *w, const char *dir, const struct stat *st)
{
    const dirrec_t *old = old_dir(w, dir);
    dirrec_t rec;
    bool whole = true;
    int r;
    rec.path = dir;
    rec.path_len = strlen(dir);
    rec.sec = (int64_t)st->st_mtim.tv_sec;
    rec.nsec = (uint32_t)st->st_mtim.tv_nsec;
    rec.first = w->npieces;
    if (rec.path_len > 0xffff) {
        w->unwritable = true;   /* no record of it: no cache */
        return walk_dir(w, dir, &whole);
    }
    if (old != NULL && old->settled && old->sec == rec.sec
        && old->nsec == rec.nsec)
        r = from_record(w, old, &whole);
    else
        r = walk_dir(w, dir, &whole);
    if (r != 0)
        return r;
    rec.count = w->npieces - rec.first;
    rec.settled = whole && settled(w, &st->st_mtim);
    return add_dir(w, &rec, old);
}

/* The walk's lists freed; its fonts too when they are not the
** configuration's (fonts). */
static void
walk_fini(walk_t *w, bool fonts)
{
    cf__buf_free(&w->fresh);
    cf_free(w->pieces);
    cf_free(w->dirs);
    cf_free(w->old.entries);
    cf_free(w->alen);
    if (fonts) {
        drop_fonts(w, 0);
        cf_free(w->fonts);
        cf__fm_mapped_free(w->mapped);
    }
}

/* The cache file at cache mapped (map NULL: none or not the user's),
** kept by the walk's mapped; -1 when out of memory. */
static int
open_cache(walk_t *w, const char *cache, int *dfd)
{
    void *map = NULL;
    size_t len = 0;
    long n;
    bool oom;
    if (cache != NULL && (*dfd = open_dir(cache, false)) >= 0)
        map = map_cache(*dfd, &len);
    n = cf__fcache_parse(map, len, &w->old, &oom, false);
    w->changed = n < 0;
    if (map == NULL)
        return oom ? -1 : 0;
    if (!oom) {
        /* kept by the configuration while its fonts' views are of it */
        w->mapped = cf_calloc(1, sizeof *w->mapped);
    }
    if (w->mapped == NULL) {
        munmap(map, len);
        return -1;
    }
    w->mapped->map = map;
    w->mapped->len = len;
    w->mapped->cache = strdup(cache);   /* NULL: not removed */
    return 0;
}

int
cf__fcache_config(const cf__fm_source_t *dirs, size_t ndirs,
                  const char *const *accept, size_t naccept,
                  const char *cache, cf__fm_config_t **out, char *why,
                  size_t why_cap)
{
    walk_t w;
    char buf[512];
    size_t d, i;
    int dfd = -1, r = 0;
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
    clock_gettime(CLOCK_REALTIME, &w.now);
    r = open_cache(&w, cache, &dfd);
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
        r = from_dir(&w, dirs[d].dir, &st);
    }
    for (i = 0; i < w.old.n; i++)
        if (!w.old.entries[i].used)
            w.changed = true;   /* a file gone */
    /* written whole: a walk stopped by a refusal is not */
    if (r == 0 && w.changed && !w.unwritable && cache != NULL)
        r = write_pieces(&w, cache, &dfd);
    if (dfd >= 0)
        close(dfd);
    if (r != 0 || w.refused) {
        walk_fini(&w, true);
        return r != 0 ? r : 1;
    }
    walk_fini(&w, false);
    r = cf__fm_config_of(w.fonts, w.nfonts, accept, naccept, out, why,
                         why_cap);
    cf_free(w.fonts);
    if (r == 0 && w.viewed)
        cf__fm_config_keep(*out, w.mapped);
    else
        cf__fm_mapped_free(w.mapped);
    return r;
}

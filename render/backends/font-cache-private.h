/*
** The fonts' metadata cache's two halves' common part (private to
** render/backends/font-cache.c, which walks the font directories and
** writes the cache, and font-cache-read.c, which checks and decodes it):
** the file's constants, the reader of its bytes, and what the reader
** finds of its entries and directory records.  The layout: font-cache.h.
*/
#ifndef CURVEFIG_RENDER_FONT_CACHE_PRIVATE_H
#define CURVEFIG_RENDER_FONT_CACHE_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "font-match.h"
#include "sfnt.h"

#define CF__FCACHE_MAGIC "CFFACES"   /* with its NUL: 8 bytes */
/* 2: the directory records (1: none; such a cache is read as damaged,
** and written anew) */
#define CF__FCACHE_VERSION 2u
/* The cache file's name, which carries the format's version, as
** fontconfig's do: two builds of curvefig that read different formats
** (a release and a newer build, or an older one a benchmark compares
** with) each keep their own file, rather than each taking the other's as
** damaged and writing its own over it at every run (the fonts read anew
** each time, some 25 ms). */
#define CF__FCACHE_FILE "faces-2.cache"
#define CF__FCACHE_HEADER 28u
#define CF__FCACHE_MAX (64u << 20)
/* a directory record with the shortest path: path length, one byte,
** time 8 + 4, settled 1, first entry and count 4 + 4 */
#define CF__FCACHE_MIN_DIR 24u

enum { ST_FACES = 0, ST_REFUSED = 1, ST_NOT_FONT = 2 };

typedef struct rd {
    const unsigned char *p;
    size_t len, pos;
    bool bad;
    const unsigned char *ranges;   /* the entry's last face's ranges (a */
    size_t nranges;                /* count of 0 refers to them) */
} rd_t;

static inline const unsigned char *
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

/* A directory record: the directory's path and modification time when
** it was walked, and the run of entries (entries[first..first+count))
** that are its files, in the walk's order.  Settled: its time was 2 s
** or more before the walk (a file added since has changed it). */
typedef struct dirrec {
    const char *path;            /* not NUL-terminated */
    size_t path_len;
    int64_t sec;
    uint32_t nsec;
    bool settled;
    size_t first, count;
} dirrec_t;

/* A cache as read: its entries and directory records (one allocation,
** cf_free(entries)). */
typedef struct parsed {
    entry_t *entries;
    size_t n;
    dirrec_t *dirs;
    size_t ndirs;
} parsed_t;

/* The cache data[0..len) into *out, each entry's and directory record's
** fields checked, and when strict every entry's faces (else each face is
** checked when its entry is used); the number of entries, or -1
** (damaged, or out of memory: *oom; *out then empty). */
long cf__fcache_parse(const unsigned char *data, size_t len, parsed_t *out,
                      bool *oom, bool strict);

/* One face at r's position decoded into *m, *ls, its charset's bytes
** *view, checked when check (see font-cache-read.c); 0, or 1 (damaged). */
int cf__fcache_get_face(rd_t *r, cf__fmeta_t *m, cf__flangset_t *ls,
                        const unsigned char **view, bool check);

/* Whether the face at r's position has one of the families accept[0..n-1]
** (of lengths alen[]); r unchanged. */
bool cf__fcache_face_accepted(const rd_t *r, const char *const *accept,
                              const size_t *alen, size_t n);

/* The face at r's position skipped, its structure checked; 0, or 1. */
int cf__fcache_skip_face(rd_t *r);

#endif

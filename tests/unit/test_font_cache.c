/*
** The fonts' metadata cache (render/backends/font-cache.h):
**   - the configuration from the cache equals the one read from the
**     files, font by font and field by field, and a second run reads no
**     font file it has (the cache file unchanged);
**   - a cache made stale (a file's time changed) is written anew; one of
**     version 1 (no directory records) too;
**   - directories: one whose time is 2 s past (settled) is taken from its
**     record, its files not looked at (a file's time changed in place not
**     seen by the walk, the cache not written) and a font of a file
**     changed in place (its time, or its size) found at its first use
**     (its charset the file's, the cache removed); a file added, removed
**     or renamed (the directory's time another) seen; one whose time is
**     now walked whole at every run, the cache written only when its
**     record changes (settled once 2 s past);
**   - damaged caches: thousands of copies (truncated at every length of
**     its first kilobytes and at random ones, bytes flipped, lengths and
**     counts set to extremes; a directory record's every field, a record
**     of a directory twice) are checked, those damaged in their
**     structure refused, and none is read out
**     of bounds (the ASan build runs this); a damaged cache file in place
**     gives a configuration, and with every font's coverage used it is
**     replaced by a valid one (or kept, when the damage is in a face no
**     configuration takes);
**   - a charset damaged only in a face used late (a CJK face): the
**     configuration taken all the same, the damage found at the face's
**     first coverage lookup, its charset read from its file (coverage
**     and sorts those of the fonts read directly), the cache removed and
**     written anew at the next run; the same from four threads at once;
**   - hardening: a cache directory that is a symbolic link, or group-
**     writable, is not used (nothing written through it); a cache file
**     that is a symbolic link is not followed (its target unchanged, the
**     link replaced); a cache that cannot be written (a directory that
**     cannot be made) gives the configuration all the same;
**   - allocation failure (tu_fail_loop) with a cache to read and with one
**     to write: -1, nothing leaked.
** Skipped when the tool's font directories are not installed.
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>

#include "font-cache.h"
#include "testutil.h"
#include "tool-fonts.h"

static const cf__fm_source_t *const sources = tool_font_dirs;
static const char *const *const accept = tool_font_families;

static char tmp[64];

/* The fonts' charsets the same, range by range (a view checked then). */
static void
same_charset(const cf__fm_font_t *x, const cf__fm_font_t *y)
{
    size_t k, n = cf__fm_font_nranges(x);
    assert_int_equal(n, cf__fm_font_nranges(y));
    for (k = 0; k < n; k++) {
        uint32_t a, b, c, d;
        assert_true(cf__fm_font_range(x, k, &a, &b));
        assert_true(cf__fm_font_range(y, k, &c, &d));
        if (a != c || b != d)
            fail_msg("%s: range %zu [%x, %x], [%x, %x]", x->file, k,
                     (unsigned)a, (unsigned)b, (unsigned)c, (unsigned)d);
    }
    {
        uint32_t a, b;
        assert_false(cf__fm_font_range(x, n, &a, &b));
    }
}

static cf__fm_config_t *
config(const char *cache)
{
    cf__fm_config_t *c;
    char why[512];
    int r = cf__fcache_config(sources, 4, accept, 7, cache, &c, why,
                              sizeof why);
    if (r != 0)
        fail_msg("configuration: %d %s", r, why);
    return c;
}

static void
same_config(const cf__fm_config_t *a, const cf__fm_config_t *b)
{
    size_t i, n = cf__fm_config_count(a);
    assert_int_equal(n, cf__fm_config_count(b));
    for (i = 0; i < n; i++) {
        const cf__fm_font_t *x = cf__fm_config_font(a, i);
        const cf__fm_font_t *y = cf__fm_config_font(b, i);
        const cf__fmeta_t *m = &x->meta, *o = &y->meta;
        unsigned k;
        assert_string_equal(x->file, y->file);
        assert_memory_equal(&x->langs, &y->langs, sizeof x->langs);
        assert_int_equal(m->index, o->index);
        assert_int_equal(m->nfamily, o->nfamily);
        for (k = 0; k < m->nfamily; k++) {
            assert_string_equal(m->family[k], o->family[k]);
            assert_string_equal(m->familylang[k], o->familylang[k]);
        }
        assert_string_equal(m->psname, o->psname);
        assert_true(m->slant == o->slant && m->weight == o->weight
                    && m->width == o->width
                    && m->decorative == o->decorative
                    && m->has_size == o->has_size && m->cff == o->cff
                    && m->fontversion == o->fontversion
                    && m->has_codepages == o->has_codepages
                    && m->codepages[0] == o->codepages[0]
                    && m->codepages[1] == o->codepages[1]);
        same_charset(x, y);
    }
}

static int
setup(void **state)
{
    struct stat st;
    (void)state;
    if (stat(sources[0].dir, &st) != 0 || stat(sources[2].dir, &st) != 0
        || stat(sources[3].dir, &st) != 0)
        return 0;
    snprintf(tmp, sizeof tmp, "/tmp/cf-fcache-XXXXXX");
    assert_non_null(mkdtemp(tmp));
    return 0;
}

static int
teardown(void **state)
{
    char cmd[200];
    (void)state;
    if (tmp[0] != '\0') {
        snprintf(cmd, sizeof cmd, "chmod -R u+w %s; rm -rf %s", tmp, tmp);
        if (system(cmd) != 0)
            return 1;
    }
    return 0;
}

/* From the cache, the same configuration; the second run writes
** nothing; a stale entry is read again. */
static void
test_same_from_cache(void **state)
{
    char path[400];
    cf__fm_config_t *direct, *first, *second;
    struct stat st1, st2;
    (void)state;
    if (tmp[0] == '\0')
        skip();
    snprintf(path, sizeof path, "%s/a/curvefig/faces-2.cache", tmp);
    direct = config(NULL);
    first = config(path);
    assert_int_equal(stat(path, &st1), 0);
    assert_int_equal(st1.st_mode & 0777, 0600);
    {
        char dir[400];
        struct stat sd;
        snprintf(dir, sizeof dir, "%s/a/curvefig", tmp);
        assert_int_equal(stat(dir, &sd), 0);
        assert_int_equal(sd.st_mode & 0777, 0700);
    }
    second = config(path);
    assert_int_equal(stat(path, &st2), 0);
    /* not written again: the same file */
    assert_int_equal(st1.st_ino, st2.st_ino);
    same_config(direct, first);
    same_config(direct, second);
    assert_true(cf__fm_config_count(direct) > 0);
    cf__fm_config_free(first);
    cf__fm_config_free(second);
    cf__fm_config_free(direct);
}

/* Every font's coverage used (its charset checked then). */
static void
use_all(const cf__fm_config_t *c)
{
    size_t i;
    for (i = 0; i < cf__fm_config_count(c); i++)
        (void)cf__fm_font_has(cf__fm_config_font(c, i), 'A');
}

/* The sort of a request the same in both configurations, face by face. */
static void
same_sort(const cf__fm_config_t *a, const cf__fm_config_t *b,
          const char *family, const char *lang)
{
    cf__fm_face_t *fa, *fb;
    size_t na, nb, i;
    assert_int_equal(cf__fm_sort(a, family, false, false, 10240, lang, &fa,
                                 &na), 0);
    assert_int_equal(cf__fm_sort(b, family, false, false, 10240, lang, &fb,
                                 &nb), 0);
    assert_int_equal(na, nb);
    for (i = 0; i < na; i++) {
        assert_string_equal(fa[i].font->file, fb[i].font->file);
        assert_int_equal(fa[i].font->meta.index, fb[i].font->meta.index);
        assert_string_equal(fa[i].family, fb[i].family);
    }
    cf_free(fa);
    cf_free(fb);
}

typedef struct thread_arg {
    const cf__fm_config_t *c, *direct;
    bool same;
} thread_arg_t;

/* Every font's coverage of a few characters, against the direct
** configuration's. */
static void *
use_from_thread(void *p)
{
    static const uint32_t chars[] = { 'A', 0xe9, 0x3b1, 0x4e00, 0x9fa5,
                                      0xac00, 0x1f600 };
    thread_arg_t *a = p;
    size_t i, k;
    a->same = true;
    for (i = 0; i < cf__fm_config_count(a->c); i++)
        for (k = 0; k < sizeof chars / sizeof chars[0]; k++)
            if (cf__fm_font_has(cf__fm_config_font(a->c, i), chars[k])
                != cf__fm_font_has(cf__fm_config_font(a->direct, i),
                                   chars[k]))
                a->same = false;
    return NULL;
}

/* A cache whose charset is damaged only in a face used late (a CJK face,
** reached by an ideograph only the CJK faces have): the configuration is
** taken from it as from a good one, the cache kept; the first use of the
** face's coverage finds the damage: its charset is read again from its
** file (the coverage and the sorts those of the configuration read from
** the files), the cache removed, and the next run writes a valid one. */
static void
test_lazy_check(void **state)
{
    char path[400];
    cf__fm_config_t *direct, *c;
    const cf__fm_font_t *f = NULL;
    unsigned char *good;
    size_t len = 0, i, k, off, count;
    long n;
    struct stat st;
    (void)state;
    if (tmp[0] == '\0')
        skip();
    snprintf(path, sizeof path, "%s/h/curvefig/faces-2.cache", tmp);
    direct = config(NULL);
    cf__fm_config_free(config(path));
    c = config(path);
    count = cf__fm_config_count(c);
    for (k = 0; k < count; k++) {
        f = cf__fm_config_font(c, k);
        if (f->view != NULL && f->meta.nranges > 2
            && strstr(f->meta.family[0], "CJK") != NULL)
            break;
    }
    assert_true(k < count);
    off = (size_t)(f->view - (const unsigned char *)f->mapped->map);
    cf__fm_config_free(c);
    good = tu_read_file(path, &len);
    assert_non_null(good);
    n = cf__fcache_check(good, len);
    assert_true(n > 0);
    /* its second range begins where its first does: not ascending */
    memcpy(good + off + 8, good + off, 4);
    assert_int_equal(cf__fcache_check(good, len), -1);
    tu_write_file(path, good, len);
    /* from several threads at once: each its first use, the same
    ** answers as the files' */
    c = config(path);
    {
        pthread_t t[4];
        thread_arg_t arg[4];
        for (i = 0; i < 4; i++) {
            arg[i].c = c;
            arg[i].direct = direct;
            arg[i].same = false;
            assert_int_equal(pthread_create(&t[i], NULL, use_from_thread,
                                            &arg[i]), 0);
        }
        for (i = 0; i < 4; i++) {
            assert_int_equal(pthread_join(t[i], NULL), 0);
            assert_true(arg[i].same);
        }
    }
    cf__fm_config_free(c);
    assert_int_not_equal(stat(path, &st), 0);   /* removed */
    tu_write_file(path, good, len);
    c = config(path);
    assert_int_equal(cf__fm_config_count(c), count);
    /* a match reads no charset; a Latin face's coverage, its own */
    {
        cf__fm_face_t face;
        assert_int_equal(cf__fm_match(c, "Latin Modern Roman", false, false,
                                      10240, "en", &face), 0);
        assert_true(cf__fm_font_has(face.font, 'A'));
    }
    assert_int_equal(stat(path, &st), 0);
    /* the damaged face's coverage: the file's */
    for (i = 0; i < 4; i++) {
        static const uint32_t chars[] = { 0x4e00, 0x9fa5, 'A', 0x10ffff };
        assert_true(cf__fm_font_has(cf__fm_config_font(c, k), chars[i])
                    == cf__fm_font_has(cf__fm_config_font(direct, k),
                                       chars[i]));
    }
    assert_true(cf__fm_font_has(cf__fm_config_font(c, k), 0x4e00));
    assert_int_not_equal(stat(path, &st), 0);   /* removed */
    same_sort(direct, c, "Latin Modern Roman", "en");
    same_sort(direct, c, "Noto Sans CJK SC", "zh-cn");
    same_config(direct, c);
    cf__fm_config_free(c);
    /* written anew */
    cf__fm_config_free(config(path));
    free(good);
    good = tu_read_file(path, &len);
    assert_int_equal(cf__fcache_check(good, len), n);
    free(good);
    cf__fm_config_free(direct);
}

static uint32_t
le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16
           | (uint32_t)p[3] << 24;
}

static void
put32(unsigned char *p, uint32_t v)
{
    size_t i;
    for (i = 0; i < 4; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

/* Where the directory records of a valid cache begin (after its
** entries: header 28 bytes, then each entry's length first). */
static size_t
dirs_at(const unsigned char *c)
{
    size_t pos = 28, i, n = le32(c + 16);
    for (i = 0; i < n; i++)
        pos += le32(c + pos);
    return pos;
}

/* A cache's first directory record damaged, field by field (its path
** length at good + at): refused. */
static void
damaged_records(const unsigned char *good, size_t len)
{
    unsigned char *copy = malloc(len + 300);
    size_t at = dirs_at(good);
    size_t pl = (size_t)good[at] | (size_t)good[at + 1] << 8;
    size_t t = at + 2 + pl, n = le32(good + 16);
    /* the fields after its path: time 8, ns 4, settled 1, first 4, count 4 */
    struct { size_t off; uint32_t v; } bad[] = {
        { t + 8, 1000000000u },   /* nanoseconds */
        { t + 12, 2 },            /* settled neither 0 nor 1 (a byte) */
        { t + 13, 1 },            /* a run not where the entries begin */
        { t + 13, (uint32_t)n + 1 },
        { t + 17, 0xffffffffu },  /* more entries than there are */
        { t + 17, (uint32_t)n + 1 },
        { t + 17, le32(good + t + 17) + 1 },   /* the next one's first */
        { t + 17, le32(good + t + 17) - 1 },   /* one short */
    };
    size_t i;
    assert_non_null(copy);
    assert_int_equal(le32(good + 20), 4);   /* the tool's 4 directories */
    assert_true(le32(good + t + 17) > 1);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        memcpy(copy, good, len);
        if (bad[i].off == t + 12)
            copy[t + 12] = (unsigned char)bad[i].v;
        else
            put32(copy + bad[i].off, bad[i].v);
        assert_int_equal(cf__fcache_check(copy, len), -1);
    }
    /* its path another: its files not in it */
    memcpy(copy, good, len);
    copy[at + 2 + pl - 1] ^= 0x20;
    assert_int_equal(cf__fcache_check(copy, len), -1);
    /* a record more, of no files: accepted under a path of its own, not
    ** under the first's (a directory twice) */
    for (i = 0; i < 2; i++) {
        size_t m = len;
        memcpy(copy, good, len);
        if (i == 0) {
            copy[m++] = 4;
            copy[m++] = 0;
            memcpy(copy + m, "/new", 4);
            m += 4;
        } else {
            memcpy(copy + m, good + at, 2 + pl);
            m += 2 + pl;
        }
        memset(copy + m, 0, 13);
        m += 13;
        put32(copy + m, (uint32_t)n);
        put32(copy + m + 4, 0);
        m += 8;
        put32(copy + 20, 5);
        put32(copy + 24, (uint32_t)m);
        assert_int_equal(cf__fcache_check(copy, m), i == 0 ? (long)n : -1);
    }
    free(copy);
}

/* A cache of version 1 (no directory records) is refused, and a file of
** it in place written anew. */
static void
version_1(const unsigned char *good, const char *path, long n)
{
    size_t at = dirs_at(good), m = 24 + at - 28, alen = 0;
    unsigned char *v1 = malloc(m), *again;
    assert_non_null(v1);
    memcpy(v1, good, 20);
    put32(v1 + 8, 1);
    put32(v1 + 20, (uint32_t)m);
    memcpy(v1 + 24, good + 28, at - 28);
    assert_int_equal(cf__fcache_check(v1, m), -1);
    tu_write_file(path, v1, m);
    cf__fm_config_free(config(path));
    again = tu_read_file(path, &alen);
    assert_int_equal(cf__fcache_check(again, alen), n);
    free(again);
    free(v1);
}

/* Damaged copies refused by the checker, never read out of bounds. */
static void
test_damaged_copies(void **state)
{
    char path[400];
    unsigned char *good, *copy;
    size_t len = 0, i, k;
    long n;
    tu_rng rng;
    cf__fm_config_t *c;
    (void)state;
    if (tmp[0] == '\0')
        skip();
    snprintf(path, sizeof path, "%s/b/faces-2.cache", tmp);
    mkdir(path, 0700);   /* b/faces-2.cache/ is a directory: b is made */
    rmdir(path);
    snprintf(path, sizeof path, "%s/b/curvefig/faces-2.cache", tmp);
    cf__fm_config_free(config(path));
    good = tu_read_file(path, &len);
    assert_non_null(good);
    n = cf__fcache_check(good, len);
    assert_true(n > 100);
    copy = malloc(len);
    /* truncated: every length of the first 2 KB, 500 random ones */
    for (i = 0; i < len && i < 2048; i++) {
        memcpy(copy, good, i);
        assert_int_equal(cf__fcache_check(copy, i), -1);
    }
    tu_rng_seed(&rng, 28);
    for (k = 0; k < 500; k++) {
        size_t cut = (size_t)(tu_rng_u01(&rng) * (double)len);
        memcpy(copy, good, cut);
        assert_int_equal(cf__fcache_check(copy, cut), -1);
    }
    /* bytes flipped and set to extremes at random places (some land in
    ** names or numbers that stay valid: those copies check) */
    for (k = 0; k < 3000; k++) {
        size_t at = (size_t)(tu_rng_u01(&rng) * (double)len), j;
        memcpy(copy, good, len);
        for (j = 0; j < 1 + k % 4; j++) {
            static const unsigned char extremes[] = { 0, 0xff, 0x7f, 0x80 };
            at = (size_t)(tu_rng_u01(&rng) * (double)len);
            copy[at] = k % 2 ? (unsigned char)tu_rng_next(&rng)
                             : extremes[k % 4];
        }
        (void)cf__fcache_check(copy, len);
    }
    damaged_records(good, len);
    version_1(good, path, n);
    /* every byte of the header, and of the first entry's lengths, 0xff */
    for (i = 0; i < 34 && i < len; i++) {
        memcpy(copy, good, len);
        copy[i] = 0xff;
        assert_int_equal(cf__fcache_check(copy, len), -1);
    }
    /* a damaged file in place: the same configuration, then a valid cache */
    for (k = 0; k < 20; k++) {
        size_t cut = k < 10 ? (size_t)(tu_rng_u01(&rng) * (double)len) : len;
        unsigned char *again;
        size_t alen = 0;
        memcpy(copy, good, len);
        if (k >= 10)
            copy[24 + (size_t)(tu_rng_u01(&rng) * (double)(len - 24))] ^= 0x5a;
        tu_write_file(path, copy, cut);
        c = config(path);
        assert_true(cf__fm_config_count(c) > 0);
        use_all(c);
        cf__fm_config_free(c);
        cf__fm_config_free(config(path));
        again = tu_read_file(path, &alen);
        /* valid; or damaged only in a face no configuration takes,
        ** whose ranges are never read: the copy as it was */
        assert_true(cf__fcache_check(again, alen) == n
                    || (alen == cut && memcmp(again, copy, cut) == 0));
        free(again);
    }
    free(copy);
    free(good);
}

/* The cache's directory and file are not followed through links, not
** used when others may write them, and an unwritable place is no cache. */
static void
test_hardening(void **state)
{
    char real[128], link[128], path[256], target[128];
    struct stat st;
    cf__fm_config_t *c;
    (void)state;
    if (tmp[0] == '\0')
        skip();
    /* the cache directory a symbolic link: not used, nothing written */
    snprintf(real, sizeof real, "%s/elsewhere", tmp);
    assert_int_equal(mkdir(real, 0700), 0);
    snprintf(link, sizeof link, "%s/c", tmp);
    assert_int_equal(mkdir(link, 0700), 0);
    snprintf(link, sizeof link, "%s/c/curvefig", tmp);
    assert_int_equal(symlink(real, link), 0);
    snprintf(path, sizeof path, "%s/faces-2.cache", link);
    c = config(path);
    cf__fm_config_free(c);
    snprintf(path, sizeof path, "%s/faces-2.cache", real);
    assert_int_not_equal(stat(path, &st), 0);
    /* group-writable: not used */
    snprintf(real, sizeof real, "%s/d", tmp);
    assert_int_equal(mkdir(real, 0700), 0);
    snprintf(real, sizeof real, "%s/d/curvefig", tmp);
    assert_int_equal(mkdir(real, 0700), 0);
    assert_int_equal(chmod(real, 0770), 0);
    snprintf(path, sizeof path, "%s/faces-2.cache", real);
    cf__fm_config_free(config(path));
    assert_int_not_equal(stat(path, &st), 0);
    /* the cache file a symbolic link: its target untouched, the link
    ** replaced by the cache */
    snprintf(real, sizeof real, "%s/e", tmp);
    assert_int_equal(mkdir(real, 0700), 0);
    snprintf(real, sizeof real, "%s/e/curvefig", tmp);
    assert_int_equal(mkdir(real, 0700), 0);
    snprintf(target, sizeof target, "%s/target", tmp);
    tu_write_file(target, (const unsigned char *)"keep", 4);
    snprintf(path, sizeof path, "%s/faces-2.cache", real);
    assert_int_equal(symlink(target, path), 0);
    cf__fm_config_free(config(path));
    {
        size_t n;
        unsigned char *t = tu_read_file(target, &n);
        assert_int_equal(n, 4);
        assert_memory_equal(t, "keep", 4);
        free(t);
    }
    assert_int_equal(lstat(path, &st), 0);
    assert_true(S_ISREG(st.st_mode));
    /* nowhere to write: the configuration all the same */
    c = config("/proc/cf-no-such-dir/curvefig/faces-2.cache");
    assert_true(cf__fm_config_count(c) > 0);
    cf__fm_config_free(c);
    /* a read-only directory (when not root, for whom it is not) */
    if (geteuid() != 0) {
        snprintf(real, sizeof real, "%s/f", tmp);
        assert_int_equal(mkdir(real, 0700), 0);
        snprintf(real, sizeof real, "%s/f/curvefig", tmp);
        assert_int_equal(mkdir(real, 0500), 0);
        snprintf(path, sizeof path, "%s/faces-2.cache", real);
        cf__fm_config_free(config(path));
        assert_int_not_equal(stat(path, &st), 0);
    }
}

/* ---- directories: their times, not their files' ------------------------ */

static const char *const lm_files[] = {
    "lmroman10-regular.otf", "lmroman10-bold.otf", "lmmono10-regular.otf",
};
static const char *const lm_accept[] = { "Latin Modern Roman",
                                         "Latin Modern Mono" };
#define LM_DIR "/usr/share/texmf/fonts/opentype/public/lm"

/* path's modification time set to ago seconds before now (its access
** time too). */
static void
set_time(const char *path, long ago)
{
    struct timespec t[2];
    assert_int_equal(clock_gettime(CLOCK_REALTIME, &t[0]), 0);
    t[0].tv_sec -= ago;
    t[1] = t[0];
    assert_int_equal(utimensat(AT_FDCWD, path, t, 0), 0);
}

static void
copy_file(const char *from, const char *to)
{
    size_t n;
    unsigned char *b = tu_read_file(from, &n);
    assert_non_null(b);
    tu_write_file(to, b, n);
    free(b);
}

/* A font directory tmp/name of the three fonts of lm_files, its time
** ago seconds past, into dir, and a cache of it into cache (each 128
** bytes). */
static void
make_font_dir(char *dir, char *cache, const char *name, long ago)
{
    char from[300], to[300];
    size_t i;
    snprintf(dir, 128, "%s/%s", tmp, name);
    snprintf(cache, 128, "%s/%s-cache/curvefig/faces-2.cache", tmp, name);
    assert_int_equal(mkdir(dir, 0700), 0);
    for (i = 0; i < sizeof lm_files / sizeof lm_files[0]; i++) {
        snprintf(from, sizeof from, "%s/%s", LM_DIR, lm_files[i]);
        snprintf(to, sizeof to, "%s/%s", dir, lm_files[i]);
        copy_file(from, to);
    }
    set_time(dir, ago);
}

static cf__fm_config_t *
dir_config(const char *dir, const char *cache)
{
    cf__fm_source_t src = { dir, true };
    cf__fm_config_t *c;
    char why[512];
    int r = cf__fcache_config(&src, 1, lm_accept, 2, cache, &c, why,
                              sizeof why);
    if (r != 0)
        fail_msg("configuration of %s: %d %s", dir, r, why);
    return c;
}

/* The cache file's inode (0: there is none): another when it was
** written anew. */
static ino_t
cache_ino(const char *cache)
{
    struct stat st;
    return stat(cache, &st) == 0 ? st.st_ino : 0;
}

/* The configuration's first font of file dir/name, or NULL. */
static const cf__fm_font_t *
font_of(const cf__fm_config_t *c, const char *dir, const char *name)
{
    char path[300];
    size_t i;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    for (i = 0; i < cf__fm_config_count(c); i++)
        if (strcmp(cf__fm_config_font(c, i)->file, path) == 0)
            return cf__fm_config_font(c, i);
    return NULL;
}

/* The configuration from the cache the one read from the files. */
static void
same_as_files(const char *dir, const char *cache)
{
    cf__fm_config_t *direct = dir_config(dir, NULL);
    cf__fm_config_t *c = dir_config(dir, cache);
    same_config(direct, c);
    cf__fm_config_free(c);
    cf__fm_config_free(direct);
}

/* After a change of the directory (its time set to ago s past, another
** than the cache's): the configuration from the cache has the font of
** file name (present) or not, and is the one read from the files. */
static void
seen(const char *dir, const char *cache, long ago, const char *name,
     bool present)
{
    cf__fm_config_t *c;
    set_time(dir, ago);
    c = dir_config(dir, cache);
    assert_true((font_of(c, dir, name) != NULL) == present);
    cf__fm_config_free(c);
    same_as_files(dir, cache);
}

/* A settled directory (its time long past) is taken from the cache
** without a look at its files: a file's time changed in place is not
** seen by the walk (the cache is not written anew), but at the font's
** first use; a file grown in place the same.  A file added, removed or
** renamed changes the directory's time: the directory is walked. */
static void
test_dir_settled(void **state)
{
    char dir[128], cache[128], path[300], to[300];
    cf__fm_config_t *direct, *c;
    ino_t ino;
    (void)state;
    if (tmp[0] == '\0')
        skip();
    make_font_dir(dir, cache, "fonts-settled", 100);
    direct = dir_config(dir, NULL);
    assert_int_equal(cf__fm_config_count(direct), 3);
    cf__fm_config_free(dir_config(dir, cache));
    ino = cache_ino(cache);
    assert_true(ino != 0);
    /* (a) a file's time changed (its directory's not): not looked at */
    snprintf(path, sizeof path, "%s/%s", dir, lm_files[1]);
    set_time(path, 50);
    c = dir_config(dir, cache);
    assert_true(cache_ino(cache) == ino);
    /* the fonts of unchanged files used: the cache kept */
    cf__fm_font_verify(font_of(c, dir, lm_files[0]));
    assert_true(cf__fm_font_has(font_of(c, dir, lm_files[0]), 'A'));
    assert_true(cache_ino(cache) == ino);
    /* (d) the changed one's at its use: its charset read from its file,
    ** the cache removed; the configuration the files' */
    cf__fm_font_verify(font_of(c, dir, lm_files[1]));
    assert_true(cache_ino(cache) == 0);
    same_config(direct, c);
    cf__fm_config_free(c);
    /* written anew, with the file's new time: taken from it again */
    cf__fm_config_free(dir_config(dir, cache));
    ino = cache_ino(cache);
    assert_true(ino != 0);
    c = dir_config(dir, cache);
    cf__fm_font_verify(font_of(c, dir, lm_files[1]));
    assert_true(cache_ino(cache) == ino);
    cf__fm_config_free(c);
    /* (d) a file grown in place, its time kept: found at its use
    ** through its coverage */
    {
        struct stat st;
        struct timespec t[2];
        int fd;
        snprintf(path, sizeof path, "%s/%s", dir, lm_files[2]);
        assert_int_equal(stat(path, &st), 0);
        fd = open(path, O_WRONLY | O_APPEND);
        assert_true(fd >= 0);
        assert_int_equal(write(fd, "\0\0\0\0", 4), 4);
        close(fd);
        t[0] = st.st_atim;
        t[1] = st.st_mtim;
        assert_int_equal(utimensat(AT_FDCWD, path, t, 0), 0);
        c = dir_config(dir, cache);
        assert_true(cache_ino(cache) == ino);
        assert_true(cf__fm_font_has(font_of(c, dir, lm_files[2]), 'A'));
        assert_true(cache_ino(cache) == 0);
        same_config(direct, c);
        cf__fm_config_free(c);
        cf__fm_config_free(dir_config(dir, cache));
    }
    cf__fm_config_free(direct);
    /* (b) a file added: the directory's time changes (here set to
    ** another past time, so that the record's mtime is what differs) */
    snprintf(path, sizeof path, "%s/lmroman10-italic.otf", LM_DIR);
    snprintf(to, sizeof to, "%s/lmroman10-italic.otf", dir);
    copy_file(path, to);
    seen(dir, cache, 90, "lmroman10-italic.otf", true);
    /* removed */
    assert_int_equal(unlink(to), 0);
    seen(dir, cache, 80, "lmroman10-italic.otf", false);
    /* renamed: another name, another place in the order */
    snprintf(path, sizeof path, "%s/%s", dir, lm_files[0]);
    snprintf(to, sizeof to, "%s/a-first.otf", dir);
    assert_int_equal(rename(path, to), 0);
    seen(dir, cache, 70, "a-first.otf", true);
    /* and the warm run after each: not written again */
    ino = cache_ino(cache);
    same_as_files(dir, cache);
    assert_true(cache_ino(cache) == ino);
}

/* (c) A directory whose time is now is not settled: walked whole at
** every run (a file's time changed in place is seen), the cache not
** written again while nothing changes; once its time is 2 s past, the
** cache is written with its record settled, and the walk stops. */
static void
test_dir_unsettled(void **state)
{
    char dir[128], cache[128], path[300];
    ino_t ino;
    (void)state;
    if (tmp[0] == '\0')
        skip();
    make_font_dir(dir, cache, "fonts-fresh", 0);
    same_as_files(dir, cache);
    ino = cache_ino(cache);
    assert_true(ino != 0);
    /* nothing changed: walked, not written */
    same_as_files(dir, cache);
    assert_true(cache_ino(cache) == ino);
    /* a file's time changed in place: the walk sees it */
    snprintf(path, sizeof path, "%s/%s", dir, lm_files[1]);
    set_time(path, 30);
    set_time(dir, 0);
    cf__fm_config_free(dir_config(dir, cache));
    assert_true(cache_ino(cache) != ino);
    ino = cache_ino(cache);
    /* the directory older: its record settled, the cache written */
    set_time(dir, 3);
    cf__fm_config_free(dir_config(dir, cache));
    assert_true(cache_ino(cache) != ino);
    ino = cache_ino(cache);
    /* and from then on its files are not looked at */
    set_time(path, 20);
    cf__fm_config_free(dir_config(dir, cache));
    assert_true(cache_ino(cache) == ino);
}

/* The path: XDG_CACHE_HOME when absolute, else HOME's .cache. */
static void
test_path(void **state)
{
    char buf[512];
    (void)state;
    setenv("XDG_CACHE_HOME", "/x/cache", 1);
    setenv("HOME", "/h", 1);
    assert_true(cf__fcache_path(buf, sizeof buf));
    assert_string_equal(buf, "/x/cache/curvefig/faces-2.cache");
    setenv("XDG_CACHE_HOME", "relative", 1);
    assert_true(cf__fcache_path(buf, sizeof buf));
    assert_string_equal(buf, "/h/.cache/curvefig/faces-2.cache");
    unsetenv("XDG_CACHE_HOME");
    unsetenv("HOME");
    assert_false(cf__fcache_path(buf, sizeof buf));
    setenv("HOME", "/h", 1);
    assert_false(cf__fcache_path(buf, 8));
}

static char fail_path[400];

static cf_status_t
cached_op(cf_diag_t *diag)
{
    cf__fm_config_t *c;
    int r = cf__fcache_config(sources, 4, accept, 7, fail_path, &c, NULL, 0);
    (void)diag;
    if (r < 0)
        return CF_STATUS_NO_MEMORY;
    assert_int_equal(r, 0);
    cf__fm_config_free(c);
    return CF_STATUS_OK;
}

static cf_status_t
writing_op(cf_diag_t *diag)
{
    unlink(fail_path);
    return cached_op(diag);
}

static void
test_alloc_failure(void **state)
{
    (void)state;
    if (tmp[0] == '\0')
        skip();
    snprintf(fail_path, sizeof fail_path, "%s/g/curvefig/faces-2.cache", tmp);
    cf__fm_config_free(config(fail_path));
    tu_fail_loop("font cache read", cached_op, false);
    tu_fail_loop("font cache written", writing_op, false);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_from_cache),
        cmocka_unit_test(test_damaged_copies),
        cmocka_unit_test(test_lazy_check),
        cmocka_unit_test(test_hardening),
        cmocka_unit_test(test_dir_settled),
        cmocka_unit_test(test_dir_unsettled),
        cmocka_unit_test(test_alloc_failure),
        cmocka_unit_test(test_path),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

/*
** The fonts' metadata cache (render/backends/font-cache.h):
**   - the configuration from the cache equals the one read from the
**     files, font by font and field by field, and a second run reads no
**     font file it has (the cache file unchanged);
**   - a cache made stale (a file's time changed) is written anew;
**   - damaged caches: thousands of copies (truncated at every length of
**     its first kilobytes and at random ones, bytes flipped, lengths and
**     counts set to extremes) are checked, those damaged in their
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
    snprintf(path, sizeof path, "%s/a/curvefig/faces.cache", tmp);
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
    snprintf(path, sizeof path, "%s/h/curvefig/faces.cache", tmp);
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
    snprintf(path, sizeof path, "%s/b/faces.cache", tmp);
    mkdir(path, 0700);   /* b/faces.cache/ is a directory: b is made */
    rmdir(path);
    snprintf(path, sizeof path, "%s/b/curvefig/faces.cache", tmp);
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
    /* every byte of the header, and of the first entry's lengths, 0xff */
    for (i = 0; i < 30 && i < len; i++) {
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
    snprintf(path, sizeof path, "%s/faces.cache", link);
    c = config(path);
    cf__fm_config_free(c);
    snprintf(path, sizeof path, "%s/faces.cache", real);
    assert_int_not_equal(stat(path, &st), 0);
    /* group-writable: not used */
    snprintf(real, sizeof real, "%s/d", tmp);
    assert_int_equal(mkdir(real, 0700), 0);
    snprintf(real, sizeof real, "%s/d/curvefig", tmp);
    assert_int_equal(mkdir(real, 0700), 0);
    assert_int_equal(chmod(real, 0770), 0);
    snprintf(path, sizeof path, "%s/faces.cache", real);
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
    snprintf(path, sizeof path, "%s/faces.cache", real);
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
    c = config("/proc/cf-no-such-dir/curvefig/faces.cache");
    assert_true(cf__fm_config_count(c) > 0);
    cf__fm_config_free(c);
    /* a read-only directory (when not root, for whom it is not) */
    if (geteuid() != 0) {
        snprintf(real, sizeof real, "%s/f", tmp);
        assert_int_equal(mkdir(real, 0700), 0);
        snprintf(real, sizeof real, "%s/f/curvefig", tmp);
        assert_int_equal(mkdir(real, 0500), 0);
        snprintf(path, sizeof path, "%s/faces.cache", real);
        cf__fm_config_free(config(path));
        assert_int_not_equal(stat(path, &st), 0);
    }
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
    assert_string_equal(buf, "/x/cache/curvefig/faces.cache");
    setenv("XDG_CACHE_HOME", "relative", 1);
    assert_true(cf__fcache_path(buf, sizeof buf));
    assert_string_equal(buf, "/h/.cache/curvefig/faces.cache");
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
    snprintf(fail_path, sizeof fail_path, "%s/g/curvefig/faces.cache", tmp);
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
        cmocka_unit_test(test_alloc_failure),
        cmocka_unit_test(test_path),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

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
**     gives the same configuration and is replaced by a valid one;
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
        assert_int_equal(m->nranges, o->nranges);
        assert_memory_equal(m->ranges, o->ranges,
                            2 * m->nranges * sizeof *m->ranges);
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
        cf__fm_config_free(c);
        again = tu_read_file(path, &alen);
        assert_true(cf__fcache_check(again, alen) == n);
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
        cmocka_unit_test(test_hardening),
        cmocka_unit_test(test_alloc_failure),
        cmocka_unit_test(test_path),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

/*
** The figure language and the curvefig tool, through the built tool:
**
**   test_tool TOOL SRCDIR
**
** Each test runs TOOL in a fresh temporary directory (the working
** directory of the child), captures its exit status, stdout and stderr, and
** checks them: the core names of DESIGN.md against the C API's own results,
** scripts with assertions, several figures per script, galleries.  The
** sandbox against hostile scripts (which must stop with a clear message
** and leave the directory empty), messages with file and line and every
** exit status are in test_tool_sandbox.c; the helpers both use in
** test_tool.h.
*/
#include "test_tool.h"

static bool
exists(const result *r, const char *name)
{
    char path[600];
    struct stat sb;
    snprintf(path, sizeof path, "%s/%s", r->dir, name);
    return stat(path, &sb) == 0 && sb.st_size > 0;
}

/* ---- scripts with assertions -------------------------------------------- */

static void
test_core_bezier_script(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("core_bezier.lua"), NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "core_bezier: ok\n");
    assert_null(strstr(r->err, "curvefig:"));
}

static void
test_core_surface_script(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("core_surface.lua"), NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "core_surface: ok\n");
}

static void
test_core_bspline_script(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("core_bspline.lua"), NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "core_bspline: ok\n");
}

static void
test_core_more_script(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("core_more.lua"), NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "core_more: ok\n");
}

static void
test_core_reduce_script(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("core_reduce.lua"), NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "core_reduce: ok\n");
}

/* pairs in one order (render/lua/lpairs.c): the script checks it against
** table.sort; a figure drawn in a pairs loop is the same file at every
** run (before, Lua's seeded string hashes gave 4 different files in 6
** runs); and of several bad options the same is named every time. */
static void
test_pairs_order(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("pairs_order.lua"), NULL };
    const char *fig[] = { "render", src("pairs_figure.lua"), "-f", "svg",
                          NULL };
    static char first[65536], svg[65536];
    char path[600];
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "pairs_order: ok\n");
    for (int k = 0; k < 6; k++) {
        run_tool(r, fig);
        assert_int_equal(r->status, 0);
        snprintf(path, sizeof path, "%s/pairs-figure.svg", r->dir);
        slurp(path, k == 0 ? first : svg, sizeof svg);
        assert_true(strlen(first) > 1000);
        if (k > 0)
            assert_string_equal(svg, first);
    }
    /* the checks of the binding name the first bad key in that order */
    for (int k = 0; k < 6; k++) {
        const char *bad[] = { "run", src("two_bad_options.lua"), NULL };
        run_tool(r, bad);
        assert_int_equal(r->status, 1);
        assert_non_null(strstr(r->err, "curve: unknown option 'colr' (did "
                                        "you mean 'color'?)"));
    }
}

/* ---- the core names against the C API ----------------------------------- */

/* Parse "key v1 v2 ..." lines of the script's output into values. */
static size_t
values_of(const char *out, const char *key, double *v, size_t cap)
{
    char pat[64];
    const char *p;
    size_t n = 0;
    snprintf(pat, sizeof pat, "\n%s ", key);
    p = strstr(out, pat);
    if (p == NULL && strncmp(out, pat + 1, strlen(pat + 1)) == 0)
        p = out - 1;
    if (p == NULL)
        fail_msg("no line \"%s\" in the script's output", key);
    p += strlen(pat);
    while (*p != '\n' && *p != '\0' && n < cap) {
        char *end;
        v[n++] = strtod(p, &end);
        if (end == p)
            fail_msg("bad number after %s", key);
        p = end;
        while (*p == ' ')
            p++;
    }
    return n;
}

/* The binding hands numbers to the C functions and back unchanged, and
** %.17g round-trips a double: the values must be identical. */
static void
expect_values(const result *r, const char *key, const double *want, size_t n)
{
    double got[512];
    size_t m = values_of(r->out, key, got, 512);
    if (m != n)
        fail_msg("%s: %zu values printed, the C API gives %zu", key, m, n);
    for (size_t i = 0; i < n; i++)
        if (got[i] != want[i] && !(isnan(got[i]) && isnan(want[i])))
            fail_msg("%s[%zu]: script %.17g, C API %.17g", key, i, got[i],
                     want[i]);
}

static const double orazem[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 };

static const double sample[] = { 3, 1, 3.75, 2, 5, 3, 4, 4,
                                  3, 3, 2, 4, 1, 3, 2.25, 2 };

static const double sample_u[] = { 0, 0, 0, 0.17, 0.33, 0.5,
                                   0.67, 0.83, 1, 1, 1 };

static const double sample_w[] = { 1, 2, 1, 0.5, 1, 3, 1, 1 };

static const double interp_data[] = { 0, 0, 1, 2, 3, 1, 4, 4, 6, 3 };

/* The points and knots of an interpolating B-spline, flattened. */
static size_t
spline_values(const cf_bspline_t *s, double *v)
{
    size_t n = cf_bspline_count(s) * cf_bspline_dim(s);
    cf_bspline_get_points(s, v);
    memcpy(v + n, cf_bspline_knots(s), cf_bspline_nknots(s) * sizeof *v);
    return n + cf_bspline_nknots(s);
}

static void
expect_offset_and_interp(const result *r, const cf_bezier_t *c)
{
    static const struct {
        const char *key;
        cf_interp_method_t method;
    } methods[] = {
        { "interp-natural", CF_INTERP_NATURAL },
        { "interp-not-a-knot", CF_INTERP_NOT_A_KNOT },
        { "interp-periodic", CF_INTERP_PERIODIC },
        { "interp-catmull-rom", CF_INTERP_CATMULL_ROM },
        { "interp-global", CF_INTERP_GLOBAL },
    };
    cf_offset_options_t oo;
    cf_offset_report_t rep;
    cf_cubics_t *raw;
    double v[1024];
    cf_offset_options_init(&oo);
    oo.tolerance = 1e-3;
    assert_int_equal(cf_bezier_offset(c, 1.5, &oo, &raw, NULL, &rep, NULL),
                     0);
    assert_true(raw->count * 8 + 1 < 1024);
    memcpy(v, raw->pts, raw->count * 8 * sizeof *v);
    v[raw->count * 8] = rep.max_error;
    expect_values(r, "offset", v, raw->count * 8 + 1);
    cf_cubics_destroy(raw);
    for (size_t m = 0; m < sizeof methods / sizeof methods[0]; m++) {
        cf_interp_options_t io;
        cf_bspline_t *s;
        cf_interp_options_init(&io);
        io.method = methods[m].method;
        if (io.method == CF_INTERP_GLOBAL) {
            io.degree = 2;
            io.param = CF_PARAM_CENTRIPETAL;
        }
        assert_int_equal(cf_interpolate(2, interp_data, 5, &io, &s, NULL),
                         0);
        expect_values(r, methods[m].key, v, spline_values(s, v));
        cf_bspline_destroy(s);
    }
}

static void
test_core_names_match_c_api(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("api_values.lua"), NULL };
    cf_bezier_t *c, *q, *left, *right;
    cf_bspline_t *s, *nb, *t, *ds;
    cf_bezier_list_t *list;
    double v[512], w3[3] = { 1, 0.5, 2 };
    size_t span;
    int mult;
    run_tool(r, args);
    assert_int_equal(r->status, 0);

    assert_int_equal(cf_bezier_create(2, 4, orazem, NULL, &c, NULL), 0);
    assert_int_equal(cf_bezier_create(2, 2, orazem, w3, &q, NULL), 0);
    assert_int_equal(cf_bezier_eval(c, 0.3, v), 0);
    expect_values(r, "eval", v, 2);
    assert_int_equal(cf_bezier_eval(q, 0.3, v), 0);
    expect_values(r, "reval", v, 2);
    assert_int_equal(cf_bezier_decasteljau(c, 0.75, v), 0);
    expect_values(r, "decasteljau", v, cf_bezier_decasteljau_size(c));
    assert_int_equal(cf_bezier_split(c, 0.3, &left, &right, NULL), 0);
    cf_bezier_get_points(left, v);
    cf_bezier_get_points(right, v + 10);
    expect_values(r, "split", v, 20);
    cf_bezier_destroy(left);
    assert_int_equal(cf_bezier_elevate(c, 2, &left, NULL), 0);
    cf_bezier_get_points(left, v);
    expect_values(r, "elevate", v, 14);
    cf_bezier_destroy(left);
    cf_bezier_destroy(right);
    assert_int_equal(cf_bezier_derivative(c, 1, &left, NULL), 0);
    assert_int_equal(cf_bezier_eval(left, 0.4, v), 0);
    cf_bezier_destroy(left);
    assert_int_equal(cf_bezier_derivative(q, 1, &left, NULL), 0);
    assert_int_equal(cf_bezier_eval(left, 0.4, v + 2), 0);
    v[4] = cf_bezier_degree(left);
    cf_bezier_destroy(left);
    expect_values(r, "derivative", v, 5);
    cf_bezier_get_points(q, v);
    cf_bezier_get_weights(q, v + 6);
    v[9] = cf_bezier_degree(q);
    expect_values(r, "rpoints", v, 10);

    assert_int_equal(cf_bspline_create(2, 2, sample_u, 11, sample, 8, NULL, &s,
                                       NULL), 0);
    assert_int_equal(cf_bspline_create(2, 2, sample_u, 11, sample, 8,
                                       sample_w, &nb, NULL), 0);
    assert_int_equal(cf_bspline_eval(s, 0.6, v), 0);
    assert_int_equal(cf_bspline_eval(nb, 0.6, v + 2), 0);
    expect_values(r, "beval", v, 4);
    assert_int_equal(cf_bspline_insert_knot(s, 0.6, 2, &t, NULL, NULL), 0);
    cf_bspline_get_points(t, v);
    memcpy(v + 20, cf_bspline_knots(t), 13 * sizeof *v);
    expect_values(r, "insert", v, 33);
    cf_bspline_destroy(t);
    assert_int_equal(cf_bspline_deboor(s, 0.5, v, &span, &mult), 0);
    v[12] = (double)span;
    v[13] = mult;
    expect_values(r, "deboor", v, 14);
    assert_int_equal(cf_bspline_to_beziers(nb, &list, NULL), 0);
    for (size_t i = 0; i < list->count; i++) {
        cf_bezier_get_points(list->items[i], v + 9 * i);
        cf_bezier_get_weights(list->items[i], v + 9 * i + 6);
    }
    expect_values(r, "to_beziers", v, 9 * list->count);
    cf_bezier_list_destroy(list);
    assert_int_equal(cf_bspline_derivative(s, 1, &ds, NULL), 0);
    assert_int_equal(cf_bspline_eval(ds, 0.45, v), 0);
    v[2] = cf_bspline_degree(ds);
    expect_values(r, "bderivative", v, 3);
    cf_bspline_destroy(ds);
    assert_int_equal(cf_bspline_elevate(s, 1, &ds, NULL), 0);
    cf_bspline_get_points(ds, v);
    expect_values(r, "belevate", v, 2 * cf_bspline_count(ds));
    cf_bspline_destroy(ds);
    cf_bspline_get_weights(nb, v);
    memcpy(v + 8, cf_bspline_knots(nb), 11 * sizeof *v);
    v[19] = cf_bspline_degree(nb);
    expect_values(r, "bqueries", v, 20);

    expect_offset_and_interp(r, c);

    cf_bspline_destroy(s);
    cf_bspline_destroy(nb);
    cf_bezier_destroy(c);
    cf_bezier_destroy(q);
}

/* ---- figures ------------------------------------------------------------ */

static void
test_several_figures_each_written(void **state)
{
    result *r = *state;
    const char *args[] = { "render", src("multi.lua"), "-o", "out", "-f",
                           "svg,png,pdf,ps,eps", "--manifest", "m.txt",
                           NULL };
    const char *ext[] = { "svg", "png", "pdf", "ps", "eps" };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "defined 3 figures\n");
    for (int k = 1; k <= 3; k++) {
        for (int e = 0; e < 5; e++) {
            char name[64];
            snprintf(name, sizeof name, "out/multi-%d.%s", k, ext[e]);
            if (!exists(r, name))
                fail_msg("%s was not written", name);
        }
    }
    assert_int_equal(count_files(r->dir), 1 + 15 + 1);
}

static void
test_list_and_only(void **state)
{
    result *r = *state;
    const char *list[] = { "list", src("multi.lua"), NULL };
    const char *llist[] = { "list", "-l", src("multi.lua"), NULL };
    const char *only[] = { "render", src("multi.lua"), "--only", "multi-2",
                           "-f", "svg", NULL };
    run_tool(r, list);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "multi-1\nmulti-2\nmulti-3\n");
    /* (a sanitizer build may append its own report to stderr) */
    assert_true(strncmp(r->err, "defined 3 figures\n", 18) == 0);
    reset(r);
    run_tool(r, llist);
    assert_contains(r->out, "multi-2\tpart 2 <of> 3\n");
    reset(r);
    run_tool(r, only);
    assert_int_equal(r->status, 0);
    assert_true(exists(r, "multi-2.svg"));
    assert_int_equal(count_files(r->dir), 1);
    /* an empty list is a usage error (it rendered nothing, status 0) */
    {
        const char *none[] = { "render", src("multi.lua"), "--only", "",
                               NULL };
        reset(r);
        run_tool(r, none);
        assert_int_equal(r->status, 2);
        assert_contains(r->err, "--only '': give the names of the figures");
        assert_int_equal(count_files(r->dir), 0);
    }
}

static void
test_gallery(void **state)
{
    result *r = *state;
    char man[600], html[600], page[65536];
    const char *render[] = { "render", src("multi.lua"), "--manifest",
                             "m.txt", NULL };
    const char *gallery[] = { "gallery", "-o", "index.html", "m.txt",
                              NULL };
    run_tool(r, render);
    assert_int_equal(r->status, 0);
    snprintf(man, sizeof man, "%s/m.txt", r->dir);
    slurp(man, page, sizeof page);
    assert_contains(page, "multi-1\tsvg,pdf,png\tpart 1 <of> 3\t");
    /* then the alt text (the caption) and the automatic description */
    assert_contains(page, "multi.lua\tpart 1 <of> 3\t");
    run_tool(r, gallery); /* in the same directory */
    assert_int_equal(r->status, 0);
    snprintf(html, sizeof html, "%s/index.html", r->dir);
    slurp(html, page, sizeof page);
    assert_contains(page, "<img src=\"multi-1.svg\"");
    assert_contains(page, "<a href=\"multi-3.pdf\">PDF</a>");
    assert_contains(page, "part 2 &lt;of&gt; 3");
    assert_true(strstr(page, "multi-1") < strstr(page, "multi-2"));
    /* an index of the groups, the figures beside their script's source,
    ** each linked to it */
    assert_contains(page, "<nav><ul>\n<li><a href=\"#g-multi\">multi</a>:"
                          " <a href=\"#multi-1\">1</a>");
    assert_contains(page, "<div class=\"src\" id=\"src-multi.lua\">"
                          "<h3>multi.lua</h3><pre>");
    assert_contains(page, "<a href=\"#src-multi.lua\">script</a>");
    assert_contains(page, "figure{");
}

/* Captions typeset like the labels: TeX-like scripts as HTML sub and sup,
** stacked when both follow a base; a lone ^ or _ is kept. */
static void
test_gallery_captions(void **state)
{
    result *r = *state;
    char html[600], page[65536];
    const char *gallery[] = { "gallery", "-o", "index.html", "m.txt",
                              NULL };
    /* the manifest first, in the tool's dir */
    put_file(r, "m.txt",
             "sir-a\tpng\tN_0^1 and P_{i,1} and C^{-1}, x ^ y, a_ b\n", NULL,
             0);
    run_tool(r, gallery);
    assert_int_equal(r->status, 0);
    snprintf(html, sizeof html, "%s/index.html", r->dir);
    slurp(html, page, sizeof page);
    assert_contains(page, "N<span class=\"ss\"><sup>1</sup><sub>0</sub>"
                          "</span> and P<sub>i,1</sub> and C<sup>-1</sup>, "
                          "x ^ y, a_ b");
    /* the seed's title for a known prefix; no source without a script */
    assert_contains(page, "<h2>Seed 000 · Zbyněk Šír");
    assert_true(strstr(page, "<pre>") == NULL);
}

/* A manifest the gallery cannot use is an error naming the file and the
** line, not a page without those figures (a line of one field, random
** bytes and a directory gave a page and status 0, a FIFO a hang); a line of any length
** is one line (a 20000-byte caption was read as pieces of 8191 bytes,
** each a line); -o naming a manifest is refused (it overwrote it). */
static void
test_gallery_bad_manifests(void **state)
{
    result *r = *state;
    char man[600], html[600], page[65536], line[20020];
    const char *gallery[] = { "gallery", "-o", "index.html", "m.txt",
                              NULL };
    const char *dir[] = { "gallery", "-o", "index.html", "/tmp", NULL };
    const char *over[] = { "gallery", "-o", "m.txt", "m.txt", NULL };
    const char *caption;
    put_file(r, "m.txt", "sir-a\tpng\tfine\n\nsir-b png caption without "
             "tabs\n", NULL, 0);
    run_tool(r, gallery);
    assert_int_equal(r->status, 2);
    assert_contains(r->err, "curvefig: gallery: m.txt:3: not a manifest "
                            "line: it has fewer than the fields NAME, "
                            "FORMATS and CAPTION");
    assert_int_equal(count_files(r->dir), 1);

    reset(r);
    run_tool(r, dir);
    assert_int_equal(r->status, 2);
    assert_contains(r->err, "cannot read /tmp: it is a directory, not a "
                            "file");

    /* a FIFO blocked the reader for ever, /dev/zero fed it for ever */
    reset(r);
    own_dir(r);
    snprintf(man, sizeof man, "%s/m.txt", r->dir);
    assert_int_equal(mkfifo(man, 0600), 0);
    run_tool(r, gallery);
    assert_int_equal(r->status, 2);
    assert_contains(r->err, "cannot read m.txt: it is not a regular file");
    {
        const char *zero[] = { "gallery", "-o", "index.html", "/dev/zero",
                               NULL };
        run_tool(r, zero);
        assert_int_equal(r->status, 2);
        assert_contains(r->err, "cannot read /dev/zero: it is not a regular "
                                "file");
    }

    reset(r);
    /* a caption of 20000 bytes */
    memcpy(line, "sir-a\tpng\t", 10);
    memset(line + 10, 'c', 20000);
    memcpy(line + 20010, "\n", 2);
    caption = line + 10;
    put_file(r, "m.txt", line, man, sizeof man);
    line[20010] = '\0';   /* the caption alone, for the page */
    run_tool(r, over);
    assert_int_equal(r->status, 2);
    assert_contains(r->err, "-o m.txt is the manifest m.txt; the gallery "
                            "would overwrite it");
    slurp(man, page, sizeof page);
    assert_true(strncmp(page, "sir-a\tpng\tccc", 13) == 0);
    run_tool(r, gallery);
    assert_int_equal(r->status, 0);
    snprintf(html, sizeof html, "%s/index.html", r->dir);
    slurp(html, page, sizeof page);
    /* one figure, its whole caption */
    assert_contains(page, caption);
    assert_contains(page, "id=\"sir-a\"");
    assert_null(strstr(strstr(page, "id=\"sir-a\"") + 1, "id=\"sir-a\""));
}

/* Every file the tool writes goes through one writer that neither
** follows nor truncates a file planted beside the target: symbolic links
** at the old predictable temporary names (PATH.tmp~) and at the target
** itself leave the file they point to untouched; the new files are
** regular, their mode honours the umask, and no temporary file is left. */
static void
test_writes_follow_no_link(void **state)
{
    result *r = *state;
    char victim[600], path[600], page[65536];
    const char *render[] = { "render", src("multi.lua"), "-f", "svg,png",
                             "--manifest", "m.txt", NULL };
    const char *gallery[] = { "gallery", "-o", "index.html", "m.txt",
                              NULL };
    const char *planted[] = { "m.txt.tmp~", "index.html.tmp~",
                              "multi-1.svg.tmp~", "multi-2.png" };
    struct stat sb;
    mode_t old;
    FILE *f;
    snprintf(r->dir, sizeof r->dir, "/tmp/curvefig-test-XXXXXX");
    assert_non_null(mkdtemp(r->dir));
    snprintf(victim, sizeof victim, "%s/victim", r->dir);
    f = fopen(victim, "w");
    assert_non_null(f);
    fputs("precious\n", f);
    fclose(f);
    for (size_t i = 0; i < sizeof planted / sizeof planted[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", r->dir, planted[i]);
        assert_int_equal(symlink(victim, path), 0);
    }
    old = umask(027);
    run_tool(r, render);
    assert_int_equal(r->status, 0);
    run_tool(r, gallery);
    umask(old);
    assert_int_equal(r->status, 0);
    slurp(victim, page, sizeof page);
    assert_string_equal(page, "precious\n");
    for (size_t i = 0; i < 4; i++) {
        const char *made[] = { "m.txt", "index.html", "multi-1.svg",
                               "multi-2.png" };
        snprintf(path, sizeof path, "%s/%s", r->dir, made[i]);
        assert_int_equal(lstat(path, &sb), 0);
        if (!S_ISREG(sb.st_mode) || (sb.st_mode & 0777) != 0640)
            fail_msg("%s: mode %o, want a regular file of mode 640 (umask "
                     "027)", made[i], (unsigned)sb.st_mode);
    }
    {
        DIR *d = opendir(r->dir);
        struct dirent *e;
        assert_non_null(d);
        while ((e = readdir(d)) != NULL)
            if (strncmp(e->d_name, ".cf-tmp-", 8) == 0)
                fail_msg("a temporary file was left: %s", e->d_name);
        closedir(d);
    }
}

/* The gallery's title is text, not markup. */
static void
test_gallery_title_escaped(void **state)
{
    result *r = *state;
    char html[600], page[65536];
    const char *render[] = { "render", src("multi.lua"), "-f", "svg",
                             "--manifest", "m.txt", NULL };
    const char *gallery[] = { "gallery", "-o", "index.html", "--title",
                              "<script>alert('x')</script> & \"q\"", "m.txt",
                              NULL };
    run_tool(r, render);
    assert_int_equal(r->status, 0);
    run_tool(r, gallery);
    assert_int_equal(r->status, 0);
    snprintf(html, sizeof html, "%s/index.html", r->dir);
    slurp(html, page, sizeof page);
    assert_contains(page, "<title>&lt;script&gt;alert(&#39;x&#39;)&lt;/"
                          "script&gt; &amp; &quot;q&quot;</title>");
    assert_contains(page, "<h1>&lt;script&gt;alert(&#39;x&#39;)");
    assert_true(strstr(page, "<script") == NULL);
}

static void
test_every_figure_method(void **state)
{
    result *r = *state;
    const char *args[] = { "render", src("figure_api.lua"), "-f", "svg",
                           "--no-labels", NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "figure api: ok\n");
    assert_true(exists(r, "api-all.svg"));
    assert_true(exists(r, "api-plot.svg"));
    assert_true(exists(r, "api-3d.svg"));
    assert_int_equal(count_files(r->dir), 5);
}

/* label_place as a function(i, x, y): the figure is the one drawn with the
** table of the places it returns, byte for byte but for the <title>. */
static void
test_label_place_function(void **state)
{
    result *r = *state;
    const char *args[] = { "render", src("label_place_fn.lua"), "-f", "svg",
                           "--only", "place-table,place-fn", NULL };
    static char a[65536], b[65536];
    char path[600];
    const char *ta, *tb;
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_string_equal(r->out, "label_place function: ok\n");
    snprintf(path, sizeof path, "%s/place-table.svg", r->dir);
    slurp(path, a, sizeof a);
    snprintf(path, sizeof path, "%s/place-fn.svg", r->dir);
    slurp(path, b, sizeof b);
    ta = strstr(a, "</title>");
    tb = strstr(b, "</title>");
    assert_non_null(ta);
    assert_non_null(tb);
    assert_true(strlen(ta) > 1000);   /* the labels' glyphs are in it */
    assert_string_equal(ta, tb);
}

int
main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        T(test_core_bezier_script),
        T(test_core_surface_script),
        T(test_core_bspline_script),
        T(test_core_more_script),
        T(test_core_reduce_script),
        T(test_pairs_order),
        T(test_core_names_match_c_api),
        T(test_several_figures_each_written),
        T(test_list_and_only),
        T(test_gallery),
        T(test_gallery_captions),
        T(test_gallery_bad_manifests),
        T(test_writes_follow_no_link),
        T(test_gallery_title_escaped),
        T(test_every_figure_method),
        T(test_label_place_function),
    };
    if (tool_args(argc, argv) != 0)
        return 2;
    return cmocka_run_group_tests(tests, NULL, NULL);
}

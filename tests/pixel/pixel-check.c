/*
** pixel-check: the pixel test of one figure script.
**
**   pixel-check [--update] [--expect-mismatch] TOOL REFDIR OUTDIR SCRIPT...
**
** For every SCRIPT (outputs go to OUTDIR/<script name without .lua>/):
** 1. `TOOL render SCRIPT -o OUTDIR -f svg,png --dpi 144` (and again with
**    --no-labels into OUTDIR/nolabels) and `TOOL list SCRIPT` for the names.
** 2. For every figure: rasterise its SVG with librsvg at the same 144 dpi
**    and compare with cairo's own PNG (the same picture through two paths):
**    strictly for the label-free layer, with the looser text tolerance for
**    the labelled figure (glyphs are hinted differently by the two paths).
** 3. Compare cairo's PNGs with the committed references REFDIR/NAME.png
**    (labelled, text tolerance) and REFDIR/nolabels/NAME.png (strict).
** --update writes the references instead of comparing with them.
** --expect-mismatch inverts the reference comparison (the perturbation test
**    proves the suite fails when a figure changes).
** On a failure the actual, expected and diff images are written to OUTDIR
** and their paths printed.
**
** Thresholds (see pixelcmp.h for the measure):
** - threshold 0.1: pixelmatch's default; a difference of 0.1 in normalised
**   YIQ distance is about 26 grey levels, far above rounding differences
**   between rasterisers (1-3 levels) and far below any real stroke (a grey
**   polygon on white is > 0.4).
** - aa_radius 1: an edge may land one pixel away (sub-pixel placement of
**   the same geometry); a control point moved by 1 pt moves 2 pixels at 144
**   dpi, which the allowance does not forgive.
** - label-free layer: 0 bad pixels allowed: librsvg draws through cairo, so
**   the same paths rasterise the same.
** - labelled figures: up to TEXT_BAD_FRACTION of the pixels, for glyph
**   rasterisation differences between cairo's text path (hinted glyphs)
**   and librsvg's glyph outlines.  Measured on this project's figures: at
**   most 3 such pixels in a figure of ~150,000 (0.002 %); the allowance,
**   0.05 %, is 25 times that, and the label-free layer, which a moved
**   control point always changes, stays strict.
*/
#include <cairo.h>
#include <errno.h>
#include <librsvg/rsvg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "pixelcmp.h"

#define DPI 144.0
#define TEXT_BAD_FRACTION 0.0005

static int
run(char *const argv[], char *out, size_t cap)
{
    int fd[2], status;
    pid_t pid;
    size_t len = 0;
    if (pipe(fd) != 0)
        return -1;
    pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        dup2(fd[1], STDOUT_FILENO);
        close(fd[0]);
        close(fd[1]);
        execv(argv[0], argv);
        _exit(127);
    }
    close(fd[1]);
    for (;;) {
        ssize_t n;
        char sink[4096];
        if (out != NULL && len + 1 < cap)
            n = read(fd[0], out + len, cap - 1 - len);
        else
            n = read(fd[0], sink, sizeof sink);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        if (out != NULL && len + 1 < cap)
            len += (size_t)n;
    }
    if (out != NULL)
        out[len] = '\0';
    close(fd[0]);
    if (waitpid(pid, &status, 0) < 0)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static cairo_surface_t *
load_png(const char *path)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    cairo_surface_t *img;
    cairo_t *cr;
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(s);
        return NULL;
    }
    /* normalise to ARGB32 */
    img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                     cairo_image_surface_get_width(s),
                                     cairo_image_surface_get_height(s));
    cr = cairo_create(img);
    cairo_set_source_surface(cr, s, 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    cairo_surface_flush(img);
    return img;
}

static cairo_surface_t *
rasterise_svg(const char *path, int w, int h)
{
    GError *err = NULL;
    RsvgHandle *hd = rsvg_handle_new_from_file(path, &err);
    cairo_surface_t *img;
    cairo_t *cr;
    RsvgRectangle vp = { 0, 0, (double)w, (double)h };
    if (hd == NULL) {
        fprintf(stderr, "librsvg cannot read %s: %s\n", path,
                err ? err->message : "?");
        if (err)
            g_error_free(err);
        return NULL;
    }
    rsvg_handle_set_dpi(hd, DPI);
    /* the document at its own size (pt at DPI), not stretched to the
    ** PNG's whole-pixel size: cairo's PNG is the page at DPI from the
    ** origin, its last partial pixel row and column rounded up */
    {
        gdouble sw, sh;
        if (rsvg_handle_get_intrinsic_size_in_pixels(hd, &sw, &sh)) {
            vp.width = sw;
            vp.height = sh;
        }
    }
    img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cr = cairo_create(img);
    if (!rsvg_handle_render_document(hd, cr, &vp, &err)) {
        fprintf(stderr, "librsvg cannot render %s: %s\n", path,
                err ? err->message : "?");
        if (err)
            g_error_free(err);
        cairo_destroy(cr);
        cairo_surface_destroy(img);
        g_object_unref(hd);
        return NULL;
    }
    cairo_destroy(cr);
    g_object_unref(hd);
    cairo_surface_flush(img);
    return img;
}

static pc_image
view(cairo_surface_t *s)
{
    pc_image im;
    im.width = cairo_image_surface_get_width(s);
    im.height = cairo_image_surface_get_height(s);
    im.stride = cairo_image_surface_get_stride(s);
    im.data = cairo_image_surface_get_data(s);
    return im;
}

static void
write_failure(const char *outdir, const char *name, const char *what,
              cairo_surface_t *actual, cairo_surface_t *expected,
              const pc_image *a, const pc_image *e, const pc_options *opt)
{
    char p[8192];
    pc_result r;
    cairo_surface_t *d = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                                    a->width, a->height);
    cairo_surface_flush(d);
    if (a->width == e->width && a->height == e->height) {
        unsigned char *buf = malloc((size_t)a->width * (size_t)a->height * 4);
        if (buf != NULL) {
            pc_compare(a, e, opt, &r, buf);
            unsigned char *dst = cairo_image_surface_get_data(d);
            int ds = cairo_image_surface_get_stride(d);
            for (int y = 0; y < a->height; y++)
                memcpy(dst + (size_t)y * (size_t)ds,
                       buf + (size_t)y * (size_t)a->width * 4,
                       (size_t)a->width * 4);
            cairo_surface_mark_dirty(d);
            free(buf);
        }
    }
    snprintf(p, sizeof p, "%s/%s.%s.actual.png", outdir, name, what);
    cairo_surface_write_to_png(actual, p);
    fprintf(stderr, "  actual:   %s\n", p);
    snprintf(p, sizeof p, "%s/%s.%s.expected.png", outdir, name, what);
    cairo_surface_write_to_png(expected, p);
    fprintf(stderr, "  expected: %s\n", p);
    snprintf(p, sizeof p, "%s/%s.%s.diff.png", outdir, name, what);
    cairo_surface_write_to_png(d, p);
    fprintf(stderr, "  diff:     %s\n", p);
    cairo_surface_destroy(d);
}

/* Compare; print the verdict; return 1 on match. */
static int
compare(const char *outdir, const char *name, const char *what,
        cairo_surface_t *actual, cairo_surface_t *expected, int text)
{
    pc_image a = view(actual), e = view(expected);
    pc_options opt = { 0.1, 1, 0 };
    pc_result r;
    if (text)
        opt.max_bad_pixels =
            (long)(TEXT_BAD_FRACTION * (double)a.width * (double)a.height);
    if (pc_compare(&a, &e, &opt, &r, NULL) != 0) {
        fprintf(stderr, "%s %s: size %dx%d differs from %dx%d\n", name, what,
                a.width, a.height, e.width, e.height);
        write_failure(outdir, name, what, actual, expected, &a, &e, &opt);
        return 0;
    }
    printf("%s %s: %s, %ld bad pixels (allowed %ld), %ld anti-aliasing, "
           "max delta %.3f\n",
           name, what, r.identical ? "identical" : (r.match ? "match" : "MISMATCH"),
           r.bad_pixels, opt.max_bad_pixels, r.aa_pixels, r.max_delta);
    if (r.bad_pixels > 0) {
        printf("  first bad pixels at");
        for (long k = 0; k < r.bad_pixels && k < 4; k++)
            printf(" (%d, %d)", r.bad_x[k], r.bad_y[k]);
        printf("\n");
    }
    if (!r.match)
        write_failure(outdir, name, what, actual, expected, &a, &e, &opt);
    return r.match;
}

static int
copy_file(const char *from, const char *to)
{
    char buf[65536];
    size_t n;
    char tmp[8192];
    FILE *in = fopen(from, "rb"), *out;
    if (in == NULL)
        return -1;
    if (snprintf(tmp, sizeof tmp, "%s.tmp", to) >= (int)sizeof tmp) {
        fclose(in);
        return -1;
    }
    out = fopen(tmp, "wb");
    if (out == NULL) {
        fclose(in);
        return -1;
    }
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        fwrite(buf, 1, n, out);
    fclose(in);
    if (fclose(out) != 0)
        return -1;
    return rename(tmp, to);
}

static int
check_script(const char *tool, const char *script, const char *refdir,
             const char *outdir, int update, int expect_mismatch)
{
    int failures = 0, nfig = 0, mismatch_seen = 0, mismatch_missed = 0;
    char names[65536], nolabels[4096], dpi[16];

    snprintf(nolabels, sizeof nolabels, "%s/nolabels", outdir);
    snprintf(dpi, sizeof dpi, "%d", (int)DPI);
    mkdir(outdir, 0777);
    mkdir(nolabels, 0777);
    if (update) {
        char p[8192];
        snprintf(p, sizeof p, "%s/nolabels", refdir);
        mkdir(p, 0777);
    }

    {
        char *a1[] = { (char *)tool, "render", (char *)script, "-o",
                       (char *)outdir, "-f", "svg,png", "--dpi", dpi, NULL };
        char *a2[] = { (char *)tool, "render", (char *)script, "-o",
                       nolabels, "-f", "svg,png", "--dpi", dpi, "--no-labels",
                       NULL };
        char *a3[] = { (char *)tool, "list", (char *)script, NULL };
        if (run(a1, NULL, 0) != 0 || run(a2, NULL, 0) != 0) {
            fprintf(stderr, "%s: rendering failed\n", script);
            return 1;
        }
        if (run(a3, names, sizeof names) != 0) {
            fprintf(stderr, "%s: listing failed\n", script);
            return 1;
        }
    }

    for (char *line = strtok(names, "\n"); line != NULL;
         line = strtok(NULL, "\n")) {
        char name[256], p[8192];
        cairo_surface_t *png, *svg, *ref;
        if (sscanf(line, "%255s", name) != 1)
            continue;
        nfig++;

        for (int layer = 0; layer < 2; layer++) {
            const char *dir = layer == 0 ? nolabels : outdir;
            snprintf(p, sizeof p, "%s/%s.png", dir, name);
            png = load_png(p);
            if (png == NULL) {
                fprintf(stderr, "%s: cannot read %s\n", name, p);
                failures++;
                continue;
            }
            snprintf(p, sizeof p, "%s/%s.svg", dir, name);
            svg = rasterise_svg(p, cairo_image_surface_get_width(png),
                                cairo_image_surface_get_height(png));
            if (svg == NULL) {
                failures++;
            } else {
                if (!compare(dir, name, layer == 0 ? "svg-vs-png(no labels)"
                                                   : "svg-vs-png",
                             svg, png, layer == 1))
                    failures++;
                cairo_surface_destroy(svg);
            }
            cairo_surface_destroy(png);
        }

        /* against the references: the label-free layer strictly, the
        ** labelled figure with the text tolerance */
        for (int layer = 0; layer < 2; layer++) {
            const char *dir = layer == 0 ? nolabels : outdir;
            char ref_path[8192];
            int ok;
            snprintf(p, sizeof p, "%s/%s.png", dir, name);
            png = load_png(p);
            if (png == NULL)
                continue;
            snprintf(ref_path, sizeof ref_path, "%s/%s%s.png", refdir,
                     layer == 0 ? "nolabels/" : "", name);
            if (update) {
                if (copy_file(p, ref_path) != 0) {
                    fprintf(stderr, "%s: cannot write %s\n", name, ref_path);
                    failures++;
                } else {
                    printf("%s: reference updated: %s\n", name, ref_path);
                }
                cairo_surface_destroy(png);
                continue;
            }
            ref = load_png(ref_path);
            if (ref == NULL) {
                fprintf(stderr, "%s: no reference image %s (run `ninja -C "
                        "build update-references`)\n", name, ref_path);
                failures++;
                cairo_surface_destroy(png);
                continue;
            }
            ok = compare(dir, name,
                         layer == 0 ? "vs-reference(no labels)"
                                    : "vs-reference",
                         png, ref, layer == 1);
            if (expect_mismatch) {
                if (ok)
                    mismatch_missed++;
                else
                    mismatch_seen++;
            } else if (!ok) {
                failures++;
            }
            cairo_surface_destroy(ref);
            cairo_surface_destroy(png);
        }
    }
    if (expect_mismatch) {
        if (mismatch_seen == 0) {
            fprintf(stderr, "%s: the perturbed figure was NOT detected\n",
                    script);
            failures++;
        } else {
            printf("%s: perturbation detected, as expected (%d of %d "
                   "comparisons differ)\n", script, mismatch_seen,
                   mismatch_seen + mismatch_missed);
        }
    }
    if (nfig == 0) {
        fprintf(stderr, "%s: the script defines no figure\n", script);
        return 1;
    }
    return failures ? 1 : 0;
}

int
main(int argc, char **argv)
{
    const char *tool, *refdir, *outdir;
    int update = 0, expect_mismatch = 0, failures = 0, i = 1;
    char dir[4096];

    for (; i < argc && strncmp(argv[i], "--", 2) == 0; i++) {
        if (strcmp(argv[i], "--update") == 0)
            update = 1;
        else if (strcmp(argv[i], "--expect-mismatch") == 0)
            expect_mismatch = 1;
        else
            break;
    }
    if (argc - i < 4) {
        fprintf(stderr, "usage: %s [--update] [--expect-mismatch] TOOL "
                "REFDIR OUTDIR SCRIPT...\n", argv[0]);
        return 2;
    }
    tool = argv[i++];
    refdir = argv[i++];
    outdir = argv[i++];
    mkdir(outdir, 0777);
    for (; i < argc; i++) {
        const char *base = strrchr(argv[i], '/');
        size_t len;
        base = base ? base + 1 : argv[i];
        len = strlen(base);
        if (len > 4 && strcmp(base + len - 4, ".lua") == 0)
            len -= 4;
        if (snprintf(dir, sizeof dir, "%s/%.*s", outdir, (int)len, base) >=
            (int)sizeof dir)
            return 2;
        failures += check_script(tool, argv[i], refdir, dir, update,
                                 expect_mismatch);
    }
    return failures ? 1 : 0;
}

/*
** `curvefig compare A B`: two images (PNG or SVG) through the comparator.
**
**   curvefig compare A B [--diff D.png] [--dpi N] [--threshold T]
**                        [--aa-radius R] [--max-bad N | P%]
**
** Prints what each file is, then the verdict (the number and share of
** differing pixels, how many more differ by anti-aliasing only); --diff
** writes the diff image.  Exit status 0 the same picture, 1 different,
** 2 an error (a file missing or not an image, sizes that differ, usage).
*/
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checks.h"
#include "imgfile.h"

#define SAME 0
#define DIFFERENT 1
#define ERROR 2

int
cf__tool_option_number(const char *opt, const char *s, double lo, double hi,
                       double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (errno != 0 || end == s || *end != '\0' || !(v >= lo && v <= hi)) {
        fprintf(stderr, "curvefig: %s '%s': give a number from %g to %g\n",
                opt, s, lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

void
cf__tool_default_imgcmp(cf__imgcmp_options *opt)
{
    opt->threshold = CF__IMGCMP_THRESHOLD;
    opt->aa_radius = CF__IMGCMP_AA_RADIUS;
    opt->max_bad_pixels = 0;
}

typedef struct compare_args {
    const char *file[2];
    const char *diff;
    double dpi;
    bool dpi_given;       /* --dpi; else a PNG operand's own resolution */
    double max_bad;       /* pixels, or a share when max_bad_share */
    int max_bad_share;
    cf__imgcmp_options opt;
} compare_args;

int
cf__tool_usage(const char *command, const char *what, const char *arg)
{
    fprintf(stderr, "curvefig: %s: %s%s\nTry 'curvefig help %s'.\n",
            command, what, arg, command);
    return ERROR;
}

static int
usage(const char *what, const char *arg)
{
    return cf__tool_usage("compare", what, arg);
}

/* --max-bad N (pixels) or P% (a share of the pixels). */
static int
parse_max_bad(const char *v, compare_args *a)
{
    size_t n = strlen(v);
    char buf[64];
    if (n > 0 && n < sizeof buf && v[n - 1] == '%') {
        memcpy(buf, v, n - 1);
        buf[n - 1] = '\0';
        a->max_bad_share = 1;
        return cf__tool_option_number("--max-bad", buf, 0, 100, &a->max_bad);
    }
    a->max_bad_share = 0;
    return cf__tool_option_number("--max-bad", v, 0, 1e12, &a->max_bad);
}

/* 0, or the exit status to return. */
static int
parse(int argc, char **argv, compare_args *a)
{
    int nfiles = 0;
    double r;
    memset(a, 0, sizeof *a);
    a->dpi = CF__IMGCMP_DPI;
    cf__tool_default_imgcmp(&a->opt);
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(o, "-h") == 0 || strcmp(o, "--help") == 0) {
            cf__tool_checks_help("compare");
            return -1;
        }
        if (o[0] != '-' || o[1] == '\0') {
            if (nfiles == 2)
                return usage("give exactly two images; extra operand ", o);
            a->file[nfiles++] = o;
            continue;
        }
        if (v == NULL && (strcmp(o, "--diff") == 0 ||
                          strcmp(o, "--dpi") == 0 ||
                          strcmp(o, "--threshold") == 0 ||
                          strcmp(o, "--aa-radius") == 0 ||
                          strcmp(o, "--max-bad") == 0))
            return usage("this option needs a value: ", o);
        if (strcmp(o, "--diff") == 0) {
            a->diff = v;
        } else if (strcmp(o, "--dpi") == 0) {
            if (cf__tool_option_number(o, v, 1, 2400, &a->dpi) != 0)
                return ERROR;
            a->dpi_given = true;
        } else if (strcmp(o, "--threshold") == 0) {
            if (cf__tool_option_number(o, v, 0, 1, &a->opt.threshold) != 0)
                return ERROR;
        } else if (strcmp(o, "--aa-radius") == 0) {
            if (cf__tool_option_number(o, v, 0, 8, &r) != 0)
                return ERROR;
            a->opt.aa_radius = (int)r;
        } else if (strcmp(o, "--max-bad") == 0) {
            if (parse_max_bad(v, a) != 0)
                return ERROR;
        } else {
            return usage("unknown option ", o);
        }
        i++;
    }
    if (nfiles != 2)
        return usage("give two images, A and B", "");
    /* an SVG against a PNG: the SVG at the resolution the PNG records
    ** (curvefig writes it), so that a figure's own SVG and PNG compare */
    for (int k = 0; k < 2 && !a->dpi_given; k++) {
        double dpi = cf__tool_png_dpi(a->file[k]);
        if (dpi >= 1 && dpi <= 2400) {
            a->dpi = dpi;
            break;
        }
    }
    return 0;
}

static void
describe(const char *path, cf__image *s, double dpi)
{
    const char *kind = cf__tool_image_kind(path);
    printf("%s: %s", path, kind);
    if (strcmp(kind, "SVG") == 0)
        printf(" rasterised at %g dpi", dpi);
    printf(", %dx%d pixels\n", s->width, s->height);
}

static int
compare_images(const compare_args *a, cf__image *img[2])
{
    cf__imgcmp_options opt = a->opt;
    cf__imgcmp_result res;
    cf__image *diff = NULL;
    int w = img[0]->width;
    int h = img[0]->height;
    long pixels = (long)w * (long)h;
    char verdict[512];

    opt.max_bad_pixels = a->max_bad_share
                             ? (long)(a->max_bad / 100.0 * (double)pixels)
                             : (long)a->max_bad;
    /* B is the expected image: the diff fades B and marks A's changes */
    if (cf__tool_image_compare(img[0], img[1], &opt, &res,
                               a->diff != NULL ? &diff : NULL) != 0) {
        fprintf(stderr, "curvefig: compare: the sizes differ: %s is %dx%d "
                "pixels, %s is %dx%d pixels\n", a->file[0], w, h, a->file[1],
                img[1]->width, img[1]->height);
        return ERROR;
    }
    cf__tool_image_verdict(verdict, sizeof verdict, &res, &opt, pixels);
    printf("%s\n", verdict);
    if (res.bad_pixels > 0) {
        printf("first differing pixels (x, y from the top left):");
        for (long k = 0; k < res.bad_pixels && k < 4; k++)
            printf(" (%d, %d)", res.bad_x[k], res.bad_y[k]);
        printf("\n");
    }
    if (a->diff != NULL) {
        if (diff == NULL) {
            fprintf(stderr, "curvefig: compare: out of memory for the diff "
                    "image\n");
            return ERROR;
        }
        if (cf__tool_image_write_png(diff, a->diff) != 0) {
            fprintf(stderr, "curvefig: compare: cannot write %s: %s\n",
                    a->diff, strerror(errno));
            cf__image_destroy(diff);
            return ERROR;
        }
        cf__image_destroy(diff);
        printf("diff: %s (B faded; red: differs, yellow: anti-aliasing "
               "only)\n", a->diff);
    }
    return res.match ? SAME : DIFFERENT;
}

int
cf__tool_compare(int argc, char **argv)
{
    compare_args a;
    cf__image *img[2] = { NULL, NULL };
    char err[1024];
    int rc = parse(argc, argv, &a);
    if (rc != 0)
        return rc < 0 ? 0 : rc;
    for (int k = 0; k < 2; k++) {
        img[k] = cf__tool_image_read(a.file[k], a.dpi, err, sizeof err);
        if (img[k] == NULL) {
            fprintf(stderr, "curvefig: compare: %s\n", err);
            if (k == 1)
                cf__image_destroy(img[0]);
            return ERROR;
        }
    }
    describe(a.file[0], img[0], a.dpi);
    describe(a.file[1], img[1], a.dpi);
    rc = compare_images(&a, img);
    cf__image_destroy(img[0]);
    cf__image_destroy(img[1]);
    return rc;
}

/*
** `curvefig test`: figure scripts against reference images.
**
**   curvefig test [SCRIPT.lua... | DIR...] --references REF [-o OUT]
**                 [--update] [--dpi N] [--threshold T]
**
** Every figure of every script (a DIR stands for its *.lua files) is
** rendered as `render -f svg,png` does, once with its labels into OUT and
** once without into OUT/nolabels.  Each figure then passes four
** comparisons (imgcmp.h gives the rules):
**   its SVG rasterised by librsvg against cairo's PNG, without labels
**   (strict) and with labels (the text allowance): two rasterisers, one
**   picture;
**   its PNG against REF/nolabels/NAME.png (strict) and REF/NAME.png (the
**   text allowance): the picture has not changed.
** A figure with overlay steps is checked step by step too: its files
** NAME-K.svg and NAME-K.png (step K alone, as `render --steps` writes
** them) against REF/NAME-K.png and REF/nolabels/NAME-K.png, and a failure
** says which step differs.
** Failures get their expected, actual and diff images in OUT/failures and
** a section of OUT/report.html.  With DIR operands only, a reference no
** figure produces any more is a failure too (the figure was removed).
** --update writes the references instead (each through a temporary name)
** and lists every figure as new, changed or unchanged, and with DIR
** operands removes the references of figures that are gone.
*/
#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "checks.h"
#include "curvefig/figure.h"
#include "imgfile.h"
#include "refs.h"
#include "report.h"
#include "script.h"
#include "operands.h"
#include "tool.h"

#define PASSED 0
#define FAILED 1
#define ERROR 2

typedef struct produced {
    char *name;
    const char *script;
    unsigned steps;            /* overlay steps (1: none) */
} produced;

typedef struct test_run {
    const char *refdir, *outdir;
    char *out_nolabels, *out_failures, *ref_nolabels;
    double dpi;
    double threshold;
    bool update;
    cf__tool_scripts scripts;
    produced *figs;            /* the figures rendered */
    size_t nfigs, capfigs;
    cf__tool_failure *fails;
    size_t nfails, capfails;
    size_t failed_figures, stale, errors;
    size_t added, changed, unchanged, removed;
} test_run;

static int
usage(const char *what, const char *arg)
{
    return cf__tool_usage("test", what, arg);
}

static int
grow(void **p, size_t *cap, size_t n, size_t size)
{
    void *q;
    size_t c;
    if (n < *cap)
        return 0;
    c = *cap ? 2 * *cap : 16;
    q = realloc(*p, c * size);
    if (q == NULL)
        return -1;
    *p = q;
    *cap = c;
    return 0;
}

/* 0, or the exit status to return (-1: help printed). */
static int
parse(int argc, char **argv, test_run *t)
{
    bool operands = false;
    t->outdir = "curvefig-test";
    t->dpi = CF__IMGCMP_DPI;
    t->threshold = CF__IMGCMP_THRESHOLD;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(o, "-h") == 0 || strcmp(o, "--help") == 0) {
            cf__tool_checks_help("test");
            return -1;
        } else if (strcmp(o, "--update") == 0) {
            t->update = true;
            continue;
        } else if (o[0] != '-' || o[1] == '\0') {
            operands = true;
            if (cf__tool_scripts_add(&t->scripts, o) != 0)
                return ERROR;
            continue;
        } else if (v == NULL && (strcmp(o, "--references") == 0 ||
                                 strcmp(o, "-o") == 0 ||
                                 strcmp(o, "--output") == 0 ||
                                 strcmp(o, "--dpi") == 0 ||
                                 strcmp(o, "--threshold") == 0)) {
            return usage("this option needs a value: ", o);
        } else if (strcmp(o, "--references") == 0) {
            t->refdir = v;
        } else if (strcmp(o, "-o") == 0 || strcmp(o, "--output") == 0) {
            t->outdir = v;
        } else if (strcmp(o, "--dpi") == 0) {
            if (cf__tool_option_number(o, v, 1, 2400, &t->dpi) != 0)
                return ERROR;
        } else if (strcmp(o, "--threshold") == 0) {
            if (cf__tool_option_number(o, v, 0, 1, &t->threshold) != 0)
                return ERROR;
        } else {
            return usage("unknown option ", o);
        }
        i++;
    }
    if (!operands)
        return usage("give the figure scripts, or a directory of them", "");
    if (t->refdir == NULL)
        return usage("give the directory of the reference images: "
                     "--references DIR", "");
    return 0;
}

/* ---- rendering ---------------------------------------------------------- */

static const char *
owner_of(const test_run *t, const char *name)
{
    for (size_t i = 0; i < t->nfigs; i++)
        if (strcmp(t->figs[i].name, name) == 0)
            return t->figs[i].script;
    return NULL;
}

/* Whether a reference image named name belongs to a figure of the run:
** the figure's own, or one of its steps (NAME-K). */
static bool
has_figure(const test_run *t, const char *name)
{
    for (size_t i = 0; i < t->nfigs; i++) {
        size_t n = strlen(t->figs[i].name);
        char *end;
        unsigned long k;
        if (strcmp(t->figs[i].name, name) == 0)
            return true;
        if (t->figs[i].steps < 2 || strncmp(t->figs[i].name, name, n) != 0
            || name[n] != '-' || name[n + 1] < '1' || name[n + 1] > '9')
            continue;
        k = strtoul(name + n + 1, &end, 10);
        if (*end == '\0' && k <= t->figs[i].steps)
            return true;
    }
    return false;
}

/* Run script with or without labels and write its figures as SVG and PNG
** into dir, as `curvefig render -f svg,png` does.  Returns the number of
** figures, or -1 (the message printed).  With labels the names are
** recorded. */
static int
render_layer(test_run *t, const char *script, bool labels, const char *dir)
{
    cf_script_t *s = NULL;
    cf_diag_t diag;
    cf_write_options_t wo;
    int n = -1;
    cf_diag_clear(&diag);
    if (cf_script_create(NULL, stderr, &s, &diag) != CF_STATUS_OK) {
        fprintf(stderr, "curvefig: %s\n", diag.msg);
        return -1;
    }
    cf_script_set_labels(s, labels);
    if (cf_script_run_file(s, script) != CF_STATUS_OK) {
        fprintf(stderr, "curvefig: %s\n", cf_script_error(s));
        cf_script_destroy(s);
        return -1;
    }
    cf_write_options_init(&wo);
    wo.dpi = t->dpi;
    wo.step_files = true;   /* NAME-K.svg, .png: each overlay step */
    for (size_t i = 0; i < cf_script_figure_count(s); i++) {
        const char *name = cf_script_figure_name(s, i);
        const char *other = owner_of(t, name);
        char *base;
        cf_status_t st;
        if (labels && other != NULL) {
            fprintf(stderr, "curvefig: test: the figure '%s' is defined by "
                    "%s and by %s; the reference images are named after "
                    "the figures, so the names must differ\n", name, other,
                    script);
            goto out;
        }
        base = cf__tool_join(dir, name);
        if (base == NULL)
            goto oom;
        cf_diag_clear(&diag);
        st = cf_figure_write_all(cf_script_figure(s, i), base,
                                 CF_FORMAT_BIT(CF_FORMAT_SVG) |
                                     CF_FORMAT_BIT(CF_FORMAT_PNG),
                                 &wo, &diag);
        free(base);
        if (st != CF_STATUS_OK) {
            fprintf(stderr, "curvefig: %sfigure '%s': %s\n",
                    cf_script_figure_where(s, i), name,
                    diag.msg[0] ? diag.msg : cf_status_to_string(st));
            goto out;
        }
        if (labels) {
            char *copy = strdup(name);
            if (copy == NULL ||
                grow((void **)&t->figs, &t->capfigs, t->nfigs,
                     sizeof *t->figs) != 0) {
                free(copy);
                goto oom;
            }
            t->figs[t->nfigs].name = copy;
            t->figs[t->nfigs].steps = cf_figure_steps(cf_script_figure(s,
                                                                     i));
            t->figs[t->nfigs++].script = script;
        }
    }
    n = (int)cf_script_figure_count(s);
out:
    cf_script_destroy(s);
    return n;
oom:
    fprintf(stderr, "curvefig: test: %s: out of memory\n", script);
    goto out;
}

/* ---- comparing ---------------------------------------------------------- */

/* printf into a fresh string (NULL when out of memory) */
static char *
dupf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

static char *
dupf(const char *fmt, ...)
{
    va_list ap;
    int n;
    char *s;
    va_start(ap, fmt);
    n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0 || (s = malloc((size_t)n + 1)) == NULL)
        return NULL;
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}

/* Write image as OUT/failures/NAME.SLUG.ROLE.png; the path relative to OUT,
** or NULL. */
static char *
keep_image(test_run *t, const char *name, const char *slug, const char *role,
           cf__image *image)
{
    char *rel, *full;
    if (image == NULL)
        return NULL;
    rel = dupf("failures/%s.%s.%s.png", name, slug, role);
    full = rel != NULL ? cf__tool_join(t->outdir, rel) : NULL;
    if (full == NULL || cf__tool_image_write_png(image, full) != 0) {
        fprintf(stderr, "curvefig: test: cannot write %s: %s\n",
                full != NULL ? full : rel, strerror(errno));
        t->errors++;
        free(rel);
        rel = NULL;
    }
    free(full);
    return rel;
}

static void
record_failure(test_run *t, const char *script, const char *name,
               const char *slug, const char *what, const char *verdict,
               cf__image *expected, cf__image *actual,
               cf__image *diff)
{
    cf__tool_failure *f;
    printf("FAIL %s (%s): %s: %s\n", name, script, what, verdict);
    if (grow((void **)&t->fails, &t->capfails, t->nfails,
             sizeof *t->fails) != 0) {
        t->errors++;
        return;
    }
    f = &t->fails[t->nfails++];
    f->figure = strdup(name);
    f->script = strdup(script);
    f->what = strdup(what);
    f->verdict = strdup(verdict);
    f->expected = keep_image(t, name, slug, "expected", expected);
    f->actual = keep_image(t, name, slug, "actual", actual);
    f->diff = keep_image(t, name, slug, "diff", diff);
    if (f->figure == NULL || f->script == NULL || f->what == NULL ||
        f->verdict == NULL)
        t->errors++;
}

/* The comparator's options for one layer: strict without labels, the
** text allowance with them. */
static cf__imgcmp_options
layer_options(const test_run *t, bool labels, cf__image *image)
{
    cf__imgcmp_options opt;
    cf__tool_default_imgcmp(&opt);
    opt.threshold = t->threshold;
    if (labels)
        opt.max_bad_pixels = (long)(CF__IMGCMP_TEXT_FRACTION *
                                    image->width * image->height);
    return opt;
}

/* Compare actual with expected; a failure is recorded.  true on match. */
static bool
check_pair(test_run *t, const char *script, const char *name,
           const char *slug, const char *what, bool labels,
           cf__image *actual, cf__image *expected)
{
    cf__imgcmp_options opt = layer_options(t, labels, expected);
    cf__imgcmp_result res;
    cf__image *diff = NULL;
    char verdict[512];
    long pixels = (long)expected->width * expected->height;
    if (cf__tool_image_compare(actual, expected, &opt, &res, &diff) != 0) {
        snprintf(verdict, sizeof verdict, "the sizes differ: %dx%d pixels, "
                 "expected %dx%d", actual->width, actual->height,
                 expected->width, expected->height);
        record_failure(t, script, name, slug, what, verdict, expected,
                       actual, NULL);
        return false;
    }
    if (!res.match) {
        cf__tool_image_verdict(verdict, sizeof verdict, &res, &opt, pixels);
        record_failure(t, script, name, slug, what, verdict, expected,
                       actual, diff);
    }
    if (diff != NULL)
        cf__image_destroy(diff);
    return res.match;
}

/* The comparisons of one layer of one picture: the figure name, or its
** step (files and references NAME-STEP.*; step 0: the figure's own);
** returns its update state (unchanged when not updating, failed when an
** error stopped it). */
static int
check_layer(test_run *t, const char *script, const char *fig_name,
            unsigned step, bool labels, char *verdict, size_t vsize)
{
    char name[300], note[40] = "";
    const char *dir = labels ? t->outdir : t->out_nolabels;
    char *png_path, *svg_path, *ref_path;
    cf__image *png = NULL, *svg = NULL, *ref = NULL;
    char err[1024], what[1200];
    int state = t->update ? CF__TOOL_REF_FAILED : CF__TOOL_REF_UNCHANGED;
    const char *layer = labels ? "" : ", without labels";
    verdict[0] = '\0';
    if (step > 0)
        snprintf(note, sizeof note, "step %u: ", step);
    if (step > 0)
        snprintf(name, sizeof name, "%s-%u", fig_name, step);
    else
        snprintf(name, sizeof name, "%s", fig_name);
    png_path = dupf("%s/%s.png", dir, name);
    svg_path = dupf("%s/%s.svg", dir, name);
    ref_path = dupf("%s/%s.png", labels ? t->refdir : t->ref_nolabels, name);
    if (png_path == NULL || svg_path == NULL || ref_path == NULL) {
        fprintf(stderr, "curvefig: test: out of memory\n");
        t->errors++;
        goto out;
    }
    png = cf__tool_image_read(png_path, t->dpi, err, sizeof err);
    if (png == NULL) {
        fprintf(stderr, "curvefig: test: %s\n", err);
        t->errors++;
        goto out;
    }
    snprintf(what, sizeof what, "%sits SVG (rasterised by librsvg) "
             "against its PNG (cairo)%s", note, layer);
    svg = cf__tool_image_read(svg_path, t->dpi, err, sizeof err);
    if (svg == NULL)
        record_failure(t, script, name, labels ? "svg" : "svg-nolabels",
                       what, err, png, NULL, NULL);
    else
        check_pair(t, script, name, labels ? "svg" : "svg-nolabels", what,
                   labels, svg, png);
    if (t->update) {
        cf__imgcmp_options opt = layer_options(t, labels, png);
        state = cf__tool_ref_update(png_path, png, ref_path, &opt, t->dpi,
                                    verdict, vsize);
        if (state == CF__TOOL_REF_FAILED)
            t->errors++;
        goto out;
    }
    snprintf(what, sizeof what, "%sits PNG against the reference %s%s",
             note, ref_path, layer);
    ref = cf__tool_image_read(ref_path, t->dpi, err, sizeof err);
    if (ref == NULL) {
        struct stat sb;
        if (stat(ref_path, &sb) != 0)
            snprintf(err, sizeof err, "no reference image %s (write it with "
                     "--update)", ref_path);
        else
            t->errors++;    /* a reference that cannot be read */
        record_failure(t, script, name,
                       labels ? "reference" : "reference-nolabels", what,
                       err, NULL, png, NULL);
    } else {
        check_pair(t, script, name,
                   labels ? "reference" : "reference-nolabels", what, labels,
                   png, ref);
    }
out:
    if (png != NULL)
        cf__image_destroy(png);
    if (svg != NULL)
        cf__image_destroy(svg);
    if (ref != NULL)
        cf__image_destroy(ref);
    free(png_path);
    free(svg_path);
    free(ref_path);
    return state;
}

/* The update state of two: a failure, then a new or changed one. */
static int
worse(int a, int b)
{
    static const int rank[] = { [CF__TOOL_REF_UNCHANGED] = 0,
                                [CF__TOOL_REF_CHANGED] = 1,
                                [CF__TOOL_REF_ADDED] = 2,
                                [CF__TOOL_REF_FAILED] = 3 };
    return rank[b] > rank[a] ? b : a;
}

/* Check figure f: its files, then each of its overlay steps (NAME-K). */
static void
check_figure(test_run *t, const produced *f)
{
    size_t before = t->nfails;
    char v_labels[512], v_plain[512], v_step[512];
    int a = check_layer(t, f->script, f->name, 0, true, v_labels,
                        sizeof v_labels);
    int b = check_layer(t, f->script, f->name, 0, false, v_plain,
                        sizeof v_plain);
    int steps_state = CF__TOOL_REF_UNCHANGED;
    char steps_note[512] = "";
    for (unsigned k = 1; f->steps > 1 && k <= f->steps; k++) {
        int sa = check_layer(t, f->script, f->name, k, true, v_step,
                             sizeof v_step);
        int sb = check_layer(t, f->script, f->name, k, false, v_step,
                             sizeof v_step);
        int st = worse(sa, sb);
        if (st == CF__TOOL_REF_CHANGED || st == CF__TOOL_REF_ADDED) {
            size_t n = strlen(steps_note);
            snprintf(steps_note + n, sizeof steps_note - n, "%s%u%s",
                     n > 0 ? ", " : "", k,
                     st == CF__TOOL_REF_ADDED ? " (new)" : "");
        }
        steps_state = worse(steps_state, st);
    }
    if (t->nfails > before)
        t->failed_figures++;
    if (!t->update) {
        if (t->nfails == before)
            printf(f->steps > 1 ? "ok   %s (%u steps)\n" : "ok   %s\n",
                   f->name, f->steps);
        return;
    }
    if (a == CF__TOOL_REF_FAILED || b == CF__TOOL_REF_FAILED
        || steps_state == CF__TOOL_REF_FAILED)
        return;
    if (a == CF__TOOL_REF_ADDED) {
        t->added++;
        printf("new:       %s\n", f->name);
    } else if (a == CF__TOOL_REF_CHANGED || b != CF__TOOL_REF_UNCHANGED
               || steps_state != CF__TOOL_REF_UNCHANGED) {
        t->changed++;
        printf("changed:   %s\n", f->name);
        if (a == CF__TOOL_REF_CHANGED)
            printf("           with labels: %s\n", v_labels);
        if (b != CF__TOOL_REF_UNCHANGED)
            printf("           without labels: %s\n",
                   b == CF__TOOL_REF_ADDED ? "new" : v_plain);
        if (steps_note[0] != '\0')
            printf("           steps: %s\n", steps_note);
    } else {
        t->unchanged++;
        printf("unchanged: %s\n", f->name);
    }
}

/* ---- the whole run ------------------------------------------------------ */

/* One reference no figure of the run produced: with --update removed,
** else a failure.  A name stale in both layers counts once. */
static void
stale_reference(test_run *t, const char *dir, const char *name, bool plain)
{
    char *path = dupf("%s/%s.png", dir, name);
    char *twin = plain ? dupf("%s/%s.png", t->refdir, name) : NULL;
    struct stat sb;
    if (path == NULL || (plain && twin == NULL)) {
        t->errors++;
    } else if (t->update) {
        if (remove(path) != 0) {
            fprintf(stderr, "curvefig: test: cannot remove %s: %s\n", path,
                    strerror(errno));
            t->errors++;
        } else if (!plain) {
            t->removed++;
            printf("removed:   %s (%s)\n", name, path);
        }
    } else if (!plain || stat(twin, &sb) != 0) {
        char verdict[1024];
        snprintf(verdict, sizeof verdict, "the reference %s has no figure "
                 "any more: the figure was removed or renamed (--update "
                 "removes the reference)", path);
        record_failure(t, "-", name, "removed", "a reference without its "
                       "figure", verdict, NULL, NULL, NULL);
        t->stale++;
    }
    free(path);
    free(twin);
}

static void
stale_references(test_run *t)
{
    for (int layer = 0; layer < 2; layer++) {
        const char *dir = layer == 0 ? t->refdir : t->ref_nolabels;
        size_t n;
        char **names = cf__tool_list_dir(dir, ".png", &n);
        for (size_t i = 0; i < n; i++)
            if (!has_figure(t, names[i]))
                stale_reference(t, dir, names[i], layer == 1);
        if (names != NULL)
            cf__tool_free_list(names, n);
    }
}

/* Remove the images of an earlier run's failures. */
static void
clear_failures(const char *dir)
{
    size_t n;
    char **names = cf__tool_list_dir(dir, ".png", &n);
    for (size_t i = 0; i < n; i++) {
        char *p = dupf("%s/%s.png", dir, names[i]);
        if (p != NULL)
            remove(p);
        free(p);
    }
    if (names != NULL)
        cf__tool_free_list(names, n);
}

static int
prepare_dirs(test_run *t)
{
    struct stat sb;
    t->out_nolabels = cf__tool_join(t->outdir, "nolabels");
    t->out_failures = cf__tool_join(t->outdir, "failures");
    t->ref_nolabels = cf__tool_join(t->refdir, "nolabels");
    if (t->out_nolabels == NULL || t->out_failures == NULL ||
        t->ref_nolabels == NULL) {
        fprintf(stderr, "curvefig: test: out of memory\n");
        return -1;
    }
    if (!t->update && (stat(t->refdir, &sb) != 0 || !S_ISDIR(sb.st_mode))) {
        bool missing = stat(t->refdir, &sb) != 0;
        fprintf(stderr, "curvefig: test: the reference directory %s %s; "
                "write the references first with --update\n", t->refdir,
                missing ? "does not exist" : "is not a directory");
        return -1;
    }
    if (t->update && (cf__tool_mkdir_p(t->refdir) != 0 ||
                      cf__tool_mkdir_p(t->ref_nolabels) != 0)) {
        fprintf(stderr, "curvefig: test: cannot create the reference "
                "directory %s: %s\n", t->ref_nolabels, strerror(errno));
        return -1;
    }
    if (cf__tool_mkdir_p(t->out_nolabels) != 0 ||
        cf__tool_mkdir_p(t->out_failures) != 0) {
        fprintf(stderr, "curvefig: test: cannot create the output "
                "directory %s: %s\n", t->out_failures, strerror(errno));
        return -1;
    }
    clear_failures(t->out_failures);
    return 0;
}

static void
run_scripts(test_run *t)
{
    for (size_t k = 0; k < t->scripts.count; k++) {
        const char *script = t->scripts.path[k];
        size_t first = t->nfigs;
        int n = render_layer(t, script, true, t->outdir);
        int m = n < 0 ? n : render_layer(t, script, false, t->out_nolabels);
        if (n < 0 || m < 0) {
            fprintf(stderr, "curvefig: test: %s failed; its figures are "
                    "not checked%s\n", script,
                    t->update ? " and their references not written" : "");
            t->errors++;
            continue;
        }
        if (m != n) {
            fprintf(stderr, "curvefig: test: %s defines %d figures with "
                    "labels but %d without\n", script, n, m);
            t->errors++;
            continue;
        }
        if (n == 0)
            printf("note: %s defines no figure\n", script);
        for (size_t i = first; i < t->nfigs; i++)
            check_figure(t, &t->figs[i]);
    }
}

static int
finish(test_run *t)
{
    char summary[512], stale[64] = "";
    char *report = cf__tool_join(t->outdir, "report.html");
    if (t->stale > 0)
        snprintf(stale, sizeof stale, "; %zu reference(s) without a figure",
                 t->stale);
    if (t->update)
        snprintf(summary, sizeof summary, "references in %s: %zu new, %zu "
                 "changed, %zu unchanged, %zu removed; %zu figure(s) of %zu "
                 "script(s), %zu failing", t->refdir, t->added, t->changed,
                 t->unchanged, t->removed, t->nfigs, t->scripts.count,
                 t->failed_figures);
    else
        snprintf(summary, sizeof summary, "%zu figure(s) of %zu script(s): "
                 "%zu pass, %zu fail%s%s", t->nfigs, t->scripts.count,
                 t->nfigs - t->failed_figures, t->failed_figures, stale,
                 t->errors ? "; errors (see the messages above)" : "");
    printf("curvefig test: %s\n", summary);
    if (report == NULL ||
        cf__tool_report_write(report, summary, t->fails, t->nfails) != 0) {
        fprintf(stderr, "curvefig: test: cannot write the report %s: %s\n",
                report != NULL ? report : t->outdir, strerror(errno));
        t->errors++;
    } else if (t->nfails > 0) {
        printf("report: %s\n", report);
    }
    free(report);
    return t->errors ? ERROR : t->nfails ? FAILED : PASSED;
}

static void
release(test_run *t)
{
    for (size_t i = 0; i < t->nfigs; i++)
        free(t->figs[i].name);
    for (size_t i = 0; i < t->nfails; i++)
        cf__tool_failure_free(&t->fails[i]);
    cf__tool_scripts_free(&t->scripts);
    free(t->figs);
    free(t->fails);
    free(t->out_nolabels);
    free(t->out_failures);
    free(t->ref_nolabels);
}

int
cf__tool_test(int argc, char **argv)
{
    test_run t;
    int rc;
    memset(&t, 0, sizeof t);
    rc = parse(argc, argv, &t);
    if (rc == 0 && prepare_dirs(&t) != 0)
        rc = ERROR;
    if (rc == 0) {
        cf__tool_fonts_init();
        run_scripts(&t);
        if (t.scripts.only_dirs && t.errors == 0)
            stale_references(&t);
        rc = finish(&t);
    }
    release(&t);
    return rc < 0 ? 0 : rc;
}

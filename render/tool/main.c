/*
** curvefig: the command-line tool.
**
**   curvefig render SCRIPT.lua [-o DIR] [-f svg,pdf,png,ps,eps] [--dpi N]
**                              [--only NAME[,NAME...]] [--tight] [--steps]
**   curvefig run SCRIPT.lua
**   curvefig list SCRIPT.lua
**   curvefig check SCRIPT.lua [--json] [--min-de N] (colours.c)
**   curvefig live SCRIPT.lua [--port N] (live.h)
**   curvefig gallery -o INDEX.html MANIFEST...
**   curvefig compare A B ...; curvefig test SCRIPT... --references DIR ...
**   (checks.h)
**
** Exit status: 0 success, 1 the script (or a figure, or writing a file)
** failed, 2 usage error (bad command line, unreadable script).
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "animate.h"
#include "formats-arg.h"
#include "curvefig/access.h"
#include "curvefig/figure.h"
#include "help.h"
#include "helpers.h"
#include "html.h"
#include "interactive.h"
#include "font-config.h"
#include "runlimits.h"
#include "script.h"
#include "tool.h"

#define EXIT_SCRIPT 1
#define EXIT_USAGE 2

typedef struct options {
    const char *command;
    const char *script;
    const char *outdir;
    const char *only;
    const char *manifest;
    const char *gallery_title;
    unsigned formats;
    double dpi;
    bool tight;
    const char *font;         /* --font, --theme: NULL the scripts' */
    double font_size;         /* bp; 0 the scripts' */
    double width, height;     /* --width, --height: bp; 0 the scripts' */
    long long seed;           /* --seed: math.random's */
    const char *background;   /* --background: NULL the scripts' */
    bool steps;
    bool no_labels;
    bool verbose;
    bool long_list;
    bool json;                /* check: JSON on stdout */
    double min_de;            /* check: the least CIEDE2000 distance */
    cf__tool_limits limits;
    cf__tool_anim_t anim;     /* --sweep and the other options of an
                                 animation (animate.h) */
    bool formats_given;
    const char *prefix;       /* --prefix: before every figure's name */
    int nfiles;
    char **files;
} options;

static int
usage_error(const char *fmt, const char *arg)
{
    fprintf(stderr, "curvefig: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\nTry 'curvefig --help'.\n");
    return EXIT_USAGE;
}

/* The options of render, run and list, for the nearest one. */
static const char *const known_options[] = {
    "--output", "--formats", "--dpi", "--only", "--manifest", "--title",
    "--max-memory", "--max-instructions", "--timeout", "--font",
    "--font-size", "--theme", "--background", "--width", "--height",
    "--seed", "--help", "--verbose", "--long", "--tight", "--steps",
    "--no-labels", "--sweep", "--frames", "--fps", "--seconds", "--ease",
    "--bounce", "--step-seconds", "--animate", "--workers", "--prefix",
    "--json", "--min-de",
};

/* A font size: a number in TeX points, or a number and a unit (texpt,
** bp, mm, cm, in); bp in *out. */
static int
parse_size(const char *s, double *out)
{
    char *end;
    double v = strtod(s, &end);
    cf_unit_t u = CF_UNIT_TEXPT;
    if (end == s || !isfinite(v))
        return -1;
    if (*end != '\0' && cf_unit_from_name(end, &u, NULL) != CF_STATUS_OK)
        return -1;
    *out = cf_length_to_bp(v, u);
    return *out > 0 && *out <= 1000 ? 0 : -1;
}

/* A page length: a number and a unit (cm, mm, in, bp, pt, texpt); bp in
** *out. */
static int
parse_length(const char *s, double *out)
{
    char *end;
    double v = strtod(s, &end);
    cf_unit_t u;
    if (end == s || !isfinite(v) || *end == '\0'
        || cf_unit_from_name(end, &u, NULL) != CF_STATUS_OK)
        return -1;
    *out = cf_length_to_bp(v, u);
    return *out > 0 && *out <= 14400 ? 0 : -1;
}

static bool
takes_value(const char *opt)
{
    static const char *const with_value[] = {
        "-o", "--output", "-f", "--formats", "--dpi", "--only", "--manifest",
        "--title", "--max-memory", "--max-instructions", "--timeout",
        "--font", "--font-size", "--theme", "--background", "--width",
        "--height", "--seed", "--prefix", "--min-de", NULL,
    };
    for (int i = 0; with_value[i] != NULL; i++)
        if (strcmp(opt, with_value[i]) == 0)
            return true;
    return cf__tool_anim_takes_value(opt);
}

/* Parse argv into o; returns -1 when the tool should exit with *rc. */
static int
parse_args(int argc, char **argv, options *o, int *rc)
{
    int i = 2;
    memset(o, 0, sizeof *o);
    o->outdir = ".";
    o->formats = CF_FORMAT_BIT(CF_FORMAT_SVG) | CF_FORMAT_BIT(CF_FORMAT_PDF) |
                 CF_FORMAT_BIT(CF_FORMAT_PNG);
    o->dpi = 150;
    o->min_de = CF__TOOL_MIN_DE;
    o->seed = CF_SCRIPT_DEFAULT_SEED;
    o->limits.timeout = CF__TOOL_TIMEOUT;
    if (argc < 2) {
        *rc = usage_error("%sno command given", "");
        return -1;
    }
    o->command = argv[1];
    if (strcmp(o->command, "--help") == 0 || strcmp(o->command, "-h") == 0 ||
        strcmp(o->command, "help") == 0) {
        *rc = cf__tool_help(argc > 2 ? argv[2] : NULL);
        return -1;
    }
    if (strcmp(o->command, "--version") == 0 ||
        strcmp(o->command, "version") == 0) {
        printf("curvefig %s\nfonts: %s\n", CF_TOOL_VERSION,
               cf__tool_fonts_init());
        *rc = 0;
        return -1;
    }
    if (strcmp(o->command, "render") != 0 && strcmp(o->command, "run") != 0 &&
        strcmp(o->command, "list") != 0 &&
        strcmp(o->command, "check") != 0 &&
        strcmp(o->command, "gallery") != 0) {
        *rc = usage_error("unknown command '%s'", o->command);
        return -1;
    }
    /* operands, gathered from between the options (argc slots suffice) */
    o->files = calloc((size_t)argc, sizeof *o->files);
    if (o->files == NULL) {
        *rc = EXIT_SCRIPT;
        return -1;
    }
    for (; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        bool takes = true;
        char limmsg[200];
        int lim;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            *rc = cf__tool_help(o->command);
            return -1;
        } else if (strcmp(a, "-v") == 0 || strcmp(a, "--verbose") == 0) {
            o->verbose = true;
            takes = false;
        } else if (strcmp(a, "-l") == 0 || strcmp(a, "--long") == 0) {
            o->long_list = true;
            takes = false;
        } else if (strcmp(a, "--tight") == 0) {
            o->tight = true;
            takes = false;
        } else if (strcmp(a, "--steps") == 0) {
            o->steps = true;
            takes = false;
        } else if (strcmp(a, "--no-labels") == 0) {
            o->no_labels = true;
            takes = false;
        } else if (strcmp(a, "--json") == 0) {
            o->json = true;
            takes = false;
        } else if (takes_value(a) && v == NULL) {
            *rc = usage_error("option '%s' needs a value", a);
            return -1;
        } else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            o->outdir = v;
        } else if (strcmp(a, "--prefix") == 0) {
            if (strchr(v, '/') != NULL) {
                *rc = usage_error("--prefix '%s': a prefix of file names "
                                  "has no '/'", v);
                return -1;
            }
            o->prefix = v;
        } else if ((lim = cf__tool_anim_option(a, v, &o->anim, limmsg,
                                               sizeof limmsg)) != 0) {
            if (lim < 0) {
                *rc = usage_error("%s", limmsg);
                return -1;
            }
            takes = cf__tool_anim_takes_value(a);
        } else if (strcmp(a, "-f") == 0 || strcmp(a, "--formats") == 0) {
            o->formats_given = true;
            if (cf__tool_parse_formats(v, &o->formats) != 0) {
                const char *near = cf__tool_nearest_format(v);
                char msg[512];
                snprintf(msg, sizeof msg, "bad format list '%s' (%s%s%suse "
                         "svg, pdf, png, ps, eps, pgf, html or all, and for "
                         "animations gif, apng, mp4, webm, separated by "
                         "commas)", v,
                         near != NULL ? "did you mean " : "",
                         near != NULL ? near : "", near != NULL ? "? " : "");
                *rc = usage_error("%s", msg);
                return -1;
            }
        } else if (strcmp(a, "--min-de") == 0) {
            if (cf__tool_number(v, 0.001, 100, &o->min_de) != 0) {
                *rc = usage_error("--min-de '%s': give a CIEDE2000 distance "
                                  "from 0.001 to 100", v);
                return -1;
            }
        } else if (strcmp(a, "--dpi") == 0) {
            if (cf__tool_number(v, 1, 2400, &o->dpi) != 0) {
                *rc = usage_error("--dpi '%s': give a number from 1 to 2400",
                                  v);
                return -1;
            }
        } else if (strcmp(a, "--font") == 0) {
            o->font = v;
        } else if (strcmp(a, "--font-size") == 0) {
            if (parse_size(v, &o->font_size) != 0) {
                *rc = usage_error("--font-size '%s': give a size in TeX "
                                  "points (11) or with a unit (11texpt, 11bp, 4mm)",
                                  v);
                return -1;
            }
        } else if (strcmp(a, "--width") == 0 || strcmp(a, "--height") == 0) {
            if (parse_length(v, a[2] == 'w' ? &o->width : &o->height) != 0) {
                fprintf(stderr, "curvefig: %s '%s': give a length and a "
                        "unit up to 200in, e.g. 12cm (cm, mm, in; bp or pt: "
                        "the PostScript point, 1/72 in; texpt: TeX's point, "
                        "1/72.27 in)\nTry 'curvefig --help'.\n", a, v);
                *rc = EXIT_USAGE;
                return -1;
            }
        } else if (strcmp(a, "--seed") == 0) {
            char *end;
            errno = 0;
            o->seed = strtoll(v, &end, 10);
            if (errno != 0 || end == v || *end != '\0') {
                *rc = usage_error("--seed '%s': give a whole number", v);
                return -1;
            }
        } else if (strcmp(a, "--theme") == 0) {
            if (strcmp(v, "article") == 0) {
                o->font = "serif";
                o->font_size = 10 * 72.0 / 72.27;
            } else if (strcmp(v, "beamer") == 0) {
                o->font = "sans";
                o->font_size = 11 * 72.0 / 72.27;
            } else {
                *rc = usage_error("--theme '%s': use article (serif, 10 pt) "
                                  "or beamer (sans, 11 pt)", v);
                return -1;
            }
        } else if (strcmp(a, "--background") == 0) {
            cf_color_t c;
            if (strcmp(v, "auto") != 0 && strcmp(v, "none") != 0
                && cf_color_parse(v, &c, NULL) != CF_STATUS_OK) {
                *rc = usage_error("--background '%s': use auto, none or a "
                                  "colour (white, #fdf6e3)", v);
                return -1;
            }
            o->background = v;
        } else if (strcmp(a, "--only") == 0) {
            /* an empty list would render nothing and succeed */
            if (v[0] == '\0') {
                *rc = usage_error("--only '%s': give the names of the "
                                  "figures to render, NAME[,NAME]", v);
                return -1;
            }
            o->only = v;
        } else if (strcmp(a, "--manifest") == 0) {
            o->manifest = v;
        } else if (strcmp(a, "--title") == 0) {
            o->gallery_title = v;
        } else if ((lim = cf__tool_limit_option(a, v, &o->limits, limmsg,
                                                sizeof limmsg)) != 0) {
            if (lim < 0) {
                *rc = usage_error("%s", limmsg);
                return -1;
            }
        } else if (strcmp(a, "--") == 0) {
            for (i++; i < argc; i++)
                o->files[o->nfiles++] = argv[i];
            break;
        } else if (a[0] == '-' && a[1] != '\0') {
            const char *near = cf_nearest_name(a, known_options,
                                               sizeof known_options
                                                   / sizeof known_options[0]);
            char msg[512];
            snprintf(msg, sizeof msg, "unknown option '%s'%s%s%s", a,
                     near != NULL ? " (did you mean " : "",
                     near != NULL ? near : "",
                     near == NULL ? ""
                     : strcmp(near, "--output") == 0 ? ", -o?)"
                     : strcmp(near, "--formats") == 0 ? ", -f?)" : "?)");
            *rc = usage_error("%s", msg);
            return -1;
        } else {
            o->files[o->nfiles] = argv[i];
            o->nfiles++;
            takes = false;
        }
        if (takes)
            i++;
    }
    if (strcmp(o->command, "gallery") == 0) {
        if (o->nfiles < 1) {
            *rc = usage_error("%sgallery needs at least one manifest", "");
            return -1;
        }
        return 0;
    }
    if (o->nfiles != 1) {
        *rc = usage_error(o->nfiles == 0 ? "%s: no script given"
                                         : "%s: give exactly one script",
                          o->command);
        return -1;
    }
    o->script = o->files[0];
    if (strcmp(o->command, "render") == 0
        && cf__tool_anim_wanted(&o->anim, o->formats)) {
        char msg[300];
        if (!o->formats_given)
            o->formats = CF_FORMAT_BIT(CF_FORMAT_SVG)
                         | CF_FORMAT_BIT(CF_FORMAT_PDF) | CF__TOOL_GIF_BIT;
        if (cf__tool_anim_check_formats(o->formats, msg, sizeof msg) != 0) {
            *rc = usage_error("%s", msg);
            return -1;
        }
    } else if ((o->formats & CF__TOOL_ANIM_BITS) != 0) {
        *rc = usage_error("%s: -f gif, apng, mp4 and webm are made by "
                          "render", o->command);
        return -1;
    } else if (strcmp(o->command, "render") != 0
               && cf__tool_anim_wanted(&o->anim, 0)) {
        *rc = usage_error("%s: --sweep, --animate and the other options of "
                          "an animation are render's (curvefig render "
                          "SCRIPT --sweep ...)", o->command);
        return -1;
    }
    return 0;
}

/* ---- render, run, list -------------------------------------------------- */

static bool
selected(const char *only, const char *name)
{
    size_t n = strlen(name);
    const char *p = only;
    if (only == NULL)
        return true;
    while (*p != '\0') {
        const char *e = strchr(p, ',');
        size_t len = e != NULL ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0)
            return true;
        if (e == NULL)
            break;
        p = e + 1;
    }
    return false;
}

/* Every name of --only must be a figure of the script. */
static int
check_only(const cf_script_t *s, const options *o)
{
    const char *p = o->only;
    while (p != NULL && *p != '\0') {
        const char *e = strchr(p, ',');
        size_t len = e != NULL ? (size_t)(e - p) : strlen(p);
        bool found = false;
        for (size_t i = 0; i < cf_script_figure_count(s) && !found; i++) {
            const char *name = cf_script_figure_name(s, i);
            found = strlen(name) == len && strncmp(name, p, len) == 0;
        }
        if (!found) {
            fprintf(stderr, "curvefig: --only: %s defines no figure named "
                    "'%.*s'; it defines:", o->script, (int)len, p);
            for (size_t i = 0; i < cf_script_figure_count(s); i++)
                fprintf(stderr, " %s", cf_script_figure_name(s, i));
            fprintf(stderr, "\n");
            return -1;
        }
        p = e != NULL ? e + 1 : NULL;
    }
    return 0;
}

/* The files cf_figure_write_all wrote for base. */
static void
print_written(const char *base, unsigned formats, unsigned steps,
              bool step_files)
{
    for (int f = 0; f < CF_FORMAT_LAST_; f++) {
        if (!(formats & CF_FORMAT_BIT(f)))
            continue;
        printf("%s.%s\n", base, cf_format_extension((cf_format_t)f));
        for (unsigned k = 1; steps > 1 && k <= steps
                             && (f == CF_FORMAT_PNG || step_files); k++)
            printf("%s-%u.%s\n", base, k,
                   cf_format_extension((cf_format_t)f));
    }
}

/* The figure's warnings (labels on ink) on stderr, each naming the
** figure; they do not fail the render. */
static void
warn_labels(const cf_script_t *s, size_t i, const char *script)
{
    const char *w = cf_figure_warnings(cf_script_figure(s, i));
    const char *where = cf_script_figure_where(s, i);
    while (*w != '\0') {
        const char *nl = strchr(w, '\n');
        int n = nl != NULL ? (int)(nl - w) : (int)strlen(w);
        if (where[0] != '\0')
            fprintf(stderr, "curvefig: %sfigure '%s': warning: %.*s\n",
                    where, cf_script_figure_name(s, i), n, w);
        else
            fprintf(stderr, "curvefig: %s: figure '%s': warning: %.*s\n",
                    script, cf_script_figure_name(s, i), n, w);
        w += n + (nl != NULL);
    }
}

/* --background over the script's: auto, none or a colour (checked) */
static void
set_background(cf_figure_t *fig, const char *v)
{
    cf_theme_t th;
    if (v == NULL)
        return;
    if (strcmp(v, "auto") == 0 || strcmp(v, "none") == 0) {
        cf_figure_set_background(fig, v[0] == 'a' ? CF_BACKGROUND_AUTO
                                                   : CF_BACKGROUND_NONE);
        return;
    }
    cf_figure_get_theme(fig, &th);
    cf_color_parse(v, &th.background, NULL);
    cf_figure_set_theme(fig, &th);
    cf_figure_set_background(fig, CF_BACKGROUND_ALWAYS);
}

/* PREFIXNAME, or OUTDIR/PREFIXNAME with dir (malloc'd; NULL out of
** memory). */
static char *
prefixed_in(const options *o, const char *name, bool dir)
{
    const char *p = o->prefix != NULL ? o->prefix : "";
    char *both = malloc(strlen(p) + strlen(name) + 1), *path;
    if (both == NULL || !dir)
        return both != NULL ? strcat(strcpy(both, p), name) : NULL;
    sprintf(both, "%s%s", p, name);
    path = cf__tool_join(o->outdir, both);
    free(both);
    return path;
}

static char *
prefixed(const options *o, const char *name)
{
    return prefixed_in(o, name, true);
}

static cf__tool_run_t
run_settings(const options *o)
{
    cf__tool_run_t r;
    memset(&r, 0, sizeof r);
    r.script = o->script;
    r.limits = &o->limits;
    r.labels = !o->no_labels;
    r.font = o->font;
    r.font_size = o->font_size;
    r.width = o->width;
    r.height = o->height;
    r.seed = o->seed;
    r.background = o->background;
    r.prepare = set_background;
    return r;
}

static int
render_figures(const cf_script_t *s, const options *o)
{
    cf_write_options_t wo;
    cf__tool_out man;
    int rc = 0;
    cf_write_options_init(&wo);
    wo.dpi = o->dpi;
    wo.tight = o->tight;
    wo.step_files = o->steps;
    if (cf__tool_mkdir_p(o->outdir) != 0) {
        fprintf(stderr, "curvefig: cannot create the directory %s: %s\n",
                o->outdir, strerror(errno));
        return EXIT_SCRIPT;
    }
    for (size_t i = 0; i < cf_script_figure_count(s); i++) {
        const char *name = cf_script_figure_name(s, i);
        cf_figure_t *fig = cf_script_figure(s, i);
        char *base;
        cf_diag_t diag;
        cf_status_t st;
        cf_script_scope_t scope;
        char over[200];
        if (!selected(o->only, name))
            continue;
        base = prefixed(o, name);
        if (base == NULL) {
            fprintf(stderr, "curvefig: out of memory\n");
            return EXIT_SCRIPT;
        }
        if (cf__tool_anim_wanted(&o->anim, o->formats)) {
            cf__tool_run_t run = run_settings(o);
            if (cf__tool_animate(s, i, &run, &o->anim, base, o->formats,
                                 o->dpi, o->tight, o->verbose) != 0)
                rc = EXIT_SCRIPT;
            free(base);
            continue;
        }
        cf_diag_clear(&diag);
        set_background(fig, o->background);
        st = CF_STATUS_OK;
        cf_script_budget_begin(s, &scope);
        if (o->formats & ~CF__TOOL_HTML_BIT)
            st = cf_figure_write_all(fig, base, o->formats & ~CF__TOOL_HTML_BIT,
                                     &wo, &diag);
        if (st == CF_STATUS_OK && (o->formats & CF__TOOL_HTML_BIT)) {
            char *html = malloc(strlen(base) + 6);
            if (html == NULL) {
                cf_script_budget_end(s, &scope, NULL, 0);
                free(base);
                fprintf(stderr, "curvefig: out of memory\n");
                return EXIT_SCRIPT;
            }
            sprintf(html, "%s.html", base);
            if (cf__tool_write_html(s, i, o->script, &o->limits, html,
                                    NULL, diag.msg, sizeof diag.msg) != 0)
                st = CF_STATUS_INVALID_ARG;
            else if (o->verbose)
                printf("%s\n", html);
            free(html);
        }
        if (cf_script_budget_end(s, &scope, over, sizeof over) &&
            st != CF_STATUS_OK) {
            char both[sizeof over + sizeof diag.msg + 2];
            size_t n;
            snprintf(both, sizeof both, "%s; %s", over,
                     diag.msg[0] ? diag.msg : cf_status_to_string(st));
            n = strlen(both) < sizeof diag.msg ? strlen(both)
                                               : sizeof diag.msg - 1;
            memcpy(diag.msg, both, n);
            diag.msg[n] = '\0';
        }
        if (st != CF_STATUS_OK) {
            const char *where = cf_script_figure_where(s, i);
            if (where[0] != '\0')
                fprintf(stderr, "curvefig: %sfigure '%s': %s\n", where,
                        name,
                        diag.msg[0] ? diag.msg : cf_status_to_string(st));
            else
                fprintf(stderr, "curvefig: %s: figure '%s': %s\n",
                        o->script, name,
                        diag.msg[0] ? diag.msg : cf_status_to_string(st));
            rc = EXIT_SCRIPT;
        } else {
            warn_labels(s, i, o->script);
        }
        if (st == CF_STATUS_OK && o->verbose) {
            print_written(base, o->formats, cf_figure_steps(fig), o->steps);
        }
        free(base);
    }
    if (rc == 0 && o->manifest != NULL) {
        if (cf__tool_open_atomic(&man, o->manifest) != 0) {
            fprintf(stderr, "curvefig: cannot write %s: %s\n", o->manifest,
                    strerror(errno));
            return EXIT_SCRIPT;
        }
        for (size_t i = 0; i < cf_script_figure_count(s); i++) {
            char *alt = NULL, *desc = NULL;
            if (!selected(o->only, cf_script_figure_name(s, i)))
                continue;
            char *name = prefixed_in(o, cf_script_figure_name(s, i), false);
            if (name == NULL) {
                cf__tool_discard_atomic(&man);
                fprintf(stderr, "curvefig: out of memory\n");
                return EXIT_SCRIPT;
            }
            /* a figure that rendered has its text (out of memory: none) */
            cf_figure_alt_text(cf_script_figure(s, i), &alt);
            cf_figure_description(cf_script_figure(s, i), &desc);
            cf__tool_manifest_line(man.f, name,
                                   cf_script_figure_caption(s, i),
                                   o->formats, o->script, alt, desc);
            cf_free(alt);
            cf_free(desc);
            free(name);
        }
        if (cf__tool_close_atomic(&man) != 0) {
            fprintf(stderr, "curvefig: cannot write %s: %s\n", o->manifest,
                    strerror(errno));
            return EXIT_SCRIPT;
        }
    }
    return rc;
}

static void
fonts_init(void)
{
    (void)cf__tool_fonts_init();
}

static int
run_script(const options *o)
{
    cf_script_t *s = NULL;
    cf_diag_t diag;
    cf_status_t st;
    int rc = 0;
    struct stat sb;
    if (stat(o->script, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        fprintf(stderr, "curvefig: cannot read the script %s: %s\n",
                o->script, errno ? strerror(errno) : "not a regular file");
        return EXIT_USAGE;
    }
    cf__tool_watchdog(o->script, o->limits.timeout);
    /* the fonts are configured when the first label looks one up */
    cf__fonts_before_open(fonts_init);
    cf_diag_clear(&diag);
    /* list keeps stdout for the names: the script's prints go to stderr */
    st = cf_script_create(&o->limits.script,
                          strcmp(o->command, "list") == 0 ? stderr : stdout,
                          &s, &diag);
    if (st != CF_STATUS_OK) {
        fprintf(stderr, "curvefig: %s\n", diag.msg);
        return EXIT_SCRIPT;
    }
    cf_script_set_labels(s, !o->no_labels);
    cf_script_set_fonts(s, o->font, o->font_size);
    cf_script_set_page(s, o->width, o->height);
    cf_script_set_seed(s, o->seed);
    st = cf_script_run_file(s, o->script);
    fflush(stdout);
    if (st == CF_STATUS_IO) {
        fprintf(stderr, "curvefig: %s\n", cf_script_error(s));
        cf_script_destroy(s);
        return EXIT_USAGE;
    }
    if (st != CF_STATUS_OK) {
        fprintf(stderr, "curvefig: %s\n", cf_script_error(s));
        cf_script_destroy(s);
        return EXIT_SCRIPT;
    }
    {
        /* a points{} list dragged in a figure the script does not define:
        ** the error live gives, given here too */
        char err[400];
        int line = cf_interactive_check_figures(s, err, sizeof err);
        if (line >= 0) {
            fprintf(stderr, "curvefig: %s:%d: %s\n", o->script, line, err);
            cf_script_destroy(s);
            return EXIT_SCRIPT;
        }
    }
    if (strcmp(o->command, "list") == 0) {
        for (size_t i = 0; i < cf_script_figure_count(s); i++) {
            if (o->long_list)
                printf("%s\t%s\n", cf_script_figure_name(s, i),
                       cf_script_figure_caption(s, i));
            else
                printf("%s\n", cf_script_figure_name(s, i));
        }
    } else if (strcmp(o->command, "check") == 0) {
        rc = cf__tool_colours(s, o->script, o->min_de, o->json);
    } else if (strcmp(o->command, "render") == 0) {
        if (check_only(s, o) != 0)
            rc = EXIT_USAGE;
        else
            rc = render_figures(s, o);
    }
    cf_script_destroy(s);
    return rc;
}

int
main(int argc, char **argv)
{
    options o;
    int rc = 0;
    void *heap;
    if (argc > 1 && (strcmp(argv[1], "compare") == 0 ||
                     strcmp(argv[1], "test") == 0))
        return cf__tool_run_helper(CF__TOOL_CHECK_HELPER, argc, argv);
    if (argc > 1 && strcmp(argv[1], "live") == 0)
        return cf__tool_run_helper(CF__TOOL_LIVE_HELPER, argc, argv);
    heap = cf__tool_heap_for_one_run();
    /* the renderer chooses the tool's faces itself (faces.c) */
    cf__tool_fonts_own(cf__tool_own_faces);
    if (parse_args(argc, argv, &o, &rc) == 0) {
        if (strcmp(o.command, "gallery") == 0)
            rc = cf__tool_gallery(o.outdir, o.gallery_title,
                                  (const char *const *)o.files, o.nfiles);
        else
            rc = run_script(&o);
    }
    free(o.files);
    free(heap);
    return rc;
}

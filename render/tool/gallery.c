/*
** The HTML gallery (`curvefig gallery`): the figures of render manifests
** (NAME TAB FORMATS TAB CAPTION [TAB SCRIPT] a line), grouped by the
** seed their name starts with (the part before the first '-'), with an
** index of the groups and their figures at the top.  The figures of one
** script stand beside its source (read from SCRIPT, a path as the
** manifest gives it, relative to the current directory), and each
** figure links to it.  Captions are typeset like the labels: the
** TeX-like scripts of N_{i,1}^p become HTML subscripts and superscripts
** (stacked when both follow one base), so that the page needs no other
** files and its text can still be searched and copied.
*/
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "tool.h"

/* The largest manifest or script the gallery reads (a manifest line a
** figure: 64 MiB is some hundred thousand figures). */
#define GALLERY_MAX_FILE ((size_t)64 << 20)

typedef struct entry {
    char *name, *formats, *caption, *script;   /* script "" if none */
    char *alt, *desc;                          /* "" if none */
} entry_t;

/* What the name prefixes stand for: the seeds of the shipped figures. */
static const char *const groups[][2] = {
    { "markova", "Seed 002 · Hana Marková, B-spline křivky (Czech)" },
    { "orazem", "Seed 003 · Maruša Oražem, Bezierjeva krivulja in njen "
                "odmik (Slovene)" },
    { "sir", "Seed 000 · Zbyněk Šír, Bézierovy křivky (Czech)" },
    { "lecture5", "Seed 001 · Лекция 5: Кривые и поверхности в "
                  "компьютерной геометрии, I (Russian)" },
    { "lec05", "Seed 004 · Lec05, Bezier曲线 B样条曲线 (Chinese)" },
    { "surfaces", "Part II · Surfaces: 3D figures with exact hidden lines" },
    { "anim", "Animations · the interactive examples swept, the overlay "
              "figures step by step (docs/animations.md)" },
};

static const char gallery_head[] =
    "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    "<meta name=\"viewport\" "
    "content=\"width=device-width, initial-scale=1\">\n"
    "<title>";
static const char gallery_style[] = "</title>\n<style>\n"
    "body{font-family:serif;margin:2em auto;max-width:90em;padding:0 1em}\n"
    "nav li{margin:.3em 0}nav a{text-decoration:none}\n"
    "h2{margin:1.5em 0 .5em;border-bottom:1px solid #ccc}\n"
    ".script{display:grid;grid-template-columns:minmax(0,3fr) "
    "minmax(0,2fr);gap:1em;margin:1em 0;padding-top:.5em;"
    "border-top:1px dashed #ddd}\n"
    ".figs{display:grid;grid-template-columns:repeat(auto-fill,"
    "minmax(18em,1fr));gap:1em;align-content:start}\n"
    "figure{margin:0;padding:.5em;border:1px solid #ddd;border-radius:4px}\n"
    "figure img{width:100%;height:14em;object-fit:contain}\n"
    "figcaption{font-size:.9em}\nfigcaption b{font-family:monospace}\n"
    ".a11y{margin-top:.3em}.a11y p{margin:.2em 0}\n"
    ".src h3{font:bold .9em monospace;margin:0 0 .3em}\n"
    ".src pre{font-size:.75em;max-height:40em;overflow:auto;margin:0;"
    "padding:.5em;background:#f7f7f7;border:1px solid #ddd}\n"
    ".ss{display:inline-flex;flex-direction:column;vertical-align:.42em;"
    "font-size:.75em;line-height:1.05}\n"
    ".ss sup,.ss sub{font-size:1em;vertical-align:baseline}\n"
    "@media (max-width:60em){.script{grid-template-columns:1fr}}\n"
    "</style>\n</head>\n<body>\n<h1>";

static const char *
group_title(const char *prefix, size_t n)
{
    for (size_t i = 0; i < sizeof groups / sizeof groups[0]; i++)
        if (strlen(groups[i][0]) == n && strncmp(groups[i][0], prefix, n) == 0)
            return groups[i][1];
    return NULL;
}

/* The length of one script after s[0] (_ or ^): a {group} (its braces
** counted, nested ones kept) or one UTF-8 character; *body, *blen its
** text. */
static size_t
script_arg(const char *s, const char **body, size_t *blen)
{
    size_t k = 1;
    if (s[1] == '{') {
        int depth = 1;
        for (k = 2; s[k] != '\0' && depth > 0; k++)
            depth += s[k] == '{' ? 1 : s[k] == '}' ? -1 : 0;
        if (depth > 0)
            return 0;
        *body = s + 2;
        *blen = k - 3;
        return k;
    }
    if (s[1] == '\0' || s[1] == ' ')
        return 0;
    k = 2;
    while ((s[k] & 0xc0) == 0x80)
        k++;
    *body = s + 1;
    *blen = k - 1;
    return k;
}

static void put_math(FILE *f, const char *s, size_t n);

static void
put_script(FILE *f, char which, const char *body, size_t blen)
{
    fputs(which == '_' ? "<sub>" : "<sup>", f);
    put_math(f, body, blen);
    fputs(which == '_' ? "</sub>" : "</sup>", f);
}

/* The first n bytes of caption s as HTML, scripts typeset. */
static void
put_math(FILE *f, const char *s, size_t n)
{
    size_t i = 0;
    while (i < n) {
        const char *b1, *b2;
        size_t l1, l2, k1, k2;
        if ((s[i] != '_' && s[i] != '^') || i == 0 || s[i - 1] == ' '
            || (k1 = script_arg(s + i, &b1, &l1)) == 0 || i + k1 > n) {
            const char *e = s + i + 1;
            while (e < s + n && *e != '_' && *e != '^')
                e++;
            cf__tool_put_html(f, s + i, (size_t)(e - (s + i)));
            i = (size_t)(e - s);
            continue;
        }
        /* a subscript and a superscript on one base: stacked */
        if ((s[i + k1] == '_' || s[i + k1] == '^') && s[i + k1] != s[i]
            && (k2 = script_arg(s + i + k1, &b2, &l2)) != 0
            && i + k1 + k2 <= n) {
            fputs("<span class=\"ss\">", f);
            if (s[i] == '^') {
                put_script(f, '^', b1, l1);
                put_script(f, '_', b2, l2);
            } else {
                put_script(f, '^', b2, l2);
                put_script(f, '_', b1, l1);
            }
            fputs("</span>", f);
            i += k1 + k2;
        } else {
            put_script(f, s[i], b1, l1);
            i += k1;
        }
    }
}

/* A script's source (read as every script is: a FIFO, a device or a
** directory named in a manifest is not read). */
static void
put_source(FILE *out, const char *script)
{
    size_t n;
    const char *why;
    char *text = cf__tool_read_file(script, GALLERY_MAX_FILE, &n, &why);
    if (text == NULL) {
        fputs("<p>(source not found)</p>", out);
        return;
    }
    fputs("<pre>", out);
    cf__tool_put_html(out, text, n);
    fputs("</pre>", out);
    free(text);
}

static const char *
base_name(const char *path)
{
    const char *b = strrchr(path, '/');
    return b != NULL ? b + 1 : path;
}

/* The figure's alt text and long description, shown below its caption
** (docs/accessibility.md): the text a reader without the image gets. */
static void
put_access(FILE *out, const entry_t *e)
{
    if (e->alt[0] == '\0' && e->desc[0] == '\0')
        return;
    fputs("<details class=\"a11y\"><summary>Alt text", out);
    fputs(e->desc[0] != '\0' ? " and description" : "", out);
    fputs("</summary>\n<p class=\"alt\">", out);
    cf__tool_put_html(out, e->alt, strlen(e->alt));
    fputs("</p>", out);
    if (e->desc[0] != '\0') {
        fputs("\n<p class=\"desc\">", out);
        cf__tool_put_html(out, e->desc, strlen(e->desc));
        fputs("</p>", out);
    }
    fputs("</details>", out);
}

static void
put_figure(FILE *out, const entry_t *e)
{
    const char *name = e->name, *cap = e->caption;
    char fmts[64];
    fputs("<figure id=\"", out);
    cf__tool_put_html(out, name, strlen(name));
    fputs("\">", out);
    if (strstr(e->formats, "svg") != NULL || strstr(e->formats, "png") != NULL) {
        const char *img = strstr(e->formats, "svg") != NULL ? "svg" : "png";
        fputs("<a href=\"", out);
        cf__tool_put_html(out, name, strlen(name));
        fprintf(out, ".%s\"><img src=\"", img);
        cf__tool_put_html(out, name, strlen(name));
        fprintf(out, ".%s\" alt=\"", img);
        cf__tool_put_html(out, e->alt[0] != '\0' ? e->alt : cap,
                          strlen(e->alt[0] != '\0' ? e->alt : cap));
        fputs("\" loading=\"lazy\"></a>", out);
    }
    fputs("\n<figcaption><b>", out);
    cf__tool_put_html(out, name, strlen(name));
    fputs("</b> ", out);
    put_math(out, cap, strlen(cap));
    fputs("<br>", out);
    snprintf(fmts, sizeof fmts, "%s", e->formats);
    for (char *f = strtok(fmts, ","); f != NULL; f = strtok(NULL, ",")) {
        char upper[8];
        size_t k;
        for (k = 0; k + 1 < sizeof upper && f[k] != '\0'; k++)
            upper[k] = (char)(f[k] >= 'a' && f[k] <= 'z' ? f[k] - 32 : f[k]);
        upper[k] = '\0';
        fputs(" <a href=\"", out);
        cf__tool_put_html(out, name, strlen(name));
        fputc('.', out);
        cf__tool_put_html(out, f, strlen(f));
        fputs("\">", out);
        cf__tool_put_html(out, upper, strlen(upper));
        fputs("</a>", out);
    }
    if (e->script[0] != '\0') {
        fputs(" · <a href=\"#src-", out);
        cf__tool_put_html(out, base_name(e->script), strlen(base_name(e->script)));
        fputs("\">script</a>", out);
    }
    put_access(out, e);
    fputs("</figcaption></figure>\n", out);
}

static size_t
prefix_len(const char *name)
{
    return strcspn(name, "-");
}

static void
put_group_heading(FILE *out, const char *tag, const char *name, bool link)
{
    size_t plen = prefix_len(name);
    const char *t = group_title(name, plen);
    fprintf(out, "<%s>", tag);
    if (link) {
        fputs("<a href=\"#g-", out);
        cf__tool_put_html(out, name, plen);
        fputs("\">", out);
    }
    if (t != NULL)
        cf__tool_put_html(out, t, strlen(t));
    else
        cf__tool_put_html(out, name, plen);
    fputs(link ? "</a>" : "", out);
    if (strcmp(tag, "li") != 0)   /* an index entry stays open */
        fprintf(out, "</%s>", tag);
}

static bool
same_group(const entry_t *a, const entry_t *b)
{
    size_t n = prefix_len(a->name);
    return n == prefix_len(b->name) && strncmp(a->name, b->name, n) == 0;
}

/* The index: per group its title and its figures. */
static void
put_index(FILE *out, const entry_t *es, size_t n)
{
    fputs("<nav><ul>\n", out);
    for (size_t i = 0; i < n; i++) {
        const char *short_name = es[i].name + prefix_len(es[i].name);
        if (i == 0 || !same_group(&es[i - 1], &es[i])) {
            if (i > 0)
                fputs("</li>\n", out);
            put_group_heading(out, "li", es[i].name, true);
            fputs(":", out);
        }
        if (*short_name == '-')
            short_name++;
        fputs(" <a href=\"#", out);
        cf__tool_put_html(out, es[i].name, strlen(es[i].name));
        fputs("\">", out);
        cf__tool_put_html(out, short_name, strlen(short_name));
        fputs("</a>", out);
    }
    if (n > 0)
        fputs("</li>\n", out);
    fputs("</ul></nav>\n", out);
}

static void
put_body(FILE *out, const entry_t *es, size_t n)
{
    size_t i = 0;
    while (i < n) {
        size_t j = i + 1;
        if (i == 0 || !same_group(&es[i - 1], &es[i])) {
            fputs("<section id=\"g-", out);
            cf__tool_put_html(out, es[i].name, prefix_len(es[i].name));
            fputs("\">", out);
            put_group_heading(out, "h2", es[i].name, false);
            fputs("\n", out);
        }
        /* the figures of one script, beside its source */
        while (j < n && strcmp(es[j].script, es[i].script) == 0
               && es[i].script[0] != '\0' && same_group(&es[i], &es[j]))
            j++;
        fputs("<div class=\"script\"><div class=\"figs\">\n", out);
        for (size_t k = i; k < j; k++)
            put_figure(out, &es[k]);
        fputs("</div>", out);
        if (es[i].script[0] != '\0') {
            const char *b = base_name(es[i].script);
            fputs("<div class=\"src\" id=\"src-", out);
            cf__tool_put_html(out, b, strlen(b));
            fputs("\"><h3>", out);
            cf__tool_put_html(out, b, strlen(b));
            fputs("</h3>", out);
            put_source(out, es[i].script);
            fputs("</div>", out);
        }
        fputs("</div>\n", out);
        if (j == n || !same_group(&es[j - 1], &es[j]))
            fputs("</section>\n", out);
        i = j;
    }
}

/* Split one manifest line into e (its fields copied); false when it is
** not one. */
static bool
parse_line(char *line, entry_t *e)
{
    char *f[6] = { line, NULL, NULL, NULL, NULL, NULL };
    char *nl = strchr(line, '\n');
    if (nl != NULL)
        *nl = '\0';
    for (int k = 1; k < 6; k++) {
        char *t = strchr(f[k - 1], '\t');
        if (t == NULL)
            break;
        *t = '\0';
        f[k] = t + 1;
    }
    if (f[2] == NULL)
        return false;
    e->name = strdup(f[0]);
    e->formats = strdup(f[1]);
    e->caption = strdup(f[2]);
    e->script = strdup(f[3] != NULL ? f[3] : "");
    e->alt = strdup(f[4] != NULL ? f[4] : "");
    e->desc = strdup(f[5] != NULL ? f[5] : "");
    return e->name != NULL && e->formats != NULL && e->caption != NULL
        && e->script != NULL && e->alt != NULL && e->desc != NULL;
}

static void
free_entries(entry_t *es, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        free(es[i].name);
        free(es[i].formats);
        free(es[i].caption);
        free(es[i].script);
        free(es[i].alt);
        free(es[i].desc);
    }
    free(es);
}

/* What makes line (len bytes, its newline taken off) no manifest line,
** or NULL: a NUL byte, fewer than the three fields NAME, FORMATS and
** CAPTION, an empty name or list of formats.  (The line is parsed after.) */
static const char *
line_fault(const char *line, size_t len)
{
    const char *t1, *t2;
    if (strlen(line) != len)
        return "it has a NUL byte";
    t1 = strchr(line, '\t');
    t2 = t1 != NULL ? strchr(t1 + 1, '\t') : NULL;
    if (t2 == NULL)
        return "it has fewer than the fields NAME, FORMATS and CAPTION";
    if (t1 == line || t2 == t1 + 1)
        return "its name or its list of formats is empty";
    return NULL;
}

/* Every line of the manifests; NULL (a message said why) on failure: a
** file that cannot be read (a directory, a FIFO, a device, or larger than
** GALLERY_MAX_FILE), a line that is not a manifest line (named by file
** and line; empty lines are passed over), no memory.  Lines of any length
** (a caption of 10 MB was read as pieces of 8191 bytes, each a line). */
static entry_t *
read_manifests(const char *const *manifests, int count, size_t *n)
{
    entry_t *es = NULL;
    size_t cap = 0;
    *n = 0;
    for (int i = 0; i < count; i++) {
        size_t size, len;
        const char *why;
        char *text = cf__tool_read_file(manifests[i], GALLERY_MAX_FILE, &size,
                                        &why), *line, *next;
        long no = 0;
        if (text == NULL) {
            fprintf(stderr, "curvefig: gallery: cannot read %s: %s\n",
                    manifests[i], why);
            goto fail;
        }
        for (line = text; line < text + size; line = next) {
            const char *fault;
            char *nl = memchr(line, '\n', (size_t)(text + size - line));
            next = nl != NULL ? nl + 1 : text + size;
            len = (size_t)((nl != NULL ? nl : text + size) - line);
            no++;
            if (len > 0 && line[len - 1] == '\r')
                len--;
            line[len] = '\0';
            if (len == 0)
                continue;
            if ((fault = line_fault(line, len)) != NULL) {
                fprintf(stderr, "curvefig: gallery: %s:%ld: not a manifest "
                        "line: %s (a line is NAME, FORMATS, CAPTION, SCRIPT, "
                        "ALT and DESCRIPTION separated by tabs, as render "
                        "--manifest writes it)\n", manifests[i], no, fault);
                free(text);
                goto fail;
            }
            if (*n == cap) {
                entry_t *more = realloc(es, (cap ? 2 * cap : 64) * sizeof *es);
                if (more == NULL) {
                    free(text);
                    goto nomem;
                }
                es = more;
                cap = cap ? 2 * cap : 64;
            }
            memset(&es[*n], 0, sizeof es[*n]);
            (*n)++;
            if (!parse_line(line, &es[*n - 1])) {
                free(text);
                goto nomem;
            }
        }
        free(text);
    }
    if (es == NULL)
        es = calloc(1, sizeof *es);
    return es;
nomem:
    fprintf(stderr, "curvefig: gallery: out of memory reading the "
            "manifests\n");
fail:
    free_entries(es, *n);
    return NULL;
}

/* Whether path names the same file as a manifest (the gallery would
** overwrite it): an error saying so. */
static bool
overwrites_manifest(const char *path, const char *const *manifests,
                    int count)
{
    struct stat out, in;
    if (stat(path, &out) != 0)
        return false;
    for (int i = 0; i < count; i++)
        if (stat(manifests[i], &in) == 0 && in.st_dev == out.st_dev
            && in.st_ino == out.st_ino) {
            fprintf(stderr, "curvefig: gallery: -o %s is the manifest %s; "
                    "the gallery would overwrite it\n", path, manifests[i]);
            return true;
        }
    return false;
}

int
cf__tool_gallery(const char *out_path, const char *title,
                 const char *const *manifests, int count)
{
    cf__tool_out o;
    FILE *out;
    entry_t *es;
    size_t n;
    if (title == NULL)
        title = "curvefig figures";
    if (out_path == NULL || strcmp(out_path, ".") == 0)
        out_path = "index.html";
    if (overwrites_manifest(out_path, manifests, count))
        return 2;
    es = read_manifests(manifests, count, &n);
    if (es == NULL)
        return 2;
    if (cf__tool_open_atomic(&o, out_path) != 0) {
        fprintf(stderr, "curvefig: cannot write %s: %s\n", out_path,
                strerror(errno));
        free_entries(es, n);
        return 1;
    }
    out = o.f;
    fputs(gallery_head, out);
    cf__tool_put_html(out, title, strlen(title));
    fputs(gallery_style, out);
    cf__tool_put_html(out, title, strlen(title));
    fputs("</h1>\n", out);
    put_index(out, es, n);
    fputs("<main>\n", out);
    put_body(out, es, n);
    fputs("</main>\n</body>\n</html>\n", out);
    free_entries(es, n);
    if (cf__tool_close_atomic(&o) != 0) {
        fprintf(stderr, "curvefig: cannot write %s: %s\n", out_path,
                strerror(errno));
        return 1;
    }
    return 0;
}

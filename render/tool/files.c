/*
** Output files of the tool: directories, atomic writes, render manifests
** and the HTML gallery that `ninja figures` builds from them; directory
** listings.
*/
#include <dirent.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "curvefig/figure.h"
#include "tool.h"

int
cf__tool_mkdir_p(const char *dir)
{
    char *p, *buf;
    size_t n = strlen(dir);
    struct stat sb;
    if (n == 0)
        return 0;
    if (stat(dir, &sb) == 0) {
        if (S_ISDIR(sb.st_mode))
            return 0;
        errno = ENOTDIR;
        return -1;
    }
    buf = malloc(n + 1);
    if (buf == NULL)
        return -1;
    memcpy(buf, dir, n + 1);
    for (p = buf + 1; *p != '\0'; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
            free(buf);
            return -1;
        }
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
        free(buf);
        return -1;
    }
    free(buf);
    return 0;
}

char *
cf__tool_join(const char *dir, const char *name)
{
    size_t a = strlen(dir), b = strlen(name);
    char *s = malloc(a + b + 2);
    if (s == NULL)
        return NULL;
    memcpy(s, dir, a);
    s[a] = '/';
    memcpy(s + a + 1, name, b + 1);
    return s;
}

static char *
temp_name(const char *path)
{
    size_t n = strlen(path);
    char *t = malloc(n + 8);
    if (t != NULL)
        snprintf(t, n + 8, "%s.tmp~", path);
    return t;
}

FILE *
cf__tool_open_atomic(const char *path)
{
    char *t = temp_name(path);
    FILE *f;
    if (t == NULL)
        return NULL;
    f = fopen(t, "wb");
    free(t);
    return f;
}

int
cf__tool_close_atomic(FILE *f, const char *path)
{
    char *t = temp_name(path);
    int bad = ferror(f);
    if (fclose(f) != 0)
        bad = 1;
    if (t == NULL)
        return -1;
    if (bad || rename(t, path) != 0) {
        int e = errno;
        remove(t);
        free(t);
        errno = e;
        return -1;
    }
    free(t);
    return 0;
}

void
cf__tool_discard_atomic(FILE *f, const char *path)
{
    char *t = temp_name(path);
    fclose(f);
    if (t != NULL)
        remove(t);
    free(t);
}

/* Captions keep to one line in the manifest. */
static void
put_oneline(FILE *f, const char *s)
{
    for (; s != NULL && *s != '\0'; s++)
        fputc(*s == '\t' || *s == '\n' || *s == '\r' ? ' ' : *s, f);
}

void
cf__tool_manifest_line(FILE *f, const char *name, const char *caption,
                       unsigned formats)
{
    int first = 1;
    fprintf(f, "%s\t", name);
    for (int k = 0; k < CF_FORMAT_LAST_; k++) {
        if (!(formats & CF_FORMAT_BIT(k)))
            continue;
        fprintf(f, "%s%s", first ? "" : ",",
                cf_format_extension((cf_format_t)k));
        first = 0;
    }
    fputc('\t', f);
    put_oneline(f, caption);
    fputc('\n', f);
}

/* ---- the gallery -------------------------------------------------------- */

void
cf__tool_put_html(FILE *f, const char *s, size_t n)
{
    for (size_t i = 0; i < n && s[i] != '\0'; i++) {
        switch (s[i]) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(s[i], f); break;
        }
    }
}

static const char gallery_head[] =
    "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    "<meta name=\"viewport\" "
    "content=\"width=device-width, initial-scale=1\">\n"
    "<title>%s</title>\n<style>\n"
    "body{font-family:serif;margin:2em auto;max-width:72em;padding:0 1em}\n"
    "main{display:grid;"
    "grid-template-columns:repeat(auto-fill,minmax(20em,1fr));"
    "gap:1.5em}\n"
    "h2{grid-column:1/-1;margin:1em 0 0;border-bottom:1px solid #ccc}\n"
    "figure{margin:0;padding:.5em;border:1px solid #ddd;border-radius:4px}\n"
    "figure img{width:100%%;height:14em;object-fit:contain}\n"
    "figcaption{font-size:.9em}\nfigcaption b{font-family:monospace}\n"
    "</style>\n</head>\n<body>\n<h1>%s</h1>\n<main>\n";

/* One manifest line: name TAB formats TAB caption. */
static void
gallery_entry(FILE *out, char *line, char *group, size_t group_size)
{
    char *name = line, *fmts, *cap, *e;
    size_t plen;
    fmts = strchr(name, '\t');
    if (fmts == NULL)
        return;
    *fmts++ = '\0';
    cap = strchr(fmts, '\t');
    if (cap == NULL)
        return;
    *cap++ = '\0';
    e = strchr(cap, '\n');
    if (e != NULL)
        *e = '\0';
    /* a heading whenever the seed prefix (before the first '-') changes */
    plen = strcspn(name, "-");
    if (strlen(group) != plen || strncmp(group, name, plen) != 0) {
        snprintf(group, group_size, "%.*s", (int)plen, name);
        fputs("<h2>", out);
        cf__tool_put_html(out, group, plen);
        fputs("</h2>\n", out);
    }
    fputs("<figure id=\"", out);
    cf__tool_put_html(out, name, strlen(name));
    fputs("\">", out);
    if (strstr(fmts, "svg") != NULL || strstr(fmts, "png") != NULL) {
        const char *img = strstr(fmts, "svg") != NULL ? "svg" : "png";
        fputs("<a href=\"", out);
        cf__tool_put_html(out, name, strlen(name));
        fprintf(out, ".%s\"><img src=\"", img);
        cf__tool_put_html(out, name, strlen(name));
        fprintf(out, ".%s\" alt=\"", img);
        cf__tool_put_html(out, cap, strlen(cap));
        fputs("\" loading=\"lazy\"></a>", out);
    }
    fputs("\n<figcaption><b>", out);
    cf__tool_put_html(out, name, strlen(name));
    fputs("</b> ", out);
    cf__tool_put_html(out, cap, strlen(cap));
    fputs("<br>", out);
    for (char *f = strtok(fmts, ","); f != NULL; f = strtok(NULL, ",")) {
        char upper[8];
        size_t k;
        for (k = 0; k + 1 < sizeof upper && f[k] != '\0'; k++)
            upper[k] = (char)(f[k] >= 'a' && f[k] <= 'z' ? f[k] - 32 : f[k]);
        upper[k] = '\0';
        fputs(" <a href=\"", out);
        cf__tool_put_html(out, name, strlen(name));
        fprintf(out, ".%s\">%s</a>", f, upper);
    }
    fputs("</figcaption></figure>\n", out);
}

int
cf__tool_gallery(const char *out_path, const char *title,
                 const char *const *manifests, int count)
{
    FILE *out;
    char line[4096], group[64] = "";
    if (title == NULL)
        title = "curvefig figures";
    if (out_path == NULL || strcmp(out_path, ".") == 0)
        out_path = "index.html";
    out = cf__tool_open_atomic(out_path);
    if (out == NULL) {
        fprintf(stderr, "curvefig: cannot write %s: %s\n", out_path,
                strerror(errno));
        return 1;
    }
    fprintf(out, gallery_head, title, title);
    for (int i = 0; i < count; i++) {
        FILE *m = fopen(manifests[i], "r");
        if (m == NULL) {
            fprintf(stderr, "curvefig: cannot read %s: %s\n", manifests[i],
                    strerror(errno));
            cf__tool_discard_atomic(out, out_path);
            return 2;
        }
        while (fgets(line, sizeof line, m) != NULL)
            gallery_entry(out, line, group, sizeof group);
        fclose(m);
    }
    fputs("</main>\n</body>\n</html>\n", out);
    if (cf__tool_close_atomic(out, out_path) != 0) {
        fprintf(stderr, "curvefig: cannot write %s: %s\n", out_path,
                strerror(errno));
        return 1;
    }
    return 0;
}

/* ---- directory listings ------------------------------------------------- */

static int
by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

void
cf__tool_free_list(char **list, size_t count)
{
    for (size_t i = 0; i < count; i++)
        free(list[i]);
    free(list);
}

char **
cf__tool_list_dir(const char *dir, const char *suffix, size_t *count)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **list = NULL;
    size_t n = 0, cap = 0, m = strlen(suffix);
    *count = 0;
    if (d == NULL)
        return NULL;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        char *name;
        if (e->d_name[0] == '.' || len <= m ||
            strcmp(e->d_name + len - m, suffix) != 0)
            continue;
        if (n == cap) {
            char **more = realloc(list, (cap ? 2 * cap : 16) * sizeof *list);
            if (more == NULL)
                goto fail;
            list = more;
            cap = cap ? 2 * cap : 16;
        }
        name = malloc(len - m + 1);
        if (name == NULL)
            goto fail;
        memcpy(name, e->d_name, len - m);
        name[len - m] = '\0';
        list[n++] = name;
    }
    closedir(d);
    if (list == NULL)
        list = malloc(sizeof *list);     /* an empty list, not a failure */
    if (list == NULL) {
        errno = ENOMEM;
        return NULL;
    }
    qsort(list, n, sizeof *list, by_name);
    *count = n;
    return list;
fail:
    closedir(d);
    cf__tool_free_list(list, n);
    errno = ENOMEM;
    return NULL;
}

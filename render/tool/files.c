/*
** Output files of the tool: directories, atomic writes (every file
** through the renderer's one writer, cf_write_file), render manifests
** and the HTML gallery that `ninja figures` builds from them; directory
** listings.
*/
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "curvefig/figure.h"
#include "curvefig/output.h"
#include "animate.h"
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

int
cf__tool_open_atomic(cf__tool_out *o, const char *path)
{
    memset(o, 0, sizeof *o);
    o->path = path;
    o->f = open_memstream(&o->data, &o->size);
    return o->f != NULL ? 0 : -1;
}

int
cf__tool_close_atomic(cf__tool_out *o)
{
    cf_diag_t diag;
    int bad = ferror(o->f), rc = 0;
    if (fclose(o->f) != 0 || bad) {
        errno = EIO;
        rc = -1;
    } else {
        errno = 0;
        if (cf_write_file(o->path, o->data, o->size, &diag)
            != CF_STATUS_OK) {
            rc = -1;
            if (errno == 0)
                errno = EIO;
        }
    }
    free(o->data);
    memset(o, 0, sizeof *o);
    return rc;
}

void
cf__tool_discard_atomic(cf__tool_out *o)
{
    fclose(o->f);
    free(o->data);
    memset(o, 0, sizeof *o);
}

char *
cf__tool_read_file(const char *path, size_t max, size_t *len,
                   const char **why)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat sb;
    char *buf = NULL;
    size_t n = 0, cap;
    *len = 0;
    *why = NULL;
    if (fd < 0) {
        *why = strerror(errno);
        return NULL;
    }
    /* a FIFO would block the reader for ever, a directory reads as
    ** nothing: neither is a script */
    if (fstat(fd, &sb) != 0) {
        *why = strerror(errno);
        close(fd);
        return NULL;
    }
    if (!S_ISREG(sb.st_mode)) {
        *why = S_ISDIR(sb.st_mode) ? "it is a directory, not a file"
                                   : "it is not a regular file (a FIFO, "
                                     "a socket or a device)";
        close(fd);
        return NULL;
    }
    if ((unsigned long long)sb.st_size > max) {
        *why = "the file is too large";
        close(fd);
        return NULL;
    }
    cap = (size_t)sb.st_size + 4097;
    for (;;) {
        ssize_t got;
        if (n + 1 >= cap) {
            char *p = n >= max ? NULL : realloc(buf, cap * 2);
            if (p == NULL) {
                *why = n >= max ? "the file is too large" : "out of memory";
                break;
            }
            buf = p;
            cap *= 2;
        } else if (buf == NULL && (buf = malloc(cap)) == NULL) {
            *why = "out of memory";
            break;
        }
        got = read(fd, buf + n, cap - n - 1);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            *why = strerror(errno);
            break;
        }
        if (got == 0) {
            close(fd);
            buf[n] = '\0';
            *len = n;
            return buf;
        }
        n += (size_t)got;
    }
    close(fd);
    free(buf);
    return NULL;
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
                       unsigned formats, const char *script, const char *alt,
                       const char *desc)
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
    /* an animation's own formats (animate.h) */
    for (int k = 0; k < 4; k++) {
        static const char *const ext[] = { "gif", "apng", "mp4", "webm" };
        if (!(formats & (CF__TOOL_GIF_BIT << k)))
            continue;
        fprintf(f, "%s%s", first ? "" : ",", ext[k]);
        first = 0;
    }
    fputc('\t', f);
    put_oneline(f, caption);
    fputc('\t', f);
    put_oneline(f, script);
    fputc('\t', f);
    put_oneline(f, alt);
    fputc('\t', f);
    put_oneline(f, desc);
    fputc('\n', f);
}

/* ---- HTML --------------------------------------------------------------- */

void
cf__tool_put_html(FILE *f, const char *s, size_t n)
{
    for (size_t i = 0; i < n && s[i] != '\0'; i++) {
        switch (s[i]) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&#39;", f); break;
        default: fputc(s[i], f); break;
        }
    }
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

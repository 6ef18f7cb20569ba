/*
** The figure scripts `curvefig test` is given; see operands.h.
*/
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "operands.h"
#include "tool.h"

static int
add(cf__tool_scripts *s, const char *path)
{
    char *copy;
    if (s->count == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 16;
        char **more = realloc(s->path, cap * sizeof *more);
        if (more == NULL)
            return -1;
        s->path = more;
        s->cap = cap;
    }
    copy = strdup(path);
    if (copy == NULL)
        return -1;
    s->path[s->count++] = copy;
    return 0;
}

static int
add_dir(cf__tool_scripts *s, const char *dir)
{
    size_t n, before = s->count;
    char **names = cf__tool_list_dir(dir, ".lua", &n);
    int rc = 0;
    if (names == NULL) {
        fprintf(stderr, "curvefig: test: cannot read the directory %s: %s\n",
                dir, strerror(errno));
        return -1;
    }
    for (size_t i = 0; i < n && rc == 0; i++) {
        char *file = malloc(strlen(names[i]) + 5), *path;
        struct stat sb;
        if (file == NULL) {
            rc = -1;
            break;
        }
        snprintf(file, strlen(names[i]) + 5, "%s.lua", names[i]);
        path = cf__tool_join(dir, file);
        free(file);
        if (path == NULL)
            rc = -1;
        else if (stat(path, &sb) == 0 && S_ISREG(sb.st_mode))
            rc = add(s, path);
        free(path);
    }
    cf__tool_free_list(names, n);
    if (rc != 0) {
        fprintf(stderr, "curvefig: test: out of memory\n");
        return -1;
    }
    if (s->count == before) {
        fprintf(stderr, "curvefig: test: %s holds no figure script "
                "(*.lua)\n", dir);
        return -1;
    }
    return 0;
}

int
cf__tool_scripts_add(cf__tool_scripts *s, const char *operand)
{
    struct stat sb;
    if (s->count == 0 && s->cap == 0)
        s->only_dirs = true;
    if (stat(operand, &sb) != 0) {
        fprintf(stderr, "curvefig: test: cannot read %s: %s\n", operand,
                strerror(errno));
        return -1;
    }
    if (S_ISDIR(sb.st_mode))
        return add_dir(s, operand);
    s->only_dirs = false;
    if (add(s, operand) != 0) {
        fprintf(stderr, "curvefig: test: out of memory\n");
        return -1;
    }
    return 0;
}

void
cf__tool_scripts_free(cf__tool_scripts *s)
{
    for (size_t i = 0; i < s->count; i++)
        free(s->path[i]);
    free(s->path);
    memset(s, 0, sizeof *s);
}

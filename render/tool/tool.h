/*
** Internals of the curvefig tool shared between its files.
*/
#ifndef CURVEFIG_TOOL_H
#define CURVEFIG_TOOL_H

#include <stdio.h>

/* mkdir -p; 0 on success (errno set otherwise). */
int cf__tool_mkdir_p(const char *dir);
/* dir + "/" + name, malloc'd (NULL when out of memory). */
char *cf__tool_join(const char *dir, const char *name);
/* Write to path through a temporary file renamed on close, so that a
** failure never leaves a half-written file.  NULL on failure (errno). */
FILE *cf__tool_open_atomic(const char *path);
int cf__tool_close_atomic(FILE *f, const char *path);
/* Close and remove the temporary file (the target is left as it was). */
void cf__tool_discard_atomic(FILE *f, const char *path);

/* The names in dir that end in suffix (and do not start with '.'), the
** suffix cut off, in strcmp order; *count of them.  NULL (*count 0, errno
** set) when dir cannot be read or memory runs out. */
char **cf__tool_list_dir(const char *dir, const char *suffix, size_t *count);
void cf__tool_free_list(char **list, size_t count);

/* One line of a render manifest: name TAB formats TAB caption TAB script
** (the path of the script that made the figure). */
void cf__tool_manifest_line(FILE *f, const char *name, const char *caption,
                            unsigned formats, const char *script);
/* Write the first n bytes of s (up to a NUL) with & < > " escaped. */
void cf__tool_put_html(FILE *f, const char *s, size_t n);
/* Write the HTML gallery `out` from manifests in the given order
** (gallery.c); returns the exit status. */
int cf__tool_gallery(const char *out, const char *title,
                     const char *const *manifests, int count);

/* Before the first font is used: a fontconfig configuration with just
** the figure fonts (fonts.c), unless the user chose one or the fonts are
** elsewhere.  Returns which configuration is in use, for --version. */
const char *cf__tool_fonts_init(void);

#endif

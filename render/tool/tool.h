/*
** Internals of the curvefig tool shared between its files.
*/
#ifndef CURVEFIG_TOOL_H
#define CURVEFIG_TOOL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* mkdir -p; 0 on success (errno set otherwise). */
int cf__tool_mkdir_p(const char *dir);
/* dir + "/" + name, malloc'd (NULL when out of memory). */
char *cf__tool_join(const char *dir, const char *name);
/* A file written whole at its close through the one writer of every
** curvefig file (cf_write_file: a new file of a random name, created
** exclusively, renamed over path), so that a failure never leaves a
** half-written file and no planted symbolic link is followed.  Write to
** o->f; open and close return -1 on failure (errno). */
typedef struct cf__tool_out {
    FILE *f;
    const char *path;
    char *data;        /* the bytes so far (open_memstream) */
    size_t size;
} cf__tool_out;
int cf__tool_open_atomic(cf__tool_out *o, const char *path);
int cf__tool_close_atomic(cf__tool_out *o);
/* Drop what was written (the target is left as it was). */
void cf__tool_discard_atomic(cf__tool_out *o);

/* The whole regular file at path (at most max bytes), NUL-terminated
** (free()), *len its length; NULL and *why (what went wrong) when it is
** missing, unreadable, too large, a directory, or a FIFO, socket or
** device (opened without blocking, so that a FIFO cannot hang the
** reader; every read checked). */
char *cf__tool_read_file(const char *path, size_t max, size_t *len,
                         const char **why);

/* The names in dir that end in suffix (and do not start with '.'), the
** suffix cut off, in strcmp order; *count of them.  NULL (*count 0, errno
** set) when dir cannot be read or memory runs out. */
char **cf__tool_list_dir(const char *dir, const char *suffix, size_t *count);
void cf__tool_free_list(char **list, size_t count);

/* One line of a render manifest: name TAB formats TAB caption TAB script
** (the path of the script that made the figure) TAB alt text TAB long
** description (docs/accessibility.md; either may be NULL: empty). */
void cf__tool_manifest_line(FILE *f, const char *name, const char *caption,
                            unsigned formats, const char *script,
                            const char *alt, const char *desc);
/* Write the first n bytes of s (up to a NUL) with & < > " ' escaped: the
** one escaping of every text the tool writes into HTML (titles, captions,
** names, paths, messages), in element content and quoted attributes. */
void cf__tool_put_html(FILE *f, const char *s, size_t n);
/* Write the HTML gallery `out` from manifests in the given order
** (gallery.c); returns the exit status. */
int cf__tool_gallery(const char *out, const char *title,
                     const char *const *manifests, int count);

/* Set up glibc's heap for one render (render/tool/heap.c): what is freed
** kept for reuse, the heap in huge pages; a block to free at the end (or
** NULL). */
void *cf__tool_heap_for_one_run(void);

/* Before the first font is used: a fontconfig configuration with just
** the figure fonts (fonts.c), unless the user chose one or the fonts are
** elsewhere.  Returns which configuration is in use, for --version. */
const char *cf__tool_fonts_init(void);

/* A font directory of the tool's configuration. */
typedef struct cf__tool_font_dir {
    const char *path;
    bool required;
} cf__tool_font_dir_t;

/* A function that takes the tool's configuration (its directories
** dirs[0..ndirs-1], present, and its accepted families) without
** fontconfig, and registers make_config to make fontconfig's when pango
** needs it; false when it declines (fontconfig's is made at once). */
typedef bool (*cf__tool_own_fonts_fn)(const cf__tool_font_dir_t *dirs,
                                      size_t ndirs,
                                      const char *const *families,
                                      size_t nfamilies,
                                      void (*make_config)(void));

/* Use fn in cf__tool_fonts_init (curvefig: cf__tool_own_faces). */
void cf__tool_fonts_own(cf__tool_own_fonts_fn fn);

/* curvefig's: its renderer's matcher (faces.c). */
bool cf__tool_own_faces(const cf__tool_font_dir_t *dirs, size_t ndirs,
                        const char *const *families, size_t nfamilies,
                        void (*make_config)(void));

/* curvefig check (colours.c): the colour clashes of every figure of the
** run script s, as lines on stderr (json: and the checks as JSON on
** stdout); 0 when none, 1 otherwise.  CF__TOOL_MIN_DE is the default
** least distance (docs/accessibility.md). */
#define CF__TOOL_MIN_DE 10.0
struct cf_script;
int cf__tool_colours(const struct cf_script *s, const char *script,
                     double min_de, bool json);

#endif

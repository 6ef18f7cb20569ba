/*
** The fonts' metadata cache of the face matcher (render/backends/
** font-cache.c): reading the cmap of every font of the tool's
** configuration (46 faces, of which 20 CJK faces of 65,000 characters)
** costs more than a render, so what render/fontfile/fontmeta.h and
** fontlangs.h read of each file is kept in one file, and a file is read
** again only when its size or modification time changed.  A directory is
** revalidated as fontconfig revalidates its caches, by its own time: when
** its time is the one the cache recorded, its files are the cache's
** record of it (no readdir, no stat of a file: one stat a directory for a
** warm run); else it is walked (listed, sorted, each file's size and
** time compared with its entry's).  A file added, removed or renamed
** changes its directory's time; one added in the same tick of a coarse
** clock as the time recorded would not, so that a record is trusted
** only when settled: its directory's time 2 s or more before the walk
** that wrote it (an unsettled directory is walked at every run, and the
** cache written anew once its record would be settled).  A file changed
** in place leaves its directory's time alone: a font taken from a
** directory's record carries its file's size and time as recorded, and
** they are compared with the file's at its first use (its coverage, or
** its drawing: cf__fm_font_verify), where a difference is treated as a
** damaged view (below): its charset read from the file and the cache
** removed, written anew by the next run.
**
** The cache file is $XDG_CACHE_HOME/curvefig/faces-2.cache (an absolute
** XDG_CACHE_HOME), else $HOME/.cache/curvefig/faces-2.cache.  The directory
** is made mode 0700 when missing and used only when it is a directory of
** the user's own, not group- or world-writable, and not a symbolic link;
** the file is written to a new file of a random name in that directory
** (O_CREAT | O_EXCL | O_NOFOLLOW, mode 0600) and renamed over the old
** one, so that a reader sees the old cache or the new one, never a part;
** and it is read as untrusted bytes: magic, version, every length and
** offset, every name, range and number checked, each file's path, size
** and modification time compared with the file's now.  A cache found
** wrong in any way is ignored and written anew; one that cannot be read
** or written (no HOME, a read-only directory) only means reading the
** fonts.  A file that is no font, or a face the reader refuses, is kept
** too, so that it is not read again at every run.
**
** The file's layout (numbers little-endian, no padding):
**   header  "CFFACES\0", version u32 (2), languages u32 (fontconfig's
**           count, langs-table.h), entries u32, directories u32, total
**           length u32
**   entry   length u32 (of the whole entry), path length u16, path,
**           size u64, mtime seconds i64, nanoseconds u32, status u8
**           (0 faces, 1 refused, 2 not a font), then for status 0 the
**           number of faces u16 and each face, for status 1 the reason
**           (u16 length, bytes)
**   face    index u32, families u8, each (u8 length, name, u8 length,
**           language), PostScript name (u8 length, bytes), slant i32,
**           weight, width f64, flags u8 (decorative, cff, code pages,
**           optical size),
**           optical sizes 2 x f64, font version i32, code pages 2 x u32,
**           languages 8 x u32, ranges u32, then first and last u32 of
**           each; 0 ranges: the previous face's of the file (the faces
**           of a collection mostly share one cmap).
**   directory (after the entries, one a walked directory) path length
**           u16, path, mtime seconds i64, nanoseconds u32, settled u8,
**           first entry u32, entries u32: its files are the entries
**           first.. in the walk's order (each "path/name", sorted, no
**           dot file); the records' runs follow one another and cover
**           every entry, and no directory has two records.  Version 1
**           had none: such a cache is refused, and written anew.
** A file's entry is checked when it is used: its structure whole (every
** length and count in bounds); a face of an accepted family field by
** field, the others only skipped.  The file stays mapped while the
** configuration lives (render/backends/font-match.h; a cache is
** replaced by rename, never written in place), and a face's
** charset is a view of its ranges there, checked (ascending, apart, in
** Unicode) the first time the face's coverage is used: a face found
** damaged then has its charset read from its file, and the cache file is
** removed so that the next run writes it anew.  cf__fcache_check checks
** every field and range of every face, and every directory record.
*/
#ifndef CURVEFIG_RENDER_FONT_CACHE_H
#define CURVEFIG_RENDER_FONT_CACHE_H

#include <stddef.h>

#include "font-match.h"

/* The configuration of the font directories dirs[0..ndirs-1] accepting
** the families, each file's faces taken from the cache file at cache
** (NULL: no cache) when it is current there, else read (and the cache
** written anew).  0 and *out; 1 when the matcher declines (why says
** what); -1 out of memory. */
int cf__fcache_config(const cf__fm_source_t *dirs, size_t ndirs,
                      const char *const *accept, size_t naccept,
                      const char *cache, cf__fm_config_t **out, char *why,
                      size_t why_cap);

/* The user's cache file (see above) into buf (cap bytes); false when
** there is none (no absolute XDG_CACHE_HOME nor HOME, or too long). */
bool cf__fcache_path(char *buf, size_t cap);

/* The cache's entries checked as the reader checks them: the number of
** entries of a valid cache data[0..len), or -1 (for tests and the fuzz
** target: every field of every entry is decoded). */
long cf__fcache_check(const unsigned char *data, size_t len);

#endif

/*
** Fuzz target: the reader of the fonts' metadata cache (render/backends/
** font-cache.h, cf__fcache_check) on arbitrary bytes: the cache lives in
** the user's directory, where anything may have been written.  Every
** field of every entry is decoded and checked (names, lengths, ranges,
** numbers), and every directory record (its run of entries in range,
** each a file of the directory, in order; the runs covering the entries;
** no directory twice); the input is a valid cache (its number of
** entries, no more than the bytes can hold) or refused (-1), never a
** crash, a read out of bounds (the sanitizers) or a stall.
**
** The seeds (tests/fuzz/corpus/fontcache/) are caches of version 2:
** CMU Serif with a file that is no font, Latin Modern Math, and a font
** the reader refuses (written by version 1, their directory records
** added: settled, and for the refused font not), and two directories
** (LM Roman 10 with a file that is no font, and Latin Modern Math's)
** as this code wrote them.
*/
#include <stdint.h>
#include <stdlib.h>

#include "font-cache.h"
#include "fuzz-check.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    long n = cf__fcache_check(data, size);
    FZ_CHECK(n >= -1, "-1 or a number of entries");
    FZ_CHECK(n < 0 || (size_t)n <= size / 16,
             "no more entries than the bytes hold");
    /* the same bytes, the same answer */
    FZ_CHECK(cf__fcache_check(data, size) == n, "deterministic");
    return 0;
}

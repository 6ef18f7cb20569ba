/*
** The heap of one render (render/tool/tool.h).
**
** One render is one short process, and on this kind of machine (a
** virtual machine) most of its CPU time is the kernel's: each page of
** fresh memory the program touches is a page fault, about 12 us here:
** markova-2.17's PDF touched 650 pages of heap (cairo alone copies each
** font's CFF table into fresh memory twice when it writes a PDF), 8 ms
** of its 36.  So:
**
** - glibc's allocator keeps what is freed for the next allocation rather
**   than handing it back to the system (memory of 128 KiB and more it maps
**   afresh and unmaps on free, and it trims the top of its heap): the
**   rasters, display lists and surfaces of the layout's passes and of each
**   format reuse pages already touched;
** - the heap is asked for in transparent huge pages (madvise, where the
**   system gives them on request, as Debian's kernels do): one fault
**   clears 2 MiB at once (0.1-0.2 ms) instead of 512 faults.  The heap
**   starts where the kernel put it, anywhere in a 2 MiB page; the part
**   before the first boundary is taken by a block never touched (so not
**   memory the program holds), so that every allocation is in huge pages.
**   A render then holds its memory rounded up to 2 MiB pages: the peak
**   of the figure set went from 22.4 to 24.4 MiB; markova-2.17's page
**   faults from 1150 to 520;
** - one arena: threads a library starts (pango's font matching, for a
**   run the native fonts hand to it) allocate from the same heap (in huge
**   pages) rather than each from a fresh 64 MiB map (the tool's own work
**   is one thread).
**
** Under a sanitizer (its own allocator) or another C library nothing is
** done.
*/
#define _DEFAULT_SOURCE   /* sbrk, madvise */
#include <stdint.h>
#include <stdlib.h>

#include "tool.h"

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define NO_HEAP_TUNING
#endif
#endif
#else
#define NO_HEAP_TUNING
#endif

#ifndef NO_HEAP_TUNING
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#define HUGE_PAGE ((uintptr_t)2 << 20)
#define HEAP_PAD ((size_t)32 << 20)   /* the heap's growth beyond a need */
#endif

void *
cf__tool_heap_for_one_run(void)
{
#ifndef NO_HEAP_TUNING
    char *probe, *end;
    uintptr_t first, last;
    void *head;
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 128 << 20);
    mallopt(M_TOP_PAD, (int)HEAP_PAD);
    mallopt(M_ARENA_MAX, 1);
    /* where the heap's top is now (a small block is cut from it), then a
    ** block from there to just before the first 2 MiB boundary: the header
    ** of the heap's top, which the allocator writes after it, must not
    ** touch the first huge page before it is advised (its page would then
    ** be a small one) */
    probe = malloc(1);
    if (probe == NULL)
        return NULL;
    first = ((uintptr_t)probe + 64 + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
    head = malloc(first - (uintptr_t)probe - 64);
    free(probe);
    /* the heap grown now (by HEAP_PAD more than this block, which goes
    ** back to its top untouched), so that the advice covers it (where it
    ** cannot grow in place, the allocator maps memory elsewhere, and that
    ** is not advised) */
    {
        /* volatile: a block freed unused may be left out by the compiler */
        char *volatile grow = malloc(HEAP_PAD / 4);
        free(grow);
    }
    end = sbrk(0);
    if (head == NULL || end == (char *)-1)
        return head;
    last = (uintptr_t)end & ~(HUGE_PAGE - 1);
    if (last > first)
        (void)madvise((void *)first, last - first, MADV_HUGEPAGE);
    return head;
#else
    return NULL;
#endif
}

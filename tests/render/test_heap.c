/* The heap of one render (render/tool/heap.c): after the set-up, the
** heap grows in a part advised for transparent huge pages (the "hg" flag
** of its mapping in /proc/self/smaps), where the system has them: blocks
** that need fresh memory lie there (a small block may still reuse one
** freed before the set-up, where it was); the block handed back
** (the part before the first 2 MiB boundary) is not touched (no memory
** held for it).  Skipped under a sanitizer (its own allocator: the set-up
** does nothing) and where the system gives no huge pages. */
#define _DEFAULT_SOURCE
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "tool.h"

/* The flags and resident size of the mapping holding address a. */
static int
mapping_of(uintptr_t a, char *flags, size_t cap, long *rss_kb)
{
    FILE *f = fopen("/proc/self/smaps", "r");
    char line[512];
    int in = 0, found = 0;
    if (f == NULL)
        return 0;
    flags[0] = '\0';
    *rss_kb = -1;
    while (fgets(line, sizeof line, f) != NULL) {
        unsigned long lo, hi;
        if (sscanf(line, "%lx-%lx ", &lo, &hi) == 2
            && strchr(line, '-') < strchr(line, ' ')) {
            if (found)
                break;
            in = a >= lo && a < hi;
            found = in;
        } else if (in && strncmp(line, "Rss:", 4) == 0) {
            *rss_kb = strtol(line + 4, NULL, 10);
        } else if (in && strncmp(line, "VmFlags:", 8) == 0) {
            snprintf(flags, cap, "%s", line + 8);
        }
    }
    fclose(f);
    return found;
}

static int
huge_pages_offered(void)
{
    FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    char line[128] = "";
    if (f == NULL)
        return 0;
    if (fgets(line, sizeof line, f) == NULL)
        line[0] = '\0';
    fclose(f);
    return strstr(line, "[always]") != NULL
           || strstr(line, "[madvise]") != NULL;
}

static void
test_allocations_in_huge_pages(void **state)
{
    void *head = cf__tool_heap_for_one_run();
    uintptr_t grown = (uintptr_t)sbrk(0);
    char flags[512];
    long rss;
    size_t sizes[] = { 5000, 100000, 3u << 20 };
    (void)state;
    /* the heap could not grow in place (another mapping after it, as
    ** address randomisation sometimes puts one): nothing was advised */
    if (head == NULL || !huge_pages_offered()
        || grown < (uintptr_t)head + (16u << 20)) {
        free(head);
        skip();
    }
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        char *p = malloc(sizes[i]);
        assert_non_null(p);
        memset(p, 1, sizes[i]);
        assert_true(mapping_of((uintptr_t)p, flags, sizeof flags, &rss));
        if (strstr(flags, " hg") == NULL) {
            fprintf(stderr, "a block of %zu bytes at %p lies in a mapping "
                    "with flags%s", sizes[i], (void *)p, flags);
            fail();
        }
        /* the start of the next 2 MiB page after the head block */
        assert_true((uintptr_t)p >= (uintptr_t)head);
        free(p);
    }
    /* the head block's own mapping: not advised, and nearly nothing of it
    ** resident (its header's page and the allocator's first blocks) */
    assert_true(mapping_of((uintptr_t)head, flags, sizeof flags, &rss));
    assert_null(strstr(flags, " hg"));
    /* (unless the allocator fills every block it hands out: MALLOC_PERTURB_,
    ** which meson's test runner sets) */
    if (getenv("MALLOC_PERTURB_") == NULL)
        assert_true(rss >= 0 && rss < 256);
    free(head);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_allocations_in_huge_pages),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

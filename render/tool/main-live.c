/*
** curvefig-live: `curvefig live` (live.h), run by the curvefig command
** (helpers.c) with its arguments; and the worker of its runs (live-worker,
** live-child.c), which it starts itself.
*/
#include <stdio.h>
#include <string.h>

#include "live.h"

int
main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "live") == 0)
        return cf__tool_live(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "live-worker") == 0)
        return cf__live_worker_main(argc - 1, argv + 1);
    fprintf(stderr, "curvefig-live: run it as 'curvefig live'\n");
    return 2;
}

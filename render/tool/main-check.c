/*
** curvefig-check: `curvefig compare` and `curvefig test` (checks.h), run
** by the curvefig command (helpers.c) with its arguments.
*/
#include <stdio.h>
#include <string.h>

#include "checks.h"

int
main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "compare") == 0)
        return cf__tool_compare(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "test") == 0)
        return cf__tool_test(argc - 1, argv + 1);
    fprintf(stderr, "curvefig-check: run it as 'curvefig compare' or "
            "'curvefig test'\n");
    return 2;
}

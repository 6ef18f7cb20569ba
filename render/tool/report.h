/*
** The HTML report of `curvefig test`: every failed comparison with its
** numbers and its expected, actual and diff images side by side.
*/
#ifndef CURVEFIG_TOOL_REPORT_H
#define CURVEFIG_TOOL_REPORT_H

#include <stddef.h>

typedef struct cf__tool_failure {
    char *figure;       /* the figure's name */
    char *script;       /* the script that defines it */
    char *what;         /* which comparison, in words */
    char *verdict;      /* the comparator's verdict, or what went wrong */
    /* image files relative to the report's directory; NULL when absent */
    char *expected, *actual, *diff;
} cf__tool_failure;

/* Release the strings of f. */
void cf__tool_failure_free(cf__tool_failure *f);

/* Write the report to path (through a temporary name); summary is one
** line for the top of the page.  0, or -1 with errno set. */
int cf__tool_report_write(const char *path, const char *summary,
                          const cf__tool_failure *fails, size_t count);

#endif

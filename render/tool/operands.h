/*
** The figure scripts `curvefig test` is given (operands.c).
*/
#ifndef CURVEFIG_TOOL_OPERANDS_H
#define CURVEFIG_TOOL_OPERANDS_H

#include <stdbool.h>
#include <stddef.h>

typedef struct cf__tool_scripts {
    char **path;
    size_t count, cap;
    bool only_dirs;      /* every operand so far was a directory */
} cf__tool_scripts;

/* Add an operand: a script, or a directory standing for its *.lua files
** in name order.  -1 with a message printed when it cannot be read or a
** directory holds no script. */
int cf__tool_scripts_add(cf__tool_scripts *s, const char *operand);
void cf__tool_scripts_free(cf__tool_scripts *s);

#endif

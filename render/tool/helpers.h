/*
** The tool's helper programs (helpers.c): `compare` and `test` in
** curvefig-check, `live` in curvefig-live, behind the one curvefig
** command.
*/
#ifndef CURVEFIG_TOOL_HELPERS_H
#define CURVEFIG_TOOL_HELPERS_H

#include <stdbool.h>

#define CF__TOOL_CHECK_HELPER "curvefig-check"
#define CF__TOOL_LIVE_HELPER "curvefig-live"

/* Replace this process by the helper program name with the same
** arguments (argv[1] the command); returns the exit status 2, with a
** message, only when the helper cannot be found or run. */
int cf__tool_run_helper(const char *name, int argc, char **argv);

#endif

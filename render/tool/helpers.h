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

/* The file name of the installation (a helper program, the WebAssembly
** module) into out, where access(mode) allows it: in the running
** program's directory, or its subdirectory build_sub (the build tree's
** place; "" for the program's own), then in the libexec directory
** relative to it (an installation moved whole), then in the
** installation's.  false when none is there; where then lists the
** directories looked in, in that order. */
bool cf__tool_find_file(const char *name, const char *build_sub, int mode,
                        char *out, size_t cap, char *where, size_t wherecap);

/* Replace this process by the helper program name with the same
** arguments (argv[1] the command); returns the exit status 2, with a
** message, only when the helper cannot be found or run. */
int cf__tool_run_helper(const char *name, int argc, char **argv);

#endif

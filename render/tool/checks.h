/*
** The checking commands of the curvefig tool: `compare` (two images) and
** `test` (figure scripts against reference images), and their help.
*/
#ifndef CURVEFIG_TOOL_CHECKS_H
#define CURVEFIG_TOOL_CHECKS_H

#include "imgcmp.h"

/* `curvefig compare A B [OPTIONS]`; argv[0] is "compare".  Exit status 0
** the same picture, 1 different, 2 an error. */
int cf__tool_compare(int argc, char **argv);

/* `curvefig test [SCRIPT... | DIR...] --references DIR [OPTIONS]`; argv[0]
** is "test".  Exit status 0 every figure matches, 1 some figure differs,
** 2 an error (usage, a script that fails, a file that cannot be written). */
int cf__tool_test(int argc, char **argv);

/* Print the help on "compare" or "test"; 2 for another topic. */
int cf__tool_checks_help(const char *topic);

/* A usage error of command: "curvefig: COMMAND: WHAT ARG" and where to
** find help; returns the exit status 2. */
int cf__tool_usage(const char *command, const char *what, const char *arg);

/* Parse an option's number in [lo, hi]; 0, or -1 with a message printed
** ("curvefig: OPT 'S': give a number from LO to HI"). */
int cf__tool_option_number(const char *opt, const char *s, double lo,
                           double hi, double *out);

/* The comparator's options the commands start from (imgcmp.h rules). */
void cf__tool_default_imgcmp(cf__imgcmp_options *opt);

#endif

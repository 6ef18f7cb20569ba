/*
** The help texts of the curvefig tool.
*/
#ifndef CURVEFIG_TOOL_HELP_H
#define CURVEFIG_TOOL_HELP_H

/* Print the help on topic (NULL: the overview; a command name; "language"
** for the figure language reference) to stdout; returns the exit status
** (2 for an unknown topic). */
int cf__tool_help(const char *topic);

#endif

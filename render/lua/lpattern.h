/*
** The cost of a Lua pattern search, measured before the search is run.
**
** string.find, match, gmatch and gsub run inside one C call, where the
** instruction hook cannot see them, and a pattern such as ".-.-.-b"
** backtracks for minutes on a long subject.  The sandbox first runs the
** same backtracking search here, counting its steps against a budget, and
** calls Lua's function only when the search fits.  This is an independent
** implementation of the matching rules of the Lua 5.4 manual (section
** 6.4.1), used only to count; the results still come from Lua.
*/
#ifndef CURVEFIG_RENDER_LUA_LPATTERN_H
#define CURVEFIG_RENDER_LUA_LPATTERN_H

#include <stddef.h>

enum {
    CF__PATTERN_FITS,      /* the search ends within the budget */
    CF__PATTERN_OVER,      /* the budget ran out */
    CF__PATTERN_UNCOUNTED  /* malformed or too deep: Lua will say so */
};

/* Count the steps of searching pattern p (lp bytes) in s (ls bytes) from
** byte offset init: the first match only (find, match), or every match to
** the end of the subject (all: gmatch, gsub).  At most max steps are
** taken; *steps receives the number taken.  Returns CF__PATTERN_*. */
int cf__pattern_cost(const char *s, size_t ls, const char *p, size_t lp,
                     size_t init, int all, long long max, long long *steps);

#endif

/*
** Numbers in messages (src/numtext.c): the shortest text that reads back
** as the same double, so that a message says 1e+300 rather than
** 1.0000000000000001e+300 and 0.17 rather than 0.17000000000000001, yet
** tells apart two numbers that differ (0.30000000000000004 stays).
**
** Used by the core's messages and by the figure language's
** (render/lua/lsurface-methods.c), whose library compiles this file into
** itself: the shared core library exports no cf__ name.  So this header
** stands alone (C11 and libm, nothing of core-private.h).
*/
#ifndef CURVEFIG_NUMTEXT_PRIVATE_H
#define CURVEFIG_NUMTEXT_PRIVATE_H

/* Room for any double's text and its terminating NUL. */
#define CF__NUM_TEXT 32

/* x with the fewest significant digits (1 to 17) that read back as x,
** written as %.*g writes them, except that a number from 1 to below 1e17
** keeps its integer digits in place (100 and 1000000, not 1e+02 and
** 1e+06: the same digits, no exponent).  -0 keeps its sign; inf and -inf
** as printf writes them, a NaN as NaN (the messages' spelling: its sign
** means nothing).  Written into buf (CF__NUM_TEXT bytes), which is
** returned. */
const char *cf__num_text(double x, char buf[CF__NUM_TEXT]);

/* cf__num_text into a buffer of its own that lives until the end of the
** enclosing block: for a message's arguments,
** cf__error(diag, st, -1, "u = %s", CF__NUM(u)). */
#define CF__NUM(x) cf__num_text((x), (char[CF__NUM_TEXT]){ 0 })

/* A formatted message's "nan" and "-nan" (printf's, for a NaN given to
** %g) as "NaN", in place: every message of the core (cf_diag_set) and of
** the figure language (cf__lua_error) spells a NaN alike. */
void cf__spell_nan(char *msg);

#endif

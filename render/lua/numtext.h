/*
** Numbers in messages (render/lua/numtext.c): the shortest text that
** reads back as the same double, so that a message says 1e+300 rather
** than 1.0000000000000001e+300 and 0.1 rather than 0.10000000000000001,
** yet tells apart two numbers that differ (0.30000000000000004 stays).
*/
#ifndef CURVEFIG_RENDER_NUMTEXT_H
#define CURVEFIG_RENDER_NUMTEXT_H

#define CF__NUM_TEXT 32

/* x with the fewest significant digits (1 to 17) that read back as x, and
** at least its integer digits (1000000, not 1e+06); nan, inf, -inf as
** printf writes them.  Written into buf (CF__NUM_TEXT bytes), which is
** returned. */
const char *cf__num_text(double x, char buf[CF__NUM_TEXT]);

#endif

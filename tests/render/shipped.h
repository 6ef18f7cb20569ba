/* Every figure of the shipped scripts (the .lua files of figures/ in the
** source tree), for the tests that check them all. */
#ifndef CURVEFIG_TESTS_SHIPPED_H
#define CURVEFIG_TESTS_SHIPPED_H

#include <stddef.h>

#include "curvefig/figure.h"

/* A check of one figure (of the script file script, named name): its
** number of faults. */
typedef int (*tu_figure_check_t)(void *ctx, const char *script,
                                 const char *name, cf_figure_t *fig);

/* Run each script of root/figures in a fresh sandbox (a script that
** fails fails the test) and hand every figure it defines to check;
** returns the number of figures, and in *failed (when not NULL) how many
** had faults. */
size_t tu_each_shipped_figure(const char *root, tu_figure_check_t check,
                              void *ctx, size_t *failed);

/* The same over the scripts of root/figures and of every directory in it
** (figures/interactive, figures/surfaces, figures/examples, ...), run as
** they are: sliders at their default values. */
size_t tu_each_shipped_figure_all(const char *root, tu_figure_check_t check,
                                  void *ctx, size_t *failed);

#endif

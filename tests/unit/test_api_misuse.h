/* The helpers of the API misuse tests (test_api_misuse.c,
** test_api_misuse_render.c): BAD (a failure status that is a value of the
** enum), IS (the exact status) and the curves they misuse. */
#ifndef CURVEFIG_TESTS_TEST_API_MISUSE_H
#define CURVEFIG_TESTS_TEST_API_MISUSE_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/curvefig.h"
#include "testutil.h"
#ifdef CF_TEST_RENDER
#include "curvefig/figure.h"
#endif

#ifndef CF_SOURCE_ROOT
#error "CF_SOURCE_ROOT (the source tree) must be defined by the build"
#endif

/* A status that is a failure and a value of the enum. */
static void
bad_(cf_status_t st, const char *call, int line)
{
    if (st == CF_STATUS_OK || (int)st < 0 || st >= CF_STATUS_LAST_)
        fail_msg("line %d: %s returned %d, expected a failure status", line,
                 call, (int)st);
}
#define BAD(call) bad_((call), #call, __LINE__)

/* The exact status. */
#define IS(status, call) assert_int_equal((call), (status))

static const double P4[] = { 0, 0, 1, 2, 2, -1, 3, 1 };
static const double W4[] = { 1, 2, 1, 1 };
static const double U7[] = { 0, 0, 0, 0.5, 1, 1, 1 };
static const double NANS[] = { NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN };

#endif

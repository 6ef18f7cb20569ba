/* The vector writers' numbers (render/backends/decimals.h) are printf's:
** cf__decimals against "%.Nf" with its trailing zeros, point and the sign
** of a zero dropped, string for string, on numbers chosen where the
** arithmetic could go wrong: exact ties of the rounding (k / 2^m), the
** decimals one step of the double either side of a half (x.xxx5 as
** strtod reads it and its neighbours), the bounds of the writers' ranges
** (1e9 for SVG, 16000 bp for PGF), zeros and tiny numbers of both signs,
** and a million numbers spread over magnitudes 1e-7 ... 1e9. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "backends/decimals.h"

/* printf's digits, as the writers made them before cf__decimals. */
static void
reference(char *buf, double v, int n)
{
    size_t len = (size_t)snprintf(buf, 64, "%.*f", n, v);
    while (len > 0 && buf[len - 1] == '0')
        buf[--len] = '\0';
    if (len > 0 && buf[len - 1] == '.')
        buf[--len] = '\0';
    if (strcmp(buf, "-0") == 0)
        strcpy(buf, "0");
}

static int failures;

static void
check(double v, int n)
{
    char want[64], got[64];
    size_t len;
    reference(want, v, n);
    len = cf__decimals(got, v, n);
    if (strcmp(want, got) != 0 || len != strlen(want)) {
        if (failures++ < 10)
            print_error("%.17g with %d decimals: %s, printf %s\n", v, n, got,
                        want);
    }
}

static void
check_both_signs(double v)
{
    int n;
    for (n = 1; n <= CF__DECIMALS_MAX; n++) {
        check(v, n);
        check(-v, n);
    }
}

static uint64_t state = 0x9e3779b97f4a7c15u;

static uint64_t
next(void)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
}

static void
test_printf_strings(void **unused)
{
    static const double fixed[] = { 0, 1e-300, 4e-324, 1e-7, 0.0004999,
                                    0.0005, 0.00050000000000000001, 0.5,
                                    0.9995, 0.99995, 1e9, 999999999.9995,
                                    16000, 15999.99995, 2.5, 0.0625,
                                    0.03125, 123456.789, 1e15, 3e25 };
    size_t i;
    int k, m, n;
    char text[64];
    (void)unused;
    failures = 0;
    for (i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        check_both_signs(fixed[i]);
    check(-0.0, 3);
    /* exact ties and their neighbours: k / 2^m */
    for (m = 1; m <= 12; m++)
        for (k = 1; k < 5000; k += 7) {
            double t = ldexp(k, -m);
            check_both_signs(t);
            check_both_signs(nextafter(t, 0));
            check_both_signs(nextafter(t, 1e300));
        }
    /* decimal halves as strtod reads them, and the doubles either side */
    for (n = 1; n <= CF__DECIMALS_MAX; n++)
        for (k = 0; k < 20000; k += 3) {
            double t;
            snprintf(text, sizeof text, "%d.%0*d5", k / 7, n, k % 1000);
            t = strtod(text, NULL);
            check(t, n);
            check(nextafter(t, 0), n);
            check(nextafter(t, 1e300), n);
        }
    /* a million numbers over magnitudes 1e-7 ... 1e9 */
    for (i = 0; i < 1000000; i++) {
        double mant = (double)(next() >> 11) * 0x1p-53;
        double e = (double)(next() % 17) - 7;
        check(mant * pow(10, e), 3);
        check(-mant * pow(10, e), 4);
    }
    assert_int_equal(failures, 0);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_printf_strings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

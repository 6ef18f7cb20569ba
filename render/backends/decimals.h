/*
** A number as the vector writers print it (render/backends/backend-svgw.c
** with 3 decimals, backend-pgf.c with 4): printf's "%.Nf", its trailing
** zeros and point dropped, "-0" as "0".
**
** printf prints the exact decimal value of the double rounded to N
** decimals, through multiple-precision arithmetic: some 1,500 instructions
** a number, 13 % of markova-2.17's SVG (1,197 numbers, 902 of them its
** glyphs' outlines).  Here the number is rounded by arithmetic where that
** is exact: v * 10^N is one rounding of the exact product, off by at most
** |v| * 10^N * 2^-53; where its fraction lies farther than 4 times that
** from one half, the exact product rounds to the same integer as the
** double does, and the digits are those of that integer.  Near a tie (and
** beyond 2^50) printf itself is asked, so every string is printf's.
*/
#ifndef CURVEFIG_RENDER_DECIMALS_H
#define CURVEFIG_RENDER_DECIMALS_H

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The largest number of decimals (10^N exact, the integer's digits fit). */
#define CF__DECIMALS_MAX 6

/* v (finite, |v| < 1e30) with n decimals (1 <= n <= CF__DECIMALS_MAX)
** into buf (at least 48 bytes) as described above; its length. */
static inline size_t
cf__decimals(char *buf, double v, int n)
{
    static const double p10[] = { 1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6 };
    double sc = v * p10[n], a = fabs(sc);
    size_t len;
    if (a < 0x1p50 && fabs(a - floor(a) - 0.5) > a * 0x1p-51) {
        long long r = llrint(a), ip, fp;
        char digits[24];
        int k = 0, d;
        ip = r / (long long)p10[n];
        fp = r % (long long)p10[n];
        len = 0;
        if (sc < 0 && r != 0)
            buf[len++] = '-';
        do {
            digits[k++] = (char)('0' + ip % 10);
            ip /= 10;
        } while (ip > 0);
        while (k > 0)
            buf[len++] = digits[--k];
        if (fp != 0) {
            buf[len++] = '.';
            for (d = n - 1; d >= 0; d--) {
                digits[d] = (char)('0' + fp % 10);
                fp /= 10;
            }
            for (d = n; digits[d - 1] == '0'; d--)
                ;
            memcpy(buf + len, digits, (size_t)d);
            len += (size_t)d;
        }
        buf[len] = '\0';
        return len;
    }
    len = (size_t)snprintf(buf, 48, "%.*f", n, v);
    while (len > 0 && buf[len - 1] == '0')
        buf[--len] = '\0';
    if (len > 0 && buf[len - 1] == '.')
        buf[--len] = '\0';
    if (strcmp(buf, "-0") == 0) {
        strcpy(buf, "0");
        len = 1;
    }
    return len;
}

#endif

/*
** The patch evaluator of the hidden-line core (cf__vpatch_eval,
** src/vis-patch.c) at 6,000 points, printed bit for bit: compiled
** natively and into WebAssembly with the module's flags (wasm SIMD, where
** a bicubic patch takes its own path in f64x2 pairs), the two outputs
** must be the same text (tests/wasm/meson.build, test wasm-vpatch-bits).
** Nets of degrees 3 x 3 (most), 2 x 3, 3 x 1 and triangles of degree 3;
** rational and not; (s, t) in and out of [0, 1]^2 (Newton's steps go
** out to -0.5 and 1.5); k = 0, 1 and 2.
*/
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "vis-private.h"

static uint64_t state = 0x9E3779B97F4A7C15u;

static double
uniform(double a, double b)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return a + (b - a) * (double)(state >> 11) / 9007199254740992.0;
}

int
main(void)
{
    static const int shapes[4][3] = {{3, 3, 0}, {2, 3, 0}, {3, 1, 0}, {3, 3, 1}};
    double net[16 * 4], out[18];
    for (int c = 0; c < 6000; c++) {
        const int *sh = shapes[c % 10 < 7 ? 0 : c % 10 - 6];
        cf__vpatch_t p;
        memset(&p, 0, sizeof p);
        p.m = sh[0];
        p.n = sh[1];
        p.tri = sh[2] != 0;
        p.v1 = p.u1 = 1.0;
        p.g = net;
        size_t np = cf__vpatch_count(&p);
        double scale = c % 3 == 0 ? 1.0 : c % 3 == 1 ? 1e-3 : 1e4;
        bool rational = c % 4 != 0;
        for (size_t i = 0; i < np; i++) {
            double w = rational ? uniform(0.25, 4.0) : 1.0;
            for (int e = 0; e < 3; e++)
                net[4 * i + e] = w * scale * uniform(-3.0, 3.0);
            net[4 * i + 3] = w;
        }
        double s = uniform(-0.5, 1.5), t = uniform(-0.5, 1.5);
        if (p.tri && s + t > 1.5)
            s = 1.5 - s;
        int k = c % 3, n = k == 0 ? 3 : k == 1 ? 9 : 18;
        bool ok = cf__vpatch_eval(&p, net, s, t, k, out);
        printf("%d %d%d%d %d", c, p.m, p.n, p.tri ? 1 : 0, ok ? 1 : 0);
        for (int i = 0; ok && i < n; i++) {
            uint64_t b;
            memcpy(&b, &out[i], sizeof b);
            printf(" %016" PRIx64, b);
        }
        printf("\n");
    }
    return 0;
}

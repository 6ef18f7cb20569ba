/* The GIF and APNG frame sinks (render/output/anim-gif.c, anim-apng.c)
** through their interface (anim-sink.h), checked by decoding the bytes
** with the independent decoders of tests/support/anim-decode.c: frame
** count, each frame's time, the loop, every pixel of every frame; the
** rule above 50 frames per second; bad input and failed allocations. */
#include "test_anim.h"

#define W 80
#define H 60

static void
free_frames(cairo_surface_t **f, size_t n)
{
    for (size_t k = 0; k < n; k++)
        cairo_surface_destroy(f[k]);
}

/* Every pixel of decoded frame i equals input frame s (un-premultiplied
** RGBA; transparent as 0 0 0 0). */
static void
assert_frame_equal(const tu_anim_t *a, unsigned i, cairo_surface_t *s)
{
    for (int y = 0; y < a->height; y++) {
        for (int x = 0; x < a->width; x++) {
            unsigned char want[4];
            const unsigned char *got = a->rgba[i]
                + 4 * ((size_t)y * (size_t)a->width + (size_t)x);
            frame_rgba(s, x, y, want);
            if (memcmp(want, got, 4) != 0)
                fail_msg("frame %u pixel (%d, %d): %d %d %d %d, want %d %d "
                         "%d %d", i, x, y, got[0], got[1], got[2], got[3],
                         want[0], want[1], want[2], want[3]);
        }
    }
}

/* Start (cs) of frame k of times sec[0..k-1], as the GIF rounds them:
** round(100 s_k), in long double. */
static long
start_cs(const double *sec, size_t k)
{
    long double s = 0;
    for (size_t i = 0; i < k; i++)
        s += sec[i];
    return lroundl(100 * s);
}

/* ---- GIF ---------------------------------------------------------------- */

/* A handful of colours: the palette is them exactly, every pixel of every
** frame decodes to its input; the delays of 1/30 s add up exactly; the
** frames after the first are the changed rectangles only. */
static void
test_gif_exact(void **state)
{
    (void)state;
    cairo_surface_t *f[6];
    double sec[6];
    cf__buf_t out = { 0 };
    tu_anim_t a;
    for (int k = 0; k < 6; k++) {
        f[k] = draw_frame(W, H, k, false, false,
                          k % 2 ? CAIRO_FORMAT_RGB24 : CAIRO_FORMAT_ARGB32);
        sec[k] = 1.0 / 30;
    }
    encode_frames(CF__ANIM_GIF, f, 6, sec, true, &out);
    if (tu_gif_decode(out.data, out.size, &a) != 0)
        fail_msg("%s", a.error);
    assert_int_equal(a.width, W);
    assert_int_equal(a.height, H);
    assert_int_equal(a.frames, 6);
    assert_int_equal(a.plays, 0);
    assert_true(a.colours <= 8);   /* 5 colours, the table a power of 2 */
    for (unsigned k = 0; k < 6; k++) {
        assert_int_equal(a.den[k], 100);
        assert_int_equal(a.num[k], start_cs(sec, k + 1) - start_cs(sec, k));
        assert_frame_equal(&a, k, f[k]);
        if (k > 0)   /* the circle and the curve move: a part changes */
            assert_true(a.box[k][2] * a.box[k][3] < W * H);
    }
    tu_anim_free(&a);
    cf__buf_free(&out);
    free_frames(f, 6);
}

/* Squared distance of two RGB colours. */
static long
dist2(const unsigned char *p, const unsigned char *q)
{
    long d = 0;
    for (int c = 0; c < 3; c++)
        d += ((long)p[c] - q[c]) * ((long)p[c] - q[c]);
    return d;
}

static int
cmp_u32(const void *a, const void *b)
{
    uint32_t p = *(const uint32_t *)a, q = *(const uint32_t *)b;
    return p < q ? -1 : p > q;
}

/* The distinct colours of n frames. */
static size_t
count_colours(cairo_surface_t **f, size_t n)
{
    int w = cairo_image_surface_get_width(f[0]);
    int h = cairo_image_surface_get_height(f[0]);
    size_t np = n * (size_t)w * (size_t)h, distinct = 0;
    uint32_t *all = malloc(np * sizeof *all);
    assert_non_null(all);
    for (size_t k = 0, i = 0; k < n; k++) {
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++, i++) {
                unsigned char c[4];
                frame_rgba(f[k], x, y, c);
                all[i] = (uint32_t)c[0] << 16 | (uint32_t)c[1] << 8 | c[2];
            }
        }
    }
    qsort(all, np, sizeof *all, cmp_u32);
    for (size_t i = 0; i < np; i++)
        distinct += i == 0 || all[i] != all[i - 1];
    free(all);
    return distinct;
}

/* Antialiased frames over a gradient (thousands of colours): each pixel
** is drawn in the palette colour nearest to its own (no dithering), the
** flat colours (page, fill, circle) exactly; the error stays small. */
static void
test_gif_quantised(void **state)
{
    (void)state;
    enum { N = 4, QW = 160, QH = 120 };
    cairo_surface_t *f[N];
    double sec[N], sum = 0, worst = 0;
    cf__buf_t out = { 0 };
    tu_anim_t a;
    for (int k = 0; k < N; k++) {
        cairo_t *cr;
        cairo_pattern_t *g;
        f[k] = draw_frame(QW, QH, k, true, false, CAIRO_FORMAT_RGB24);
        cr = cairo_create(f[k]);
        g = cairo_pattern_create_linear(0, 0, QW, 0);
        cairo_pattern_add_color_stop_rgb(g, 0, 1, 0.9, 0.2);
        cairo_pattern_add_color_stop_rgb(g, 1, 0.2, 0.9, 0.5);
        cairo_set_source(cr, g);
        cairo_rectangle(cr, 0, 0, QW, 0.12 * QH);
        cairo_fill(cr);
        cairo_pattern_destroy(g);
        /* a shaded patch: a vertical ramp over a horizontal one */
        g = cairo_pattern_create_linear(0, 0.15 * QH, 0, 0.5 * QH);
        cairo_pattern_add_color_stop_rgba(g, 0, 0.1, 0.1, 0.9, 0.9);
        cairo_pattern_add_color_stop_rgba(g, 1, 0.9, 0.5, 0.1, 0.2);
        cairo_set_source(cr, g);
        cairo_rectangle(cr, 0.6 * QW, 0.15 * QH, 0.35 * QW, 0.35 * QH);
        cairo_fill(cr);
        cairo_pattern_destroy(g);
        cairo_destroy(cr);
        cairo_surface_flush(f[k]);
        sec[k] = 0.1;
    }
    encode_frames(CF__ANIM_GIF, f, N, sec, true, &out);
    if (tu_gif_decode(out.data, out.size, &a) != 0)
        fail_msg("%s", a.error);
    assert_int_equal(a.frames, N);
    assert_int_equal(a.colours, 256);
    for (unsigned k = 0; k < N; k++) {
        static const double flat[3][2] = {
            { 0.01, 0.99 }, { 0.5, 0.7 }, { 0.0, 0.0 }
        };
        for (int y = 0; y < QH; y++) {
            for (int x = 0; x < QW; x++) {
                unsigned char want[4];
                const unsigned char *got = a.rgba[k]
                    + 4 * ((size_t)y * QW + (size_t)x);
                long best, d;
                frame_rgba(f[k], x, y, want);
                best = dist2(want, a.palette[0]);
                for (int i = 1; i < a.colours; i++) {
                    d = dist2(want, a.palette[i]);
                    best = d < best ? d : best;
                }
                d = dist2(want, got);
                if (d != best)
                    fail_msg("frame %u pixel (%d, %d): %d %d %d for %d %d "
                             "%d, %ld from it; the nearest colour is %ld",
                             k, x, y, got[0], got[1], got[2], want[0],
                             want[1], want[2], d, best);
                for (int c = 0; c < 3; c++) {
                    double e = fabs((double)got[c] - want[c]);
                    sum += e;
                    worst = fmax(worst, e);
                }
            }
        }
        /* the page (bottom left), the fill, the circle's centre */
        for (int i = 0; i < 3; i++) {
            int x = (int)(flat[i][0] * QW), y = (int)(flat[i][1] * QH);
            unsigned char want[4];
            if (i == 2) {
                x = (int)((0.2 + 0.6 * fmod(k * 0.1, 1.0)) * QW);
                y = (int)(0.4 * QH);
            }
            frame_rgba(f[k], x, y, want);
            assert_memory_equal(a.rgba[k] + 4 * ((size_t)y * QW + (size_t)x),
                                want, 3);
        }
    }
    /* the tolerance of quantised frames: a channel off by at most 16 of
    ** 255, by 0.5 on average (measured: 10 and 0.13) */
    print_message("GIF quantised: %zu colours; channel error %.0f at most, "
                  "%.3f mean\n", count_colours(f, N), worst,
                  sum / (3.0 * N * QW * QH));
    assert_true(count_colours(f, N) > 1000);
    assert_true(worst <= 16);
    assert_true(sum / (3.0 * N * QW * QH) <= 0.5);
    tu_anim_free(&a);
    cf__buf_free(&out);
    free_frames(f, N);
}

/* Frames of the given times: the frames shown are those the rule of
** anim-gif.c keeps (computed here in long double), each shown >= 2 cs and
** from round(100 s_k) cs, the delays adding up to the total exactly. */
static void
check_timing(const double *sec, size_t n, size_t want_shown)
{
    cairo_surface_t *f[64];
    cf__buf_t out = { 0 };
    tu_anim_t a;
    long end = start_cs(sec, n), t = 0, last = 0;
    size_t shown = 0, j = 0, distinct = 0;
    for (size_t k = 0; k < n; k++)
        f[k] = draw_frame(W, H, (int)k, false, false, CAIRO_FORMAT_RGB24);
    encode_frames(CF__ANIM_GIF, f, n, sec, false, &out);
    if (tu_gif_decode(out.data, out.size, &a) != 0)
        fail_msg("%s", a.error);
    assert_int_equal(a.plays, 1);   /* no loop: no NETSCAPE2.0 */
    for (size_t k = 0; k < n; k++) {
        long s = start_cs(sec, k);
        if (k > 0 && !(s - last >= 2 && end - s >= 2))
            continue;   /* dropped */
        last = s;
        shown++;
    }
    assert_int_equal(shown, want_shown);
    /* a delay over 65535 cs comes as repeats: merge them */
    for (unsigned i = 0; i < a.frames; i++) {
        assert_true(a.num[i] >= 2 && a.num[i] <= 65535);
        if (i > 0 && memcmp(a.rgba[i], a.rgba[i - 1],
                            (size_t)W * H * 4) == 0) {
            t += a.num[i];
            continue;
        }
        distinct++;
        /* the frame shown from t is the one that starts at t */
        while (j < n && start_cs(sec, j) < t)
            j++;
        assert_true(j < n);
        assert_int_equal(start_cs(sec, j), t);
        assert_frame_equal(&a, i, f[j]);
        t += a.num[i];
    }
    assert_int_equal(t, end);
    assert_int_equal(distinct, shown);
    tu_anim_free(&a);
    cf__buf_free(&out);
    free_frames(f, n);
}

static void
test_gif_timing(void **state)
{
    (void)state;
    double sec[64];
    static const double varied[] = { 0.5, 0.013, 0.25, 1.0 / 3, 0.004, 0.1,
                                     0.015, 0.02 };
    static const double long_frame[] = { 0.1, 700, 0.1 };
    for (int k = 0; k < 25; k++)
        sec[k] = 1.0 / 50;   /* 50 fps: every frame, 2 cs each */
    check_timing(sec, 25, 25);
    for (int k = 0; k < 30; k++)
        sec[k] = 1.0 / 60;   /* 60 fps over 0.5 s: 2 of every 3 frames
                                ** (starts 0 2 3 5 7 8 ... cs) */
    check_timing(sec, 30, 20);
    for (int k = 0; k < 40; k++)
        sec[k] = 1.0 / 30;
    check_timing(sec, 40, 40);
    /* starts 0 50 51 76 110 110 120 122, end 124: the 2nd, 5th dropped */
    check_timing(varied, 8, 6);
    check_timing(long_frame, 3, 3);
}

/* Transparent pages: alpha < 128 transparent, the rest its colour; whole
** frames, disposed of to the background. */
static void
test_gif_transparent(void **state)
{
    (void)state;
    cairo_surface_t *f[4];
    double sec[4] = { 0.2, 0.2, 0.2, 0.2 };
    cf__buf_t out = { 0 };
    tu_anim_t a;
    for (int k = 0; k < 4; k++)
        f[k] = draw_frame(W, H, k, false, true, CAIRO_FORMAT_ARGB32);
    encode_frames(CF__ANIM_GIF, f, 4, sec, true, &out);
    if (tu_gif_decode(out.data, out.size, &a) != 0)
        fail_msg("%s", a.error);
    assert_int_equal(a.frames, 4);
    for (unsigned k = 0; k < 4; k++) {
        assert_int_equal(a.num[k], 20);
        assert_int_equal(a.box[k][2], W);
        assert_int_equal(a.box[k][3], H);
        assert_frame_equal(&a, k, f[k]);
    }
    tu_anim_free(&a);
    cf__buf_free(&out);
    free_frames(f, 4);
}

/* ---- APNG --------------------------------------------------------------- */

/* Antialiased frames, opaque (RGB) and transparent (RGBA): every pixel
** exact; delays as exact fractions; changed rectangles. */
static void
test_apng(void **state)
{
    (void)state;
    static const double sec[5] = { 1.0 / 30, 1.0 / 30, 0.25, 1.0 / 3, 2.5 };
    static const unsigned num[5] = { 1, 1, 1, 1, 5 }, den[5] = { 30, 30, 4,
                                                                3, 2 };
    for (int transparent = 0; transparent < 2; transparent++) {
        cairo_surface_t *f[5];
        cf__buf_t out = { 0 };
        tu_anim_t a;
        for (int k = 0; k < 5; k++)
            f[k] = draw_frame(W, H, k, true, transparent,
                              transparent || k % 2 ? CAIRO_FORMAT_ARGB32
                                                   : CAIRO_FORMAT_RGB24);
        encode_frames(CF__ANIM_APNG, f, 5, sec, !transparent, &out);
        if (tu_apng_decode(out.data, out.size, &a) != 0)
            fail_msg("%s", a.error);
        assert_int_equal(a.frames, 5);
        assert_int_equal(a.plays, transparent ? 1 : 0);
        assert_int_equal(a.colours, transparent ? 4 : 3);
        for (unsigned k = 0; k < 5; k++) {
            assert_int_equal(a.num[k], num[k]);
            assert_int_equal(a.den[k], den[k]);
            assert_frame_equal(&a, k, f[k]);
            if (k > 0)
                assert_true(a.box[k][2] * a.box[k][3] < W * H);
        }
        tu_anim_free(&a);
        cf__buf_free(&out);
        free_frames(f, 5);
    }
}

/* Edge sizes: 1 x 1 frames of one colour each (a palette of 1 to 3
** colours, LZW's smallest code size), and frames that do not change (an
** empty change drawn as one unchanged pixel). */
static void
test_tiny(void **state)
{
    (void)state;
    static const double sec[3] = { 0.05, 0.05, 0.05 };
    for (int kind = CF__ANIM_GIF; kind <= CF__ANIM_APNG; kind++) {
        for (int same = 0; same < 2; same++) {
            cairo_surface_t *f[3];
            cf__buf_t out = { 0 };
            tu_anim_t a;
            for (int k = 0; k < 3; k++) {
                cairo_t *cr;
                f[k] = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
                cr = cairo_create(f[k]);
                cairo_set_source_rgb(cr, same ? 0.5 : k / 2.0, 0.25, 1);
                cairo_paint(cr);
                cairo_destroy(cr);
                cairo_surface_flush(f[k]);
            }
            encode_frames((cf__anim_kind_t)kind, f, 3, sec, true, &out);
            if ((kind == CF__ANIM_GIF ? tu_gif_decode(out.data, out.size, &a)
                                      : tu_apng_decode(out.data, out.size,
                                                       &a)) != 0)
                fail_msg("%s", a.error);
            assert_int_equal(a.frames, 3);
            for (unsigned k = 0; k < 3; k++) {
                assert_int_equal(a.box[k][2] * a.box[k][3], 1);
                assert_frame_equal(&a, k, f[k]);
            }
            if (kind == CF__ANIM_GIF)
                assert_int_equal(a.colours, same ? 2 : 4);
            tu_anim_free(&a);
            cf__buf_free(&out);
            free_frames(f, 3);
        }
    }
}

/* ---- bad input ---------------------------------------------------------- */

static void
test_bad_input(void **state)
{
    (void)state;
    for (int kind = CF__ANIM_GIF; kind <= CF__ANIM_APNG; kind++) {
        cf__anim_sink_t *s = NULL;
        cf_diag_t d;
        cf__buf_t out = { 0 };
        cairo_surface_t *ok = draw_frame(W, H, 0, false, false,
                                         CAIRO_FORMAT_RGB24);
        cairo_surface_t *big = draw_frame(W + 1, H, 0, false, false,
                                          CAIRO_FORMAT_RGB24);
        cairo_surface_t *a8 = cairo_image_surface_create(CAIRO_FORMAT_A8, W,
                                                         H);
        static const double bad_sec[] = { 0, -1, NAN, INFINITY, 4000 };
        cf__anim_kind_t k = (cf__anim_kind_t)kind;

        assert_int_equal(cf__anim_sink_open(k, 0, H, 30, true, NULL, &s, &d),
                         CF_STATUS_INVALID_ARG);
        assert_null(s);
        assert_non_null(strstr(d.msg, "0 x 60"));
        assert_int_equal(cf__anim_sink_open(k, W, H, 0, true, NULL, &s, &d),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf__anim_sink_open(k, W, H, 30, true, "x.gif", &s,
                                            &d), CF_STATUS_INVALID_ARG);
        /* no frames */
        assert_int_equal(cf__anim_sink_open(k, W, H, 30, true, NULL, &s, &d),
                         CF_STATUS_OK);
        assert_int_equal(cf__anim_sink_finish(s, &out, &d),
                         CF_STATUS_INVALID_ARG);
        assert_non_null(strstr(d.msg, "no frames"));
        /* each bad frame refused with its number; finish then fails and
        ** leaves the buffer empty */
        for (int b = 0; b < 7; b++) {
            cf_status_t st;
            assert_int_equal(cf__anim_sink_open(k, W, H, 30, true, NULL, &s,
                                                &d), CF_STATUS_OK);
            assert_int_equal(cf__anim_sink_add(s, ok, 0.1, &d),
                             CF_STATUS_OK);
            st = b < 5 ? cf__anim_sink_add(s, ok, bad_sec[b], &d)
               : cf__anim_sink_add(s, b == 5 ? big : a8, 0.1, &d);
            assert_int_equal(st, CF_STATUS_INVALID_ARG);
            assert_int_equal(d.index, 1);
            assert_non_null(strstr(d.msg, "frame 1"));
            if (b == 5)
                assert_non_null(strstr(d.msg, "81 x 60 pixels, but the "
                                              "animation's frames are "
                                              "80 x 60"));
            else if (b < 5)
                assert_non_null(strstr(d.msg, "must lie in (0, 3600] s"));
            assert_int_equal(cf__anim_sink_add(s, ok, 0.1, &d),
                             CF_STATUS_INVALID_ARG);
            assert_int_equal(cf__anim_sink_finish(s, &out, &d),
                             CF_STATUS_INVALID_ARG);
            assert_int_equal(out.size, 0);
        }
        /* abort after frames: nothing to see, nothing leaked */
        assert_int_equal(cf__anim_sink_open(k, W, H, 30, true, NULL, &s, &d),
                         CF_STATUS_OK);
        assert_int_equal(cf__anim_sink_add(s, ok, 0.1, &d), CF_STATUS_OK);
        cf__anim_sink_abort(s);
        cf__anim_sink_abort(NULL);
        cairo_surface_destroy(ok);
        cairo_surface_destroy(big);
        cairo_surface_destroy(a8);
    }
}

/* A translucent APNG frame after an opaque first frame is an error. */
static void
test_apng_mixed(void **state)
{
    (void)state;
    cf__anim_sink_t *s = NULL;
    cf_diag_t d;
    cairo_surface_t *page = draw_frame(W, H, 0, true, false,
                                       CAIRO_FORMAT_ARGB32);
    cairo_surface_t *glass = draw_frame(W, H, 1, true, true,
                                        CAIRO_FORMAT_ARGB32);
    assert_int_equal(cf__anim_sink_open(CF__ANIM_APNG, W, H, 30, true, NULL,
                                        &s, &d), CF_STATUS_OK);
    assert_int_equal(cf__anim_sink_add(s, page, 0.1, &d), CF_STATUS_OK);
    assert_int_equal(cf__anim_sink_add(s, glass, 0.1, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "frame 1 has translucent pixels"));
    cf__anim_sink_abort(s);
    cairo_surface_destroy(page);
    cairo_surface_destroy(glass);
}

/* The k-th allocation failing, for every k until none does: an error,
** the buffer left empty, nothing leaked. */
static void
test_out_of_memory(void **state)
{
    (void)state;
    cairo_surface_t *f[3];
    for (int k = 0; k < 3; k++)
        f[k] = draw_frame(W, H, k, true, false, CAIRO_FORMAT_ARGB32);
    for (int kind = CF__ANIM_GIF; kind <= CF__ANIM_APNG; kind++) {
        bool done = false;
        for (long n = 1; !done && n < 2000; n++) {
            cf__anim_sink_t *s = NULL;
            cf__buf_t out = { 0 };
            cf_diag_t d;
            cf_status_t st;
            tu_fail_alloc_after(n);
            st = cf__anim_sink_open((cf__anim_kind_t)kind, W, H, 30, true,
                                    NULL, &s, &d);
            for (int k = 0; k < 3 && st == CF_STATUS_OK; k++)
                st = cf__anim_sink_add(s, f[k], 0.1, &d);
            if (st == CF_STATUS_OK)
                st = cf__anim_sink_finish(s, &out, &d);
            else
                cf__anim_sink_abort(s);
            done = st == CF_STATUS_OK;
            if (!done) {
                assert_int_equal(st, CF_STATUS_NO_MEMORY);
                assert_int_equal(out.size, 0);
            }
            cf__buf_free(&out);
            assert_int_equal(tu_alloc_live(), 0);
            tu_fail_alloc_reset();
        }
        assert_true(done);
    }
    free_frames(f, 3);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gif_exact),
        cmocka_unit_test(test_gif_quantised),
        cmocka_unit_test(test_gif_timing),
        cmocka_unit_test(test_gif_transparent),
        cmocka_unit_test(test_apng),
        cmocka_unit_test(test_apng_mixed),
        cmocka_unit_test(test_tiny),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* The MP4 and WebM sinks (render/output/anim-ffmpeg.c): ffprobe reads
** back the codec, size, frame count and duration, ffmpeg decodes frames
** that are compared with their input; skipped only when ffmpeg is absent.
** Without ffmpeg on PATH, with an ffmpeg that fails, with a directory that
** cannot be written and when aborted: a clear error and no file left. */
#include <dirent.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "test_anim.h"
#include "anim-private.h"
#include "spawn.h"

#define VW 65   /* odd: the video is padded to 66 x 50 */
#define VH 49
#define FPS 10

static char dir[64], ffmpeg[512], ffprobe[512];

/* Whether an executable named name is on PATH; its path in buf. */
static bool
on_path(const char *name, char buf[512])
{
    const char *p = getenv("PATH");
    while (p != NULL && *p != '\0') {
        int n = (int)strcspn(p, ":");
        snprintf(buf, 512, "%.*s/%s", n > 400 ? 400 : n, n ? p : ".",
                 name);
        if (access(buf, X_OK) == 0)
            return true;
        p += n + (p[n] == ':');
    }
    buf[0] = '\0';
    return false;
}

/* The entries of the test's directory (not . and ..). */
static int
entries(void)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    assert_non_null(d);
    while ((e = readdir(d)) != NULL)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static int
setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/cf-anim-video-XXXXXX");
    on_path("ffmpeg", ffmpeg);
    on_path("ffprobe", ffprobe);
    return mkdtemp(dir) != NULL ? 0 : -1;
}

static int
teardown(void **state)
{
    (void)state;
    return rmdir(dir);
}

/* The times of the frames: 0.1 s each but frame 5, 0.3 s (three video
** frames at 10 fps); 1.2 s, 12 video frames in all. */
static const double sec[10] = { 0.1, 0.1, 0.1, 0.1, 0.1, 0.3, 0.1, 0.1,
                                0.1, 0.1 };

/* Video frame n decoded to rgb24 (66 x 50 pixels) into rgb. */
static void
decode_frame(const char *file, int n, unsigned char *rgb, size_t size)
{
    char select[64], raw[128];
    FILE *fp;
    snprintf(select, sizeof select, "select=eq(n\\,%d)", n);
    snprintf(raw, sizeof raw, "%s/frame.rgb", dir);
    const char *argv[] = { ffmpeg, "-v", "error", "-i", file, "-vf",
                           select, "-frames:v", "1", "-f", "rawvideo",
                           "-pix_fmt", "rgb24", "-y", raw, NULL };
    tu_spawn_t s = { .argv = argv };
    assert_int_equal(tu_exit_code(tu_spawn(&s)), 0);
    fp = fopen(raw, "rb");
    assert_non_null(fp);
    assert_int_equal(fread(rgb, 1, size, fp), size);
    assert_int_equal(fgetc(fp), EOF);
    fclose(fp);
    unlink(raw);
}

static void
check_video(cf__anim_kind_t kind, const char *codec)
{
    cairo_surface_t *f[10];
    cf__anim_sink_t *sink = NULL;
    cf_diag_t d;
    char file[128], out[1024], *p;
    double duration;
    size_t size = 66 * 50 * 3;
    unsigned char *rgb = malloc(size);
    /* video frame -> input frame: 0-4 -> 0-4, 5-7 -> 5, 8-11 -> 6-9 */
    static const int pick[3][2] = { { 2, 2 }, { 6, 5 }, { 9, 7 } };
    const char *argv[] = { ffprobe, "-v", "error", "-count_frames",
                           "-select_streams", "v:0", "-show_entries",
                           "stream=codec_name,width,height,pix_fmt,"
                           "nb_read_frames:format=duration",
                           "-of", "default=noprint_wrappers=1", file, NULL };
    tu_spawn_t s = { .argv = argv, .capture = out,
                     .capture_cap = sizeof out };
    if (!ffmpeg[0] || !ffprobe[0])
        skip();
    snprintf(file, sizeof file, "%s/v.%s", dir,
             kind == CF__ANIM_MP4 ? "mp4" : "webm");
    assert_int_equal(cf__anim_sink_open(kind, VW, VH, FPS, true, file,
                                        &sink, &d), CF_STATUS_OK);
    for (int k = 0; k < 10; k++) {
        f[k] = draw_frame(VW, VH, k, true, k == 3, CAIRO_FORMAT_ARGB32);
        if (cf__anim_sink_add(sink, f[k], sec[k], &d) != CF_STATUS_OK)
            fail_msg("%s", d.msg);
    }
    if (cf__anim_sink_finish(sink, NULL, &d) != CF_STATUS_OK)
        fail_msg("%s", d.msg);
    assert_int_equal(entries(), 1);   /* the video, no temporary file */

    assert_int_equal(tu_exit_code(tu_spawn(&s)), 0);
    assert_non_null(strstr(out, "codec_name="));
    assert_non_null(strstr(out, codec));
    assert_non_null(strstr(out, "width=66\n"));
    assert_non_null(strstr(out, "height=50\n"));
    assert_non_null(strstr(out, "pix_fmt=yuv420p\n"));
    assert_non_null(strstr(out, "nb_read_frames=12\n"));
    p = strstr(out, "duration=");
    assert_non_null(p);
    duration = strtod(p + 9, NULL);
    print_message("%s: %s", codec, out);
    tu_assert_close(duration, 1.2, 0, 1e-3);

    /* frames against their input over white, the padding white: a mean
    ** channel error of at most 6 of 255 (measured: 2 to 3; chroma at
    ** half resolution blurs the coloured edges of a frame this small) */
    for (int i = 0; i < 3; i++) {
        double sum = 0, pad = 0;
        decode_frame(file, pick[i][0], rgb, size);
        for (int y = 0; y < 50; y++) {
            for (int x = 0; x < 66; x++) {
                const unsigned char *got = rgb + 3 * (size_t)(y * 66 + x);
                unsigned char want[4] = { 255, 255, 255, 255 };
                if (x < VW && y < VH) {
                    frame_rgba(f[pick[i][1]], x, y, want);
                    for (int c = 0; c < 3; c++)   /* over white */
                        want[c] = (unsigned char)((want[c] * want[3]
                                                   + 255 * (255 - want[3])
                                                   + 127) / 255);
                }
                for (int c = 0; c < 3; c++) {
                    double e = fabs((double)got[c] - want[c]);
                    sum += e;
                    if (x == VW || y == VH)
                        pad = fmax(pad, e);
                }
            }
        }
        print_message("%s frame %d (input %d): mean error %.2f, padding "
                      "%.0f\n", codec, pick[i][0], pick[i][1],
                      sum / size, pad);
        assert_true(sum / size <= 6);
        assert_true(pad <= 48);
    }
    unlink(file);
    for (int k = 0; k < 10; k++)
        cairo_surface_destroy(f[k]);
    free(rgb);
}

static void
test_mp4(void **state)
{
    (void)state;
    check_video(CF__ANIM_MP4, "codec_name=h264");
}

static void
test_webm(void **state)
{
    (void)state;
    check_video(CF__ANIM_WEBM, "codec_name=vp9");
}

/* Without ffmpeg on PATH: an error naming the package, before a frame. */
static void
test_no_ffmpeg(void **state)
{
    (void)state;
    char *path = getenv("PATH") ? strdup(getenv("PATH")) : NULL, file[128];
    cf__anim_sink_t *sink = NULL;
    cf_diag_t d;
    snprintf(file, sizeof file, "%s/v.mp4", dir);
    setenv("PATH", "", 1);
    assert_int_equal(cf__anim_sink_open(CF__ANIM_MP4, VW, VH, FPS, true,
                                        file, &sink, &d), CF_STATUS_IO);
    if (path != NULL)
        setenv("PATH", path, 1);
    free(path);
    assert_null(sink);
    assert_string_equal(d.msg, "MP4: the ffmpeg program is not on PATH; "
                        "install it (the Debian package ffmpeg: apt-get "
                        "install ffmpeg)");
    assert_int_equal(entries(), 0);
}

/* A video sink opened with bin (a directory holding a fake ffmpeg) first
** on PATH. */
static cf_status_t
open_with(const char *bin, cf__anim_kind_t kind, const char *file,
          cf__anim_sink_t **sink, cf_diag_t *d)
{
    static char newpath[8192], path[8000];
    const char *env = getenv("PATH");
    size_t nb = strlen(bin), np = env != NULL ? strlen(env) : 0;
    cf_status_t st;
    if (nb + np + 2 > sizeof newpath || np + 1 > sizeof path)
        skip();
    memcpy(path, env != NULL ? env : "", np + 1);
    memcpy(newpath, bin, nb);
    newpath[nb] = ':';
    memcpy(newpath + nb + 1, path, np + 1);
    setenv("PATH", newpath, 1);
    st = cf__anim_sink_open(kind, VW, VH, FPS, true, file, sink, d);
    setenv("PATH", path, 1);
    return st;
}

/* A target directory that cannot be written: an error naming the file;
** an ffmpeg that fails: its message; aborted: ffmpeg stopped.  No file
** is left, an old target is untouched. */
static void
test_failures(void **state)
{
    (void)state;
    char file[256], fake[256], bin[128];
    cf__anim_sink_t *sink = NULL;
    cairo_surface_t *f = draw_frame(VW, VH, 0, true, false,
                                    CAIRO_FORMAT_RGB24);
    cf_diag_t d;
    FILE *fp;
    cf_status_t st;
    if (!ffmpeg[0])
        skip();
    snprintf(file, sizeof file, "%s/missing/v.mp4", dir);
    assert_int_equal(cf__anim_sink_open(CF__ANIM_MP4, VW, VH, FPS, true,
                                        file, &sink, &d), CF_STATUS_IO);
    assert_non_null(strstr(d.msg, "cannot create a temporary file for"));
    assert_non_null(strstr(d.msg, "missing/v.mp4"));
    if (geteuid() != 0) {   /* root writes a read-only directory too */
        snprintf(bin, sizeof bin, "%s/ro", dir);
        assert_int_equal(mkdir(bin, 0555), 0);
        snprintf(file, sizeof file, "%s/v.mp4", bin);
        assert_int_equal(cf__anim_sink_open(CF__ANIM_MP4, VW, VH, FPS,
                                            true, file, &sink, &d),
                         CF_STATUS_IO);
        assert_non_null(strstr(d.msg, "Permission denied"));
        assert_int_equal(rmdir(bin), 0);
    }

    /* aborted after two frames */
    snprintf(file, sizeof file, "%s/v.webm", dir);
    assert_int_equal(cf__anim_sink_open(CF__ANIM_WEBM, VW, VH, FPS, true,
                                        file, &sink, &d), CF_STATUS_OK);
    assert_int_equal(entries(), 1);   /* the temporary file */
    assert_int_equal(cf__anim_sink_add(sink, f, 0.5, &d), CF_STATUS_OK);
    assert_int_equal(cf__anim_sink_add(sink, f, 0.5, &d), CF_STATUS_OK);
    cf__anim_sink_abort(sink);
    assert_int_equal(entries(), 0);

    /* an ffmpeg that fails, over an old target */
    snprintf(bin, sizeof bin, "%s/bin", dir);
    snprintf(fake, sizeof fake, "%s/ffmpeg", bin);
    assert_int_equal(mkdir(bin, 0755), 0);
    fp = fopen(fake, "w");
    assert_non_null(fp);
    fputs("#!/bin/sh\necho 'some warning' >&2\n"
          "echo 'Unknown encoder libx264' >&2\nexit 3\n", fp);
    fclose(fp);
    assert_int_equal(chmod(fake, 0755), 0);
    snprintf(file, sizeof file, "%s/bin/v.mp4", dir);
    fp = fopen(file, "w");
    assert_non_null(fp);
    fputs("old", fp);
    fclose(fp);
    st = open_with(bin, CF__ANIM_MP4, file, &sink, &d);
    assert_int_equal(st, CF_STATUS_OK);
    for (int k = 0; k < 40 && st == CF_STATUS_OK; k++)
        st = cf__anim_sink_add(sink, f, 0.5, &d);
    if (st == CF_STATUS_OK)
        st = cf__anim_sink_finish(sink, NULL, &d);
    else
        cf__anim_sink_abort(sink);
    assert_int_equal(st, CF_STATUS_IO);
    assert_string_equal(d.msg, "MP4: ffmpeg failed (exit status 3): "
                        "Unknown encoder libx264");
    fp = fopen(file, "r");
    assert_non_null(fp);
    assert_non_null(fgets(fake, sizeof fake, fp));
    assert_string_equal(fake, "old");
    fclose(fp);
    unlink(file);
    snprintf(fake, sizeof fake, "%s/ffmpeg", bin);
    unlink(fake);
    assert_int_equal(rmdir(bin), 0);
    assert_int_equal(entries(), 0);
    cairo_surface_destroy(f);
}

/* A hung ffmpeg: one that reads its input but never exits, one that
** never reads it.  The video fails once the waits pass their limit (set
** small here: half a second and 10 ms a video frame), ffmpeg killed, no
** file left, and the waits took about that limit, not longer. */
static void
test_hung(void **state)
{
    (void)state;
    static const char *const scripts[] = {
        "#!/bin/sh\ncat > /dev/null\nexec sleep 60\n",
        "#!/bin/sh\nexec sleep 60\n",
    };
    char file[256], fake[256], bin[128];
    cairo_surface_t *f = draw_frame(VW, VH, 0, true, false,
                                    CAIRO_FORMAT_RGB24);
    if (!ffmpeg[0])
        skip();
    snprintf(bin, sizeof bin, "%s/hung", dir);
    snprintf(fake, sizeof fake, "%s/ffmpeg", bin);
    snprintf(file, sizeof file, "%s/v.mp4", dir);
    assert_int_equal(mkdir(bin, 0755), 0);
    for (int i = 0; i < 2; i++) {
        cf__anim_sink_t *sink = NULL;
        cf_diag_t d;
        cf_status_t st;
        struct timespec t0, t1;
        double took, limit;
        FILE *fp = fopen(fake, "w");
        assert_non_null(fp);
        fputs(scripts[i], fp);
        fclose(fp);
        assert_int_equal(chmod(fake, 0755), 0);
        assert_int_equal(open_with(bin, CF__ANIM_MP4, file, &sink, &d),
                         CF_STATUS_OK);
        cf__anim_ffmpeg_limits(sink, 0.5, 0.01);
        clock_gettime(CLOCK_MONOTONIC, &t0);
        /* 40 frames of 5 video frames, 2 MB: more than a socket holds */
        st = CF_STATUS_OK;
        for (int k = 0; k < 40 && st == CF_STATUS_OK; k++)
            st = cf__anim_sink_add(sink, f, 0.5, &d);
        if (st == CF_STATUS_OK)
            st = cf__anim_sink_finish(sink, NULL, &d);
        else
            cf__anim_sink_abort(sink);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        took = (double)(t1.tv_sec - t0.tv_sec)
               + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
        assert_int_equal(st, CF_STATUS_IO);
        assert_non_null(strstr(d.msg, "MP4: ffmpeg did not finish: "
                                      "stopped after waiting"));
        assert_non_null(strstr(d.msg, "(0.5 s and 0.01 s a video frame"));
        /* at most 0.5 s + 200 x 10 ms of waiting; sleep 60 would be 60 s
        ** (a second of slack for a loaded machine) */
        limit = 0.5 + 0.01 * 200;
        assert_true(took < limit + 1.0);
        unlink(fake);
        assert_int_equal(entries(), 1);   /* the directory bin */
    }
    assert_int_equal(rmdir(bin), 0);
    assert_int_equal(entries(), 0);
    cairo_surface_destroy(f);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mp4),
        cmocka_unit_test(test_webm),
        cmocka_unit_test(test_no_ffmpeg),
        cmocka_unit_test(test_failures),
        cmocka_unit_test(test_hung),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}

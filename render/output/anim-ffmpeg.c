/*
** MP4 (H.264) and WebM (VP9) videos of a sweep's frames through the ffmpeg
** program (the Debian package ffmpeg), found on PATH when the sink opens
** and started there, before any frame is rendered: posix_spawn, no shell.
**
** The frames go to ffmpeg's standard input as raw rgb24 (a socket, so
** that a write to an ffmpeg that has died fails with EPIPE instead of
** killing us with SIGPIPE): translucent pixels over white (videos have no
** alpha), padded with white to even sides (yuv420p halves the chroma
** planes; the picture is padded on the right and bottom, never scaled).
** The video runs at the sink's fps; frame k covers the video frames from
** round(fps s_k) to round(fps s_{k+1}) (s_k: the sum of the earlier
** frames' times), so a frame of any time is repeated as often as it
** lasts, the total time is exact to a video frame, and a frame shorter
** than a video frame may be skipped.
**
** ffmpeg writes into a new temporary file in the target's directory
** (cf__temp_open: O_EXCL | O_NOFOLLOW), passed as its descriptor 3 and
** named /dev/fd/3, renamed over the target at finish when ffmpeg exits 0.
** Its standard error goes to an unnamed temporary file; on failure its
** last line is the error's message.  abort kills ffmpeg and removes the
** temporary file.
**
** A hung ffmpeg does not hang us: the time we wait for it (for it to take
** a frame, then to exit) is at most CF__FFMPEG_WAIT seconds and
** CF__FFMPEG_WAIT_FRAME more for every video frame sent, in all; beyond
** that ffmpeg is killed and the video fails saying so.  Only waiting
** counts, not the rendering of the frames between.
*/
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "anim-private.h"
#include "output-private.h"

extern char **environ;

typedef struct ff_sink {
    cf__anim_sink_t base;
    pid_t pid;                  /* ffmpeg, or 0 when waited for */
    int in;                     /* our end of its standard input, or -1 */
    FILE *err;                  /* its standard error */
    char *path, *tmp;           /* the target and the temporary file */
    int w2, h2;                 /* the video's size: even */
    unsigned char *rgb;         /* the last frame, rgb24, w2 x h2 */
    long sent;                  /* video frames sent */
    double wait, wait_frame;    /* the limits of the waits (seconds) */
    double waited;              /* the time waited so far */
} ff_sink_t;

/* A monotonic clock in seconds. */
static double
now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The seconds ffmpeg may still keep us waiting (<= 0: none). */
static double
wait_left(const ff_sink_t *f)
{
    return f->wait + f->wait_frame * (double)f->sent - f->waited;
}

/* The path of an executable file named name in a directory of PATH, or
** NULL (none, or out of memory). */
static char *
find_program(const char *name)
{
    const char *p = getenv("PATH");
    size_t nlen = strlen(name);
    if (p == NULL)
        return NULL;
    while (*p != '\0') {
        const char *e = strchr(p, ':');
        size_t dlen = e != NULL ? (size_t)(e - p) : strlen(p);
        char *full = cf_malloc(dlen + nlen + 3);
        struct stat sb;
        if (full == NULL)
            return NULL;
        /* an empty entry is the working directory */
        memcpy(full, dlen > 0 ? p : ".", dlen > 0 ? dlen : 1);
        full[dlen > 0 ? dlen : 1] = '\0';
        strcat(full, "/");
        strcat(full, name);
        if (stat(full, &sb) == 0 && S_ISREG(sb.st_mode)
            && access(full, X_OK) == 0)
            return full;
        cf_free(full);
        p += dlen;
        if (*p == ':')
            p++;
    }
    return NULL;
}

/* The last non-empty line of ffmpeg's standard error (at most n - 1
** characters of it) in buf. */
static void
last_error_line(FILE *err, char *buf, size_t n)
{
    char line[512];
    buf[0] = '\0';
    if (err == NULL || fflush(err) != 0 || fseek(err, 0, SEEK_SET) != 0)
        return;
    while (fgets(line, sizeof line, err) != NULL) {
        size_t len = strcspn(line, "\r\n");
        line[len] = '\0';
        if (len > 0) {
            len = len < n - 1 ? len : n - 1;
            memcpy(buf, line, len);
            buf[len] = '\0';
        }
    }
}

/* ffmpeg stopped (killed unless it has exited), everything freed, the
** temporary file removed unless it was renamed. */
static void
ff_free(cf__anim_sink_t *sink)
{
    ff_sink_t *f = (ff_sink_t *)sink;
    if (f->in >= 0)
        close(f->in);
    if (f->pid > 0) {
        kill(f->pid, SIGKILL);
        while (waitpid(f->pid, NULL, 0) < 0 && errno == EINTR)
            ;
    }
    if (f->tmp != NULL)
        unlink(f->tmp);
    if (f->err != NULL)
        fclose(f->err);
    cf_free(f->tmp);
    cf_free(f->path);
    cf_free(f->rgb);
    cf_free(f);
}

/* n bytes to ffmpeg; 0, -1 (ffmpeg has gone) or -2 (it took nothing
** for longer than the waits have left). */
static int
send_all(ff_sink_t *f, const unsigned char *p, size_t n)
{
    while (n > 0) {
        ssize_t w = send(f->in, p, n, MSG_NOSIGNAL | MSG_DONTWAIT);
        if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            struct pollfd pf = { f->in, POLLOUT, 0 };
            double left = wait_left(f), t0 = now();
            int r;
            if (left <= 0)
                return -2;
            r = poll(&pf, 1, (int)ceil(fmin(left, 3600.0) * 1000.0));
            f->waited += now() - t0;
            if (r < 0 && errno != EINTR)
                return -1;
            continue;
        }
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

/* The error of an ffmpeg that kept us waiting too long, killed. */
static cf_status_t
timed_out(ff_sink_t *f, cf_diag_t *diag)
{
    double limit = f->wait + f->wait_frame * (double)f->sent;
    kill(f->pid, SIGKILL);
    while (waitpid(f->pid, NULL, 0) < 0 && errno == EINTR)
        ;
    f->pid = 0;
    return cf_diag_set(diag, CF_STATUS_IO, -1,
                       "%s: ffmpeg did not finish: stopped after waiting "
                       "%.0f s for it (%g s and %g s a video frame, %ld "
                       "frames)", f->base.name, limit, f->wait,
                       f->wait_frame, f->sent);
}

/* ffmpeg waited for: 0 when it exited with 0, else its error in diag. */
static cf_status_t
ff_wait(ff_sink_t *f, cf_diag_t *diag)
{
    char line[160];
    int status = 0;
    pid_t r;
    if (f->in >= 0)
        close(f->in);
    f->in = -1;
    for (;;) {
        double t0 = now();
        struct timespec nap = { 0, 20000000 };   /* 20 ms */
        r = waitpid(f->pid, &status, WNOHANG);
        if (r < 0 && errno == EINTR)
            continue;
        if (r != 0)
            break;
        if (wait_left(f) <= 0)
            return timed_out(f, diag);
        nanosleep(&nap, NULL);
        f->waited += now() - t0;
    }
    f->pid = 0;
    if (r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return CF_STATUS_OK;
    last_error_line(f->err, line, sizeof line);
    if (r > 0 && WIFSIGNALED(status))
        return cf_diag_set(diag, CF_STATUS_IO, -1,
                           "%s: ffmpeg killed by signal %d%s%s",
                           f->base.name, WTERMSIG(status),
                           line[0] ? ": " : "", line);
    return cf_diag_set(diag, CF_STATUS_IO, -1, "%s: ffmpeg failed (exit "
                       "status %d)%s%s", f->base.name,
                       r > 0 ? WEXITSTATUS(status) : -1,
                       line[0] ? ": " : "", line);
}

/* One frame as rgb24 over white, padded with white, into f->rgb. */
static void
to_rgb(ff_sink_t *f, const cf__anim_frame_t *fr)
{
    int w = f->base.width, h = f->base.height;
    memset(f->rgb, 255, (size_t)f->w2 * (size_t)f->h2 * 3);
    for (int y = 0; y < h; y++) {
        const unsigned char *src = fr->data + (size_t)y * (size_t)fr->stride;
        unsigned char *d = f->rgb + (size_t)y * (size_t)f->w2 * 3;
        for (int x = 0; x < w; x++, d += 3) {
            uint32_t p, white;
            memcpy(&p, src + 4 * (size_t)x, 4);
            /* premultiplied: c + (1 - a) * 255 over white */
            white = fr->alpha ? 255 - (p >> 24) : 0;
            d[0] = (unsigned char)(((p >> 16) & 0xff) + white);
            d[1] = (unsigned char)(((p >> 8) & 0xff) + white);
            d[2] = (unsigned char)((p & 0xff) + white);
        }
    }
}

static cf_status_t
ff_add(cf__anim_sink_t *sink, const cf__anim_frame_t *fr, cf_diag_t *diag)
{
    ff_sink_t *f = (ff_sink_t *)sink;
    long upto = lround(sink->fps * (fr->start + fr->seconds));
    size_t size = (size_t)f->w2 * (size_t)f->h2 * 3;
    to_rgb(f, fr);
    for (; f->sent < upto; f->sent++) {
        int r = send_all(f, f->rgb, size);
        if (r == -2)
            return timed_out(f, diag);
        if (r != 0) {
            cf_status_t st = ff_wait(f, diag);
            if (st == CF_STATUS_OK)   /* exited 0 before its input ended */
                st = cf_diag_set(diag, CF_STATUS_IO, (long)fr->index,
                                 "%s frame %u: ffmpeg stopped reading",
                                 sink->name, fr->index);
            return st;
        }
    }
    return CF_STATUS_OK;
}

static cf_status_t
ff_finish(cf__anim_sink_t *sink, cf__buf_t *out, cf_diag_t *diag)
{
    ff_sink_t *f = (ff_sink_t *)sink;
    cf_status_t st = CF_STATUS_OK;
    (void)out;
    /* an animation shorter than one video frame: its last frame once */
    if (f->sent == 0) {
        int r = send_all(f, f->rgb, (size_t)f->w2 * (size_t)f->h2 * 3);
        if (r == 0)
            f->sent = 1;
        else if (r == -2)
            st = timed_out(f, diag);
    }
    if (st == CF_STATUS_OK)
        st = ff_wait(f, diag);
    if (st == CF_STATUS_OK && rename(f->tmp, f->path) != 0)
        st = cf_diag_set(diag, CF_STATUS_IO, -1, "cannot write \"%s\": %s",
                         f->path, strerror(errno));
    if (st == CF_STATUS_OK) {
        cf_free(f->tmp);
        f->tmp = NULL;
    }
    ff_free(sink);
    return st;
}

static const cf__anim_ops_t ff_ops = { ff_add, ff_finish, ff_free };

void
cf__anim_ffmpeg_limits(cf__anim_sink_t *sink, double wait, double wait_frame)
{
    ff_sink_t *f = (ff_sink_t *)sink;
    if (sink->ops == &ff_ops) {
        f->wait = wait;
        f->wait_frame = wait_frame;
    }
}

/* ffmpeg started on the temporary file (fd), reading from sock, writing
** its errors to errfd; 0, or an errno value. */
static int
spawn(ff_sink_t *f, const char *prog, int sock, int errfd, int fd)
{
    char size[32], rate[32];
    const char *argv[40] = {
        "ffmpeg", "-hide_banner", "-nostats", "-loglevel", "error", "-y",
        "-f", "rawvideo", "-pix_fmt", "rgb24", "-video_size", size,
        "-framerate", rate, "-i", "pipe:0", "-pix_fmt", "yuv420p"
    };
    /* visually lossless for line art: x264 at quality 18, VP9 in constant
    ** quality mode (bit rate 0) at 30 */
    static const char *const h264[] = {
        "-c:v", "libx264", "-crf", "18", "-movflags", "+faststart",
        "-f", "mp4", "/dev/fd/3", NULL
    };
    static const char *const vp9[] = {
        "-c:v", "libvpx-vp9", "-crf", "30", "-b:v", "0", "-row-mt", "1",
        "-f", "webm", "/dev/fd/3", NULL
    };
    const char *const *tail = f->base.kind == CF__ANIM_MP4 ? h264 : vp9;
    posix_spawn_file_actions_t fa;
    int r, hi[3] = { -1, -1, -1 }, src[3] = { sock, errfd, fd };
    size_t na = 18;
    for (size_t i = 0; tail[i] != NULL; i++)
        argv[na++] = tail[i];
    snprintf(size, sizeof size, "%dx%d", f->w2, f->h2);
    snprintf(rate, sizeof rate, "%.17g", f->base.fps);
    /* the sources moved above 2 and 3 first: dup2 onto the descriptor
    ** itself would keep its close-on-exec flag */
    for (int i = 0; i < 3; i++) {
        hi[i] = fcntl(src[i], F_DUPFD_CLOEXEC, 10);
        if (hi[i] < 0) {
            r = errno;
            goto done;
        }
    }
    r = posix_spawn_file_actions_init(&fa);
    if (r != 0)
        goto done;
    if ((r = posix_spawn_file_actions_adddup2(&fa, hi[0], 0)) == 0
        && (r = posix_spawn_file_actions_addopen(&fa, 1, "/dev/null",
                                                 O_WRONLY, 0)) == 0
        && (r = posix_spawn_file_actions_adddup2(&fa, hi[1], 2)) == 0
        && (r = posix_spawn_file_actions_adddup2(&fa, hi[2], 3)) == 0)
        r = posix_spawn(&f->pid, prog, &fa, NULL, (char *const *)argv,
                        environ);
    posix_spawn_file_actions_destroy(&fa);
done:
    for (int i = 0; i < 3; i++)
        if (hi[i] >= 0)
            close(hi[i]);
    if (r != 0)
        f->pid = 0;
    return r;
}

cf_status_t
cf__anim_ffmpeg_open(cf__anim_kind_t kind, int width, int height, double fps,
                     const char *path, cf__anim_sink_t **sink,
                     cf_diag_t *diag)
{
    const char *name = kind == CF__ANIM_MP4 ? "MP4" : "WebM";
    char *prog = find_program("ffmpeg");
    ff_sink_t *f;
    int sv[2] = { -1, -1 }, fd = -1, r;
    cf_status_t st;

    if (prog == NULL)
        return cf_diag_set(diag, CF_STATUS_IO, -1,
                           "%s: the ffmpeg program is not on PATH; install "
                           "it (the Debian package ffmpeg: apt-get install "
                           "ffmpeg)", name);
    f = cf_calloc(1, sizeof *f);
    if (f == NULL) {
        cf_free(prog);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "%s: out of memory", name);
    }
    f->base.ops = &ff_ops;
    f->base.kind = kind;
    f->base.name = name;
    f->base.width = width;
    f->base.height = height;
    f->base.fps = fps;
    f->in = -1;
    f->wait = CF__FFMPEG_WAIT;
    f->wait_frame = CF__FFMPEG_WAIT_FRAME;
    f->w2 = width + (width & 1);
    f->h2 = height + (height & 1);
    f->rgb = cf_alloc_array((size_t)f->w2 * (size_t)f->h2, 3);
    f->path = cf_malloc(strlen(path) + 1);
    f->err = tmpfile();
    if (f->rgb == NULL || f->path == NULL) {
        st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1, "%s: out of memory",
                         name);
        goto fail;
    }
    strcpy(f->path, path);
    memset(f->rgb, 255, (size_t)f->w2 * (size_t)f->h2 * 3);
    if (f->err == NULL
        || socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
        st = cf_diag_set(diag, CF_STATUS_IO, -1,
                         "%s: cannot set up ffmpeg's input: %s", name,
                         strerror(errno));
        goto fail;
    }
    st = cf__temp_open(path, &fd, &f->tmp, diag);
    if (st != CF_STATUS_OK)
        goto fail;
    r = spawn(f, prog, sv[1], fileno(f->err), fd);
    if (r != 0) {
        st = cf_diag_set(diag, CF_STATUS_IO, -1, "%s: cannot start %s: %s",
                         name, prog, strerror(r));
        goto fail;
    }
    close(sv[1]);
    close(fd);
    cf_free(prog);
    f->in = sv[0];
    *sink = &f->base;
    return CF_STATUS_OK;
fail:
    if (sv[0] >= 0) {
        close(sv[0]);
        close(sv[1]);
    }
    if (fd >= 0)
        close(fd);
    cf_free(prog);
    ff_free(&f->base);
    return st;
}

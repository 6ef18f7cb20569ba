/*
** One run of `curvefig live` in a child process (live.h): the run of
** cf__live_run under the limits of render, in a process that the caller
** kills once the time limit has passed (or when it is told to stop), so
** that no script, and no loop in C that the instruction count cannot see,
** holds the server or `--once`.  A thread could not be stopped safely; a
** process can, and what it leaves behind (memory, the Lua state, half a
** figure) goes with it.
**
** The child writes to a pipe: one byte (the values were bad), the length
** of the error (4 bytes) and the error, then the JSON until the end.
*/
#define _GNU_SOURCE   /* close_range, where the C library has it */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "live.h"
#include "runlimits.h"

#define MAX_REPLY ((size_t)1 << 30)

static int
write_all(int fd, const void *data, size_t n)
{
    const char *p = data;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

static int
read_all(int fd, void *data, size_t n)
{
    char *p = data;
    while (n > 0) {
        ssize_t r = read(fd, p, n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            return -1;
        p += r;
        n -= (size_t)r;
    }
    return 0;
}

/* The child: set up as a run's process, then wait on req for the values
** (their length, 4 bytes, then the bytes; the end of req without them: the
** server needs no more runs, exit), run, write the answer into fd and
** _exit (no atexit handler of the parent's runs here).  A spare child
** (forked ahead of need) is this, forked before the values exist. */
_Noreturn static void
child(int fd, int req, pid_t parent, const char *script,
      const cf__tool_limits *l)
{
    sigset_t none;
    char error[1024];
    bool bad = false;
    char *json, *values;
    uint32_t elen, vlen;
    unsigned char flag;
    long max;
    /* the signals the server waits for are its own: here the defaults */
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
    signal(SIGALRM, SIG_DFL);
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    if (getppid() != parent)
        _exit(1);
    /* the server's sockets stay the server's: the pipes at 3 and 4 (moved
    ** out of the way first: either may be 3 or 4 now), the rest closed */
    fd = fcntl(fd, F_DUPFD, 10);
    req = fcntl(req, F_DUPFD, 10);
    if (fd < 0 || req < 0 || dup2(fd, 3) != 3 || dup2(req, 4) != 4)
        _exit(1);
    fd = 3;
    req = 4;
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 34)
    if (close_range(5, ~0u, 0) != 0)
#endif
    {
        max = sysconf(_SC_OPEN_MAX);
        for (long k = 5; k < (max > 0 && max < 65536 ? max : 65536); k++)
            close((int)k);
    }
    if (read_all(req, &vlen, 4) != 0 || vlen > CF__LIVE_MAX_VALUES)
        _exit(5);
    values = malloc((size_t)vlen + 1);
    if (values == NULL || read_all(req, values, vlen) != 0)
        _exit(5);
    values[vlen] = '\0';
    close(req);
    /* a second wall, should the parent be stopped: SIGALRM ends it */
    alarm((unsigned)ceil(l->timeout) + 2);
    error[0] = '\0';
    json = cf__live_run(script, &l->script, values, vlen, &bad, error,
                        sizeof error);
    if (json == NULL)
        _exit(3);
    flag = bad;
    elen = (uint32_t)strlen(error);
    if (write_all(fd, &flag, 1) != 0 || write_all(fd, &elen, 4) != 0
        || write_all(fd, error, elen) != 0
        || write_all(fd, json, strlen(json)) != 0)
        _exit(4);
    _exit(0);
}

double
cf__live_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Read fd to its end into *buf (malloc'd, NUL-terminated), until the
** deadline or until stop_fd is readable: 0 at the end, 1 at the
** deadline, 2 told to stop, -1 out of memory or too much. */
static int
read_reply(int fd, int stop_fd, double deadline, char **buf, size_t *len)
{
    size_t cap = 65536;
    *len = 0;
    *buf = malloc(cap);
    if (*buf == NULL)
        return -1;
    for (;;) {
        struct pollfd p[2] = { { fd, POLLIN, 0 }, { stop_fd, POLLIN, 0 } };
        double left = deadline - cf__live_clock();
        ssize_t n;
        int r;
        if (left <= 0)
            return 1;
        r = poll(p, stop_fd >= 0 ? 2 : 1, (int)ceil(left * 1000));
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0)
            return -1;
        if (stop_fd >= 0 && (p[1].revents & (POLLIN | POLLHUP)))
            return 2;
        if (r == 0 || !(p[0].revents & (POLLIN | POLLHUP | POLLERR)))
            continue;
        if (*len + 1 >= cap) {
            char *more = cap >= MAX_REPLY ? NULL : realloc(*buf, 2 * cap);
            if (more == NULL)
                return -1;
            *buf = more;
            cap *= 2;
        }
        n = read(fd, *buf + *len, cap - *len - 1);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            (*buf)[*len] = '\0';
            return n == 0 ? 0 : -1;
        }
        *len += (size_t)n;
    }
}

/* Fork a run's process into sp (waiting for its values); 0, or -1 with
** errno. */
static int
spawn(cf__live_spare *sp, const char *script, const cf__tool_limits *l)
{
    int reply[2], req[2];
    pid_t pid, parent = getpid();
    if (pipe(reply) != 0)
        return -1;
    if (pipe(req) != 0) {
        close(reply[0]);
        close(reply[1]);
        return -1;
    }
    fcntl(reply[0], F_SETFD, FD_CLOEXEC);
    fcntl(req[1], F_SETFD, FD_CLOEXEC);
    fflush(NULL);
    pid = fork();
    if (pid < 0) {
        int e = errno;
        close(reply[0]);
        close(reply[1]);
        close(req[0]);
        close(req[1]);
        errno = e;
        return -1;
    }
    if (pid == 0) {
        close(reply[0]);
        close(req[1]);
        child(reply[1], req[0], parent, script, l);
    }
    close(reply[1]);
    close(req[0]);
    sp->pid = pid;
    sp->reply = reply[0];
    sp->req = req[1];
    return 0;
}

void
cf__live_spare_init(cf__live_spare *sp)
{
    sp->pid = -1;
    sp->reply = sp->req = -1;
}

void
cf__live_spare_fork(cf__live_spare *sp, const char *script,
                    const cf__tool_limits *limits)
{
    if (sp->pid <= 0 && spawn(sp, script, limits) != 0)
        cf__live_spare_init(sp);
}

void
cf__live_spare_drop(cf__live_spare *sp)
{
    int status;
    if (sp->pid <= 0)
        return;
    kill(sp->pid, SIGKILL);
    while (waitpid(sp->pid, &status, 0) < 0 && errno == EINTR)
        ;
    close(sp->req);
    close(sp->reply);
    cf__live_spare_init(sp);
}

char *
cf__live_run_child(const char *script, const cf__tool_limits *limits,
                   const char *values, size_t len, int stop_fd,
                   cf__live_spare *spare, bool *bad_values, char *error,
                   size_t error_len)
{
    int status = 0, got = -1;
    char *reply = NULL, msg[1024];
    size_t n = 0;
    uint32_t vlen = (uint32_t)len;
    cf__live_spare run;
    void (*old_pipe)(int);
    *bad_values = false;
    if (error_len > 0)
        error[0] = '\0';
    if (len > CF__LIVE_MAX_VALUES)
        return cf__live_error_json(script, "the values are larger than "
                                   "1 MiB", error, error_len);
    /* the spare when there is one (and it still lives), else a fresh
    ** process */
    if (spare != NULL && spare->pid > 0
        && waitpid(spare->pid, &status, WNOHANG) == 0) {
        run = *spare;
    } else {
        if (spare != NULL && spare->pid > 0) {
            close(spare->req);
            close(spare->reply);
        }
        if (spawn(&run, script, limits) != 0) {
            snprintf(msg, sizeof msg, "cannot start a run of %s: %s",
                     script, strerror(errno));
            if (spare != NULL)
                cf__live_spare_init(spare);
            return cf__live_error_json(script, msg, error, error_len);
        }
    }
    if (spare != NULL)
        cf__live_spare_init(spare);
    /* a run that died before reading its values: EPIPE, not SIGPIPE */
    old_pipe = signal(SIGPIPE, SIG_IGN);
    if (write_all(run.req, &vlen, 4) == 0 && write_all(run.req, values, len)
        == 0)
        got = read_reply(run.reply, stop_fd,
                         cf__live_clock() + limits->timeout, &reply, &n);
    signal(SIGPIPE, old_pipe);
    close(run.req);
    close(run.reply);
    if (got != 0)
        kill(run.pid, SIGKILL);
    while (waitpid(run.pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (got == 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0 && n >= 5) {
        uint32_t elen;
        memcpy(&elen, reply + 1, 4);
        if (elen <= n - 5) {
            *bad_values = reply[0] != 0;
            if (error_len > 0)
                snprintf(error, error_len, "%.*s", (int)elen, reply + 5);
            memmove(reply, reply + 5 + elen, n - 5 - elen + 1);
            return reply;
        }
    }
    free(reply);
    if (got == 1)
        cf__tool_timeout_message(msg, sizeof msg, script, limits->timeout);
    else if (got == 2)
        snprintf(msg, sizeof msg, "%s: the run was stopped (the server is "
                 "stopping)", script);
    else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
        cf__tool_timeout_message(msg, sizeof msg, script, limits->timeout);
    else if (WIFSIGNALED(status))
        snprintf(msg, sizeof msg, "%s: the run of the script ended with "
                 "signal %d (a bug of curvefig: please report it with the "
                 "script)", script, WTERMSIG(status));
    else if (WIFEXITED(status) && WEXITSTATUS(status) == 3)
        snprintf(msg, sizeof msg, "%s: out of memory", script);
    else
        snprintf(msg, sizeof msg, "%s: the run of the script gave no answer "
                 "(status %d)", script, WIFEXITED(status)
                 ? WEXITSTATUS(status) : -1);
    return cf__live_error_json(script, msg, error, error_len);
}

/*
** The runs of `curvefig live` in a worker process (live.h): cf__live_run
** under the limits of render, in a process that the caller kills once the
** time limit has passed (or when it is told to stop), so that no script,
** and no loop in C that the instruction count cannot see, holds the
** server or `--once`.  A thread could not be stopped safely; a process
** can, and what it leaves behind (memory, the Lua state, half a figure)
** goes with it.  The worker serves runs until one of them goes wrong (or
** it served many, or grew): a fresh process costs more than a run (its
** start, its fonts, its exit), so a run in a worker that already ran one
** costs the run alone.
**
** The worker is this program started again (/proc/self/exe live-worker
** SCRIPT, posix_spawn), never a fork of the server: a fork of a process
** with threads (the server's polling thread, its runner and watcher)
** holds, in the child, every lock another thread held at that instant;
** under AddressSanitizer the child of such a fork hung, spinning in the
** allocator, one fork in 20 in a test of this (a thread allocating from
** new call stacks while another forks), and a page of `curvefig live`
** waited for its run for ever.  A program started afresh holds no lock.
**
** The protocol, on two pipes (the worker's 3 and 4): first the setup
** (setup_t: the parent's pid, whether to warm up before the first run,
** the limits), then the values go in as their length (4 bytes)
** and the bytes; the end of the pipe: no more runs, exit.  The answer
** comes out as a flag byte (1: the values were bad; 2: this worker
** retires and exits after the answer), the length of the error (4 bytes),
** the length of the JSON (4 bytes), the error and the JSON.
*/
#define _GNU_SOURCE   /* close_range, where the C library has it */
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
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "live.h"
#include "fdio.h"
#include "runlimits.h"
#include "tool.h"

#define MAX_REPLY ((size_t)1 << 30)
#define FLAG_BAD 1
#define FLAG_RETIRE 2
#define REPLY_FD 3        /* the worker's answers */
#define REQ_FD 4          /* the setup, then the values */

/* The first message on the values' pipe (memset first: no padding byte
** is left unset). */
typedef struct setup {
    pid_t parent;             /* the worker dies with it */
    int warm;                 /* a figure run before the first run */
    cf__tool_limits limits;
} setup_t;

/* The worker's resident memory in bytes (-1: unknown). */
static long
resident(void)
{
    long pages = -1, rss = -1;
    FILE *f = fopen("/proc/self/statm", "r");
    if (f == NULL)
        return -1;
    if (fscanf(f, "%ld %ld", &pages, &rss) != 2)
        rss = -1;
    fclose(f);
    return rss < 0 ? -1 : rss * sysconf(_SC_PAGESIZE);
}

/* One run's values from req into *values (malloc'd, NUL-terminated): 0,
** 1 at the end of req (no more runs), -1 on an error. */
static int
read_values(int req, char **values, uint32_t *vlen)
{
    ssize_t r;
    *values = NULL;
    do
        r = read(req, vlen, 4);
    while (r < 0 && errno == EINTR);
    if (r == 0)
        return 1;
    if (r < 0 || (r < 4 && cf__fd_read_all(req, (char *)vlen + r, 4 - (size_t)r)
                  != 0) || *vlen > CF__LIVE_MAX_VALUES)
        return -1;
    *values = malloc((size_t)*vlen + 1);
    if (*values == NULL || cf__fd_read_all(req, *values, *vlen) != 0)
        return -1;
    (*values)[*vlen] = '\0';
    return 0;
}

/* The worker (live-worker SCRIPT): set up as a run's process, then serve
** runs -- wait on REQ_FD for the values, run, write the answer into
** REPLY_FD -- until the values' pipe ends (exit 0) or a run makes it
** retire; _exit.  It is started before the values exist. */
int
cf__live_worker_main(int argc, char **argv)
{
    int fd = REPLY_FD, req = REQ_FD;
    sigset_t none;
    char error[1024];
    long max, base = -1;
    setup_t setup;
    const cf__tool_limits *l = &setup.limits;
    const char *script;
    unsigned most;
    if (argc != 2) {
        fprintf(stderr, "curvefig-live: live-worker is started by curvefig "
                "live, not by hand\n");
        return 2;
    }
    script = argv[1];
    if (cf__fd_read_all(req, &setup, sizeof setup) != 0) {
        fprintf(stderr, "curvefig-live: live-worker found no setup on its "
                "descriptor %d (it is started by curvefig live, not by "
                "hand)\n", REQ_FD);
        return 2;
    }
    if (!(l->timeout >= 1 && l->timeout <= 86400)) {
        fprintf(stderr, "curvefig-live: live-worker's setup has a time "
                "limit of %g s, not 1 to 86400 (it is started by curvefig "
                "live, not by hand)\n", l->timeout);
        return 2;
    }
    most = l->worker_runs > 0 ? l->worker_runs : CF__LIVE_WORKER_RUNS;
    /* the signals the server waits for are its own (blocked in its
    ** threads, a mask the start keeps): here the defaults */
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
    signal(SIGALRM, SIG_DFL);
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    if (getppid() != setup.parent)
        _exit(1);
    /* nothing of the server's but the two pipes (its descriptors are
    ** close-on-exec; this is the second wall) */
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 34)
    if (close_range(5, ~0u, 0) != 0)
#endif
    {
        max = sysconf(_SC_OPEN_MAX);
        for (long k = 5; k < (max > 0 && max < 65536 ? max : 65536); k++)
            close((int)k);
    }
    cf__tool_fonts_init();
    if (setup.warm)
        cf__live_warm();
    for (unsigned runs = 1;; runs++) {
        bool bad = false;
        char *json, *values;
        uint32_t elen, jlen, vlen;
        unsigned char flag;
        long rss;
        int got = read_values(req, &values, &vlen);
        if (got != 0)
            _exit(got > 0 ? 0 : 5);
        /* a second wall, should the parent be stopped: SIGALRM ends it */
        alarm((unsigned)ceil(l->timeout) + 2);
        error[0] = '\0';
        json = cf__live_run(script, &l->script, values, vlen, &bad, error,
                            sizeof error);
        alarm(0);
        free(values);
        if (json == NULL)
            _exit(3);
        rss = resident();
        if (base < 0)
            base = rss;
        flag = (unsigned char)(bad ? FLAG_BAD : 0);
        /* a run that failed may have left C memory behind (a longjmp
        ** out of the drawing): a fresh process for the next */
        if ((!bad && error[0] != '\0') || runs >= most
            || rss < 0 || rss - base > CF__LIVE_WORKER_GROWTH)
            flag |= FLAG_RETIRE;
        elen = (uint32_t)strlen(error);
        jlen = (uint32_t)strlen(json);
        if (cf__fd_write_all(fd, &flag, 1) != 0 || cf__fd_write_all(fd, &elen, 4) != 0
            || cf__fd_write_all(fd, &jlen, 4) != 0
            || cf__fd_write_all(fd, error, elen) != 0
            || cf__fd_write_all(fd, json, jlen) != 0)
            _exit(4);
        free(json);
        if (flag & FLAG_RETIRE)
            _exit(0);
    }
}

double
cf__live_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Read n bytes of fd into buf, until the deadline or until stop_fd is
** readable: 0 done, 1 at the deadline, 2 told to stop, -1 the end of fd
** or an error. */
static int
read_until(int fd, int stop_fd, double deadline, void *buf, size_t n)
{
    char *p = buf;
    while (n > 0) {
        struct pollfd q[2] = { { fd, POLLIN, 0 }, { stop_fd, POLLIN, 0 } };
        double left = deadline - cf__live_clock();
        ssize_t got;
        int r;
        if (left <= 0)
            return 1;
        r = poll(q, stop_fd >= 0 ? 2 : 1, (int)ceil(left * 1000));
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0)
            return -1;
        if (stop_fd >= 0 && (q[1].revents & (POLLIN | POLLHUP)))
            return 2;
        if (r == 0 || !(q[0].revents & (POLLIN | POLLHUP | POLLERR)))
            continue;
        got = read(fd, p, n);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return -1;
        p += got;
        n -= (size_t)got;
    }
    return 0;
}

/* Write n bytes to fd: 0, or -1 when its reader is gone (EPIPE, not
** SIGPIPE). */
static int
write_to(int fd, const void *buf, size_t n)
{
    void (*old_pipe)(int) = signal(SIGPIPE, SIG_IGN);
    int r = cf__fd_write_all(fd, buf, n);
    signal(SIGPIPE, old_pipe);
    return r;
}

/* Start a worker into w (waiting for its values), warmed up first when
** warm; 0, or -1 with errno. */
static int
spawn(cf__live_worker *w, const char *script, const cf__tool_limits *l,
      bool warm)
{
    int reply[2], req[2], up[2], err;
    posix_spawn_file_actions_t fa;
    char *argv[] = { (char *)"curvefig-live", (char *)"live-worker",
                     (char *)script, NULL };
    setup_t setup;
    pid_t pid;
    if (pipe2(reply, O_CLOEXEC) != 0)
        return -1;
    if (pipe2(req, O_CLOEXEC) != 0) {
        err = errno;
        close(reply[0]);
        close(reply[1]);
        errno = err;
        return -1;
    }
    /* the worker's ends copied above 4, so that the copies onto 3 and 4
    ** are real copies, without close-on-exec, whichever numbers the pipes
    ** have */
    up[0] = fcntl(reply[1], F_DUPFD_CLOEXEC, 10);
    up[1] = fcntl(req[0], F_DUPFD_CLOEXEC, 10);
    err = up[0] < 0 || up[1] < 0 ? errno : 0;
    if (err == 0)
        err = posix_spawn_file_actions_init(&fa);
    if (err == 0) {
        err = posix_spawn_file_actions_adddup2(&fa, up[0], REPLY_FD);
        if (err == 0)
            err = posix_spawn_file_actions_adddup2(&fa, up[1], REQ_FD);
        if (err == 0)
            err = posix_spawn(&pid, "/proc/self/exe", &fa, NULL, argv,
                              environ);
        posix_spawn_file_actions_destroy(&fa);
    }
    for (int k = 0; k < 2; k++)
        if (up[k] >= 0)
            close(up[k]);
    close(reply[1]);
    close(req[0]);
    if (err != 0) {
        close(reply[0]);
        close(req[1]);
        errno = err;
        return -1;
    }
    w->pid = pid;
    w->reply = reply[0];
    w->req = req[1];
    w->runs = 0;
    memset(&setup, 0, sizeof setup);
    setup.parent = getpid();
    setup.warm = warm;
    setup.limits = *l;
    /* a worker gone at once is seen at its first run (ready()) */
    (void)write_to(w->req, &setup, sizeof setup);
    return 0;
}

void
cf__live_worker_init(cf__live_worker *w)
{
    w->pid = -1;
    w->reply = w->req = -1;
    w->runs = 0;
}

void
cf__live_worker_start(cf__live_worker *w, const char *script,
                      const cf__tool_limits *limits)
{
    if (w->pid <= 0 && spawn(w, script, limits, true) != 0)
        cf__live_worker_init(w);
}

/* Kill the worker (SIGKILL when kill, else it is exiting by itself: the
** end of its values, or it retired), reap it: its status. */
static int
end_worker(cf__live_worker *w, bool kill_it)
{
    int status = 0;
    if (w->pid <= 0)
        return 0;
    close(w->req);
    close(w->reply);
    if (kill_it)
        kill(w->pid, SIGKILL);
    while (waitpid(w->pid, &status, 0) < 0 && errno == EINTR)
        ;
    cf__live_worker_init(w);
    return status;
}

void
cf__live_worker_drop(cf__live_worker *w)
{
    end_worker(w, true);
}

/* The worker alive and waiting: w's, or a fresh one; -1 with msg. */
static int
ready(cf__live_worker *w, const char *script, const cf__tool_limits *l,
      char *msg, size_t size)
{
    int status;
    if (w->pid > 0 && waitpid(w->pid, &status, WNOHANG) != 0) {
        /* gone while it waited (reaped now) */
        close(w->req);
        close(w->reply);
        cf__live_worker_init(w);
    }
    if (w->pid > 0)
        return 0;
    /* needed now: no warm-up (the run does the same work) */
    if (spawn(w, script, l, false) == 0)
        return 0;
    snprintf(msg, size, "cannot start a run of %s: %s", script,
             strerror(errno));
    cf__live_worker_init(w);
    return -1;
}

/* Send the values to w: 0, or -1 when it is gone (EPIPE, not SIGPIPE). */
static int
send_values(cf__live_worker *w, const char *values, uint32_t len)
{
    return write_to(w->req, &len, 4) == 0
           && write_to(w->req, values, len) == 0 ? 0 : -1;
}

/* The answer of the run under way in w: 0 and *json, *error (malloc'd)
** and the flag; else the code of read_until. */
static int
take_answer(cf__live_worker *w, int stop_fd, double deadline,
            unsigned char *flag, char **error, char **json)
{
    unsigned char head[9];
    uint32_t elen, jlen;
    int got = read_until(w->reply, stop_fd, deadline, head, 9);
    *error = *json = NULL;
    if (got != 0)
        return got;
    *flag = head[0];
    memcpy(&elen, head + 1, 4);
    memcpy(&jlen, head + 5, 4);
    if (elen > 65536 || jlen > MAX_REPLY)
        return -1;
    *error = malloc((size_t)elen + 1);
    *json = malloc((size_t)jlen + 1);
    if (*error == NULL || *json == NULL)
        return -3;
    got = read_until(w->reply, stop_fd, deadline, *error, elen);
    if (got == 0)
        got = read_until(w->reply, stop_fd, deadline, *json, jlen);
    if (got == 0) {
        (*error)[elen] = '\0';
        (*json)[jlen] = '\0';
    }
    return got;
}

char *
cf__live_run_child(const char *script, const cf__tool_limits *limits,
                   const char *values, size_t len, int stop_fd,
                   cf__live_worker *w, bool *bad_values, char *error,
                   size_t error_len)
{
    int status = 0, got = -1;
    char msg[1024], *json = NULL, *err = NULL;
    unsigned char flag = 0;
    cf__live_worker own;
    *bad_values = false;
    if (error_len > 0)
        error[0] = '\0';
    if (len > CF__LIVE_MAX_VALUES)
        return cf__live_error_json(script, "the values are larger than "
                                   "1 MiB", error, error_len);
    if (w == NULL) {
        cf__live_worker_init(&own);
        w = &own;
    }
    if (ready(w, script, limits, msg, sizeof msg) != 0)
        return cf__live_error_json(script, msg, error, error_len);
    /* a worker that died while it waited (between the check and the
    ** write): once more with a fresh one */
    if (send_values(w, values, (uint32_t)len) != 0) {
        end_worker(w, true);
        if (ready(w, script, limits, msg, sizeof msg) != 0)
            return cf__live_error_json(script, msg, error, error_len);
        if (send_values(w, values, (uint32_t)len) != 0)
            got = -2;
    }
    if (got != -2)
        got = take_answer(w, stop_fd, cf__live_clock() + limits->timeout,
                          &flag, &err, &json);
    w->runs++;
    /* a worker that retired or served --once ends by itself; one whose
    ** run went wrong is killed; else it waits for the next run */
    if (got != 0 || (flag & FLAG_RETIRE) != 0 || w == &own)
        status = end_worker(w, got != 0);
    if (got == 0) {
        *bad_values = (flag & FLAG_BAD) != 0;
        if (error_len > 0)
            snprintf(error, error_len, "%s", err);
        free(err);
        return json;
    }
    free(err);
    free(json);
    if (got == -3)
        snprintf(msg, sizeof msg, "%s: out of memory", script);
    else if (got == 1)
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

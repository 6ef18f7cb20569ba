/* Running a program from a test (tests/support/spawn.h). */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE     /* wait4 */
#include "spawn.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static void
redirect(const char *path, int fd)
{
    int f;
    if (path == NULL)
        return;
    f = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (f < 0 || dup2(f, fd) < 0)
        _exit(126);
    close(f);
}

static void
child(const tu_spawn_t *s, int pipe_w)
{
    const char *const *e;
    if (pipe_w >= 0 && dup2(pipe_w, STDOUT_FILENO) < 0)
        _exit(126);
    redirect(pipe_w >= 0 ? NULL : s->out, STDOUT_FILENO);
    redirect(s->err, STDERR_FILENO);
    for (e = s->env; e != NULL && *e != NULL; e++) {
        const char *eq = strchr(*e, '=');
        char name[256];
        if (eq == NULL) {
            unsetenv(*e);
            continue;
        }
        if ((size_t)(eq - *e) >= sizeof name)
            _exit(126);
        memcpy(name, *e, (size_t)(eq - *e));
        name[eq - *e] = '\0';
        setenv(name, eq + 1, 1);
    }
    if (s->dir != NULL && chdir(s->dir) != 0)
        _exit(126);
    execv(s->argv[0], (char *const *)s->argv);
    _exit(127);
}

int
tu_spawn(const tu_spawn_t *s)
{
    int fd[2] = { -1, -1 }, status;
    size_t len = 0;
    pid_t pid;
    fflush(NULL);
    if (s->capture != NULL && pipe(fd) != 0)
        return -1;
    pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (fd[0] >= 0)
            close(fd[0]);
        child(s, fd[1]);
    }
    if (s->capture != NULL) {
        close(fd[1]);
        for (;;) {
            char sink[512];
            ssize_t k = len + 1 < s->capture_cap
                            ? read(fd[0], s->capture + len,
                                   s->capture_cap - 1 - len)
                            : read(fd[0], sink, sizeof sink);
            if (k <= 0)
                break;
            if (len + 1 < s->capture_cap)
                len += (size_t)k;
        }
        if (s->capture_cap > 0)
            s->capture[len] = '\0';
        close(fd[0]);
    }
    if (s->kill) {
        struct timespec ts;
        ts.tv_sec = (time_t)s->kill_after;
        ts.tv_nsec = (long)((s->kill_after - (double)ts.tv_sec) * 1e9);
        nanosleep(&ts, NULL);
        kill(pid, SIGKILL);
    }
    {
        struct rusage ru;
        if (wait4(pid, &status, 0, &ru) != pid)
            return -1;
        if (s->rss_kib != NULL)
            *s->rss_kib = ru.ru_maxrss;
    }
    return status;
}

int
tu_exit_code(int status)
{
    if (status < 0)
        return -1;
    if (WIFSIGNALED(status))
        return 128 + WTERMSIG(status);
    return WEXITSTATUS(status);
}

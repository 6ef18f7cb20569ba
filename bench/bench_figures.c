/*
** bench-figures: the figure set through the tool, start-up included.
**
**   bench-figures TOOL OUTDIR NAME FIGDIR [PYTHON MPLSCRIPT]
**
** The scripts are the .lua files of FIGDIR (in name order).  NAME is a
** figure defined by one of them (found with `TOOL list`).
**
** 1. "all": every script rendered in all five formats (svg, pdf, png, ps,
**    eps), one `TOOL render` process per script, one after another; reports
**    the wall time, the CPU time of the children (user + system) and the
**    peak resident memory of the largest child.  Best of 3 runs.
** 2. "one": the figure NAME in svg + pdf + png (`--only NAME`), 21 runs,
**    the median wall time and the median CPU time (user + system of the
**    child) per run: the numbers to compare with matplotlib (about 0.2 s
**    for the same figure).  On a shared machine the CPU time is the
**    steadier of the two.
** 3. With PYTHON and MPLSCRIPT (a matplotlib script drawing the same
**    figure NAME in the same three formats, `PYTHON MPLSCRIPT OUTDIR`;
**    bench/matplotlib/): that script, once to warm matplotlib's font
**    cache, then 7 runs; the median wall and CPU time, and how many times
**    faster the tool is (the target: at least 20 times).
** One JSON line per measurement.  Exit status 1 when a render fails.
*/
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bench-time.h"

static double
tv_s(struct timeval tv)
{
    return (double)tv.tv_sec + 1e-6 * (double)tv.tv_usec;
}

/* Run argv, stdout into buf (may be NULL); the exit status or -1. */
static int
run(char *const argv[], char *buf, size_t cap)
{
    int fd[2], status;
    size_t len = 0;
    pid_t pid;
    if (pipe(fd) != 0)
        return -1;
    pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        dup2(fd[1], STDOUT_FILENO);
        close(fd[0]);
        close(fd[1]);
        execv(argv[0], argv);
        _exit(127);
    }
    close(fd[1]);
    for (;;) {
        char sink[4096];
        ssize_t n = buf != NULL && len + 1 < cap
                        ? read(fd[0], buf + len, cap - 1 - len)
                        : read(fd[0], sink, sizeof sink);
        if (n <= 0)
            break;
        if (buf != NULL && len + 1 < cap)
            len += (size_t)n;
    }
    if (buf != NULL)
        buf[len] = '\0';
    close(fd[0]);
    if (waitpid(pid, &status, 0) < 0)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static int
cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The paths of the .lua files in dir, sorted; *count of them. */
static char **
scripts_in(const char *dir, int *count)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **v = NULL;
    int n = 0;
    if (d == NULL)
        return NULL;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        char **nv;
        if (len < 5 || strcmp(e->d_name + len - 4, ".lua") != 0)
            continue;
        nv = realloc(v, (size_t)(n + 1) * sizeof *v);
        if (nv == NULL)
            break;
        v = nv;
        v[n] = malloc(strlen(dir) + len + 2);
        if (v[n] == NULL)
            break;
        sprintf(v[n], "%s/%s", dir, e->d_name);
        n++;
    }
    closedir(d);
    if (n > 0)
        qsort(v, (size_t)n, sizeof *v, cmp_str);
    *count = n;
    return v;
}

/* Run argv n times; the wall and the CPU (user + system) time of each run,
** sorted, into wall[] and cpu[].  0, or -1 when a run fails. */
static int
time_runs(char *const argv[], int n, double *wall, double *cpu)
{
    for (int r = 0; r < n; r++) {
        struct rusage before, after;
        double t0;
        getrusage(RUSAGE_CHILDREN, &before);
        t0 = now_s();
        if (run(argv, NULL, 0) != 0) {
            fprintf(stderr, "bench-figures: %s failed\n", argv[0]);
            return -1;
        }
        wall[r] = now_s() - t0;
        getrusage(RUSAGE_CHILDREN, &after);
        cpu[r] = tv_s(after.ru_utime) - tv_s(before.ru_utime) +
                 tv_s(after.ru_stime) - tv_s(before.ru_stime);
    }
    qsort(wall, (size_t)n, sizeof wall[0], cmp_double);
    qsort(cpu, (size_t)n, sizeof cpu[0], cmp_double);
    return 0;
}

int
main(int argc, char **argv)
{
    char *tool, *outdir, *name, **scripts, *one = NULL;
    double best_wall = 1e300, best_cpu = 1e300, runs[21], cpus[21];
    double mpl_wall[7], mpl_cpu[7];
    long peak_kb = 0;
    int nscripts;
    if (argc != 5 && argc != 7) {
        fprintf(stderr, "usage: bench-figures TOOL OUTDIR NAME FIGDIR "
                        "[PYTHON MPLSCRIPT]\n");
        return 2;
    }
    tool = argv[1];
    outdir = argv[2];
    name = argv[3];
    scripts = scripts_in(argv[4], &nscripts);
    if (scripts == NULL || nscripts == 0) {
        fprintf(stderr, "bench-figures: no scripts in %s\n", argv[4]);
        return 1;
    }
    for (int r = 0; r < 3; r++) {
        struct rusage before, after;
        double t0, wall, cpu;
        getrusage(RUSAGE_CHILDREN, &before);
        t0 = now_s();
        for (int i = 0; i < nscripts; i++) {
            char *a[] = { tool, "render", scripts[i], "-o", outdir, "-f",
                          "all", NULL };
            if (run(a, NULL, 0) != 0) {
                fprintf(stderr, "bench-figures: %s failed\n", scripts[i]);
                return 1;
            }
        }
        wall = now_s() - t0;
        getrusage(RUSAGE_CHILDREN, &after);
        cpu = tv_s(after.ru_utime) - tv_s(before.ru_utime) +
              tv_s(after.ru_stime) - tv_s(before.ru_stime);
        if (wall < best_wall)
            best_wall = wall;
        if (cpu < best_cpu)
            best_cpu = cpu;
        if (after.ru_maxrss > peak_kb)
            peak_kb = after.ru_maxrss;
    }
    for (int i = 0; i < nscripts && one == NULL; i++) {
        char *a[] = { tool, "list", scripts[i], NULL };
        char out[65536], *p;
        size_t n = strlen(name);
        if (run(a, out, sizeof out) != 0)
            continue;
        for (p = out; (p = strstr(p, name)) != NULL; p += n)
            if ((p == out || p[-1] == '\n') && p[n] == '\n')
                one = scripts[i];
    }
    if (one == NULL) {
        fprintf(stderr, "bench-figures: no script defines %s\n", name);
        return 1;
    }
    {
        char *a[] = { tool, "render", one, "-o", outdir, "-f",
                      "svg,pdf,png", "--only", name, NULL };
        if (time_runs(a, 21, runs, cpus) != 0)
            return 1;
    }
    if (argc == 7) {
        char *a[] = { argv[5], argv[6], outdir, NULL };
        if (run(a, NULL, 0) != 0) {   /* warm-up: matplotlib's font cache */
            fprintf(stderr, "bench-figures: %s %s failed\n", argv[5],
                    argv[6]);
            return 1;
        }
        if (time_runs(a, 7, mpl_wall, mpl_cpu) != 0)
            return 1;
    }
    for (int i = 0; i < nscripts; i++)
        free(scripts[i]);
    free(scripts);
    printf("{\"id\": \"figures-all\", \"scripts\": %d, \"formats\": 5, "
           "\"wall_s\": %.3f, \"cpu_s\": %.3f, \"peak_rss_mib\": %.1f}\n",
           nscripts, best_wall, best_cpu, (double)peak_kb / 1024.0);
    printf("{\"id\": \"figures-one\", \"figure\": \"%s\", \"formats\": "
           "\"svg,pdf,png\", \"median_wall_ms\": %.2f, "
           "\"median_cpu_ms\": %.2f, \"vs_matplotlib_0.2s\": %.1f}\n",
           name, 1e3 * runs[10], 1e3 * cpus[10], 0.2 / runs[10]);
    if (argc == 7)
        printf("{\"id\": \"figures-one-vs-matplotlib\", \"figure\": "
               "\"%s\", \"matplotlib_median_wall_ms\": %.1f, "
               "\"matplotlib_median_cpu_ms\": %.1f, \"speedup_wall\": "
               "%.1f, \"speedup_cpu\": %.1f, \"target\": 20, "
               "\"target_met\": %s}\n",
               name, 1e3 * mpl_wall[3], 1e3 * mpl_cpu[3],
               mpl_wall[3] / runs[10], mpl_cpu[3] / cpus[10],
               mpl_wall[3] / runs[10] >= 20 && mpl_cpu[3] / cpus[10] >= 20
                   ? "true" : "false");
    return 0;
}

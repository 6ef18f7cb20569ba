/*
** Output safety: a render killed with SIGKILL at any moment leaves, for
** every figure file, either the previous file or none, never a partial one.
**
** The test writes a large script (4 figures of 400 B-splines each, written
** as SVG, PDF and PNG: 12 files) in two versions, "old" (red) and "new"
** (blue), renders both completely for reference, and measures how long the
** new render takes (T).  Then, KILLS times, it starts the new render and
** kills it with SIGKILL after (i + 0.5) T / KILLS, so the kills are spread
** over the whole run: the even runs start from a directory holding the
** complete old files, the odd runs from an empty one.  Afterwards every
** figure file must be byte-identical to the old or the new reference
** (even runs) or to the new one or absent (odd runs).  Temporary files a
** kill leaves behind (it cannot clean up) are counted and reported; they
** never carry a figure's name.
**
** usage: kill-safety TOOL SCRATCH_DIR [KILLS]
*/
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "spawn.h"

#define FIGS 4
#define FORMATS 3
static const char *const ext[FORMATS] = { "svg", "pdf", "png" };

typedef struct blob {
    unsigned char *data;
    size_t size;
    int present;
} blob;

static void
die(const char *what)
{
    fprintf(stderr, "kill-safety: %s\n", what);
    exit(2);
}

static void
write_script(const char *path, const char *colour)
{
    FILE *f = fopen(path, "w");
    if (f == NULL)
        die("cannot write the script");
    fprintf(f,
        "for k = 1, %d do\n"
        "  local f = figure{ name = 'big-' .. k, width = '12cm', height = '9cm' }\n"
        "  for i = 1, 400 do\n"
        "    local pts = {}\n"
        "    for j = 0, 7 do\n"
        "      pts[#pts + 1] = { j + 0.01 * i, math.sin(i * 0.1 + j + k) + 0.002 * i }\n"
        "    end\n"
        "    f:curve(bspline{ degree = 3, points = pts }, { color = '%s', width = 0.3 })\n"
        "  end\n"
        "  f:polygon({ {0, 0}, {1, 1}, {2, 0} }, { labels = 'P_%%d' })\n"
        "end\n", FIGS, colour);
    fclose(f);
}

static blob
load(const char *path)
{
    blob b = { NULL, 0, 0 };
    FILE *f = fopen(path, "rb");
    long n;
    if (f == NULL)
        return b;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    b.data = malloc(n > 0 ? (size_t)n : 1);
    if (b.data == NULL)
        die("out of memory");
    b.size = fread(b.data, 1, (size_t)n, f);
    b.present = 1;
    fclose(f);
    return b;
}

static int
same(const blob *a, const blob *b)
{
    return a->present && b->present && a->size == b->size &&
           memcmp(a->data, b->data, a->size) == 0;
}

static double
now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Start `tool render script -o dir -f svg,pdf,png`; kill it after delay
** seconds (delay < 0: let it finish).  Returns the wait status. */
static int
render(const char *tool, const char *script, const char *dir, double delay)
{
    const char *argv[] = { tool, "render", script, "-o", dir, "-f",
                           "svg,pdf,png", "--timeout", "300", NULL };
    tu_spawn_t sp;
    int status;
    memset(&sp, 0, sizeof sp);
    sp.argv = argv;
    sp.kill = delay >= 0;
    sp.kill_after = delay;
    status = tu_spawn(&sp);
    if (status < 0)
        die("cannot run the tool");
    return status;
}

static void
run(const char *cmd)
{
    if (system(cmd) != 0)
        die(cmd);
}

int
main(int argc, char **argv)
{
    char old_lua[1024], new_lua[1024], cmd[8192], path[1200];
    char refold[1024], refnew[1024], out[1024];
    blob old_ref[FIGS * FORMATS], new_ref[FIGS * FORMATS];
    int kills = argc > 3 ? atoi(argv[3]) : 24, bad = 0, killed = 0;
    long temps = 0;
    int seen_old = 0, seen_new = 0, seen_absent = 0;
    double t0, T;

    if (argc < 3)
        die("usage: kill-safety TOOL SCRATCH_DIR [KILLS]");
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", argv[2],
             argv[2]);
    run(cmd);
    snprintf(old_lua, sizeof old_lua, "%s/old.lua", argv[2]);
    snprintf(new_lua, sizeof new_lua, "%s/big.lua", argv[2]);
    snprintf(refold, sizeof refold, "%s/ref-old", argv[2]);
    snprintf(refnew, sizeof refnew, "%s/ref-new", argv[2]);
    snprintf(out, sizeof out, "%s/out", argv[2]);
    write_script(old_lua, "red");
    write_script(new_lua, "blue");
    if (render(argv[1], old_lua, refold, -1) != 0)
        die("the reference render (old) failed");
    t0 = now();
    if (render(argv[1], new_lua, refnew, -1) != 0)
        die("the reference render (new) failed");
    T = now() - t0;
    for (int k = 0; k < FIGS; k++) {
        for (int e = 0; e < FORMATS; e++) {
            snprintf(path, sizeof path, "%s/big-%d.%s", refold, k + 1, ext[e]);
            old_ref[k * FORMATS + e] = load(path);
            snprintf(path, sizeof path, "%s/big-%d.%s", refnew, k + 1, ext[e]);
            new_ref[k * FORMATS + e] = load(path);
            if (!old_ref[k * FORMATS + e].present ||
                !new_ref[k * FORMATS + e].present ||
                same(&old_ref[k * FORMATS + e], &new_ref[k * FORMATS + e]))
                die("the reference renders are missing or equal");
        }
    }
    printf("reference render: %.2f s for %d files\n", T, FIGS * FORMATS);

    for (int i = 0; i < kills; i++) {
        double delay = T * (i + 0.5) / kills;
        int from_old = i % 2 == 0, st;
        DIR *d;
        struct dirent *en;
        if (from_old)
            snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s' && "
                     "cp '%s'/* '%s'", out, out, refold, out);
        else
            snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", out,
                     out);
        run(cmd);
        st = render(argv[1], new_lua, out, delay);
        if (WIFSIGNALED(st) && WTERMSIG(st) == SIGKILL)
            killed++;
        for (int k = 0; k < FIGS * FORMATS; k++) {
            blob b;
            snprintf(path, sizeof path, "%s/big-%d.%s", out, k / FORMATS + 1,
                     ext[k % FORMATS]);
            b = load(path);
            if (!b.present) {
                seen_absent++;
                if (from_old) {
                    printf("kill %d at %.3f s: %s vanished (the old file "
                           "must stay)\n", i, delay, path);
                    bad++;
                }
            } else if (same(&b, &new_ref[k])) {
                seen_new++;
            } else if (from_old && same(&b, &old_ref[k])) {
                seen_old++;
            } else {
                printf("kill %d at %.3f s: %s (%zu bytes) is neither the "
                       "previous file nor a complete render\n", i, delay,
                       path, b.size);
                bad++;
            }
            free(b.data);
        }
        d = opendir(out);
        while (d != NULL && (en = readdir(d)) != NULL) {
            if (en->d_name[0] == '.' && (en->d_name[1] == '\0' ||
                                         strcmp(en->d_name, "..") == 0))
                continue;
            if (strncmp(en->d_name, "big-", 4) == 0 &&
                strlen(en->d_name) == strlen("big-1.svg"))
                continue;
            temps++;
        }
        if (d != NULL)
            closedir(d);
    }
    for (int k = 0; k < FIGS * FORMATS; k++) {
        free(old_ref[k].data);
        free(new_ref[k].data);
    }
    printf("%d renders, %d killed by SIGKILL: %d files were the previous "
           "version, %d the complete new one, %d absent; %ld temporary files "
           "left by the kills; %d bad\n", kills, killed, seen_old, seen_new,
           seen_absent, temps, bad);
    return bad ? 1 : 0;
}

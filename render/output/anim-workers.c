/*
** The processes that draw an animation's rasters (anim.h, step 3 of
** anim.c): where the machine has more than one core, each child runs its
** frames' scripts itself and sends the pixels through a pipe; the frames
** are read in order, so at most one frame per child waits.
*/
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <sys/wait.h>
#include <unistd.h>

#include "anim-write-private.h"
#include "fdio.h"

/* The reply for one frame: status, then the message or the pixels. */
typedef struct reply {
    int32_t status;
    char msg[sizeof ((cf_diag_t *)0)->msg];
} reply_t;

/* A child: the rasters of frames w, w + n, ... through fd. */
static void
worker(anim_t *a, int w, int n, int fd)
{
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                                       a->wpx, a->hpx);
    size_t bytes = (size_t)cairo_image_surface_get_stride(surf)
                   * (size_t)a->hpx;
    cf__dl_t dl;
    cf__dl_init(&dl);
    for (unsigned k = (unsigned)w; k < a->src->frames; k += (unsigned)n) {
        cf_diag_t diag;
        reply_t rep;
        cf_diag_clear(&diag);
        memset(&rep, 0, sizeof rep);
        rep.status = cairo_surface_status(surf) == CAIRO_STATUS_SUCCESS
                     ? (int32_t)cf__anim_raster(a, k, surf, &dl, &diag)
                     : (int32_t)cf_diag_set(&diag, CF_STATUS_NO_MEMORY, -1,
                                            "out of memory for a frame");
        memcpy(rep.msg, diag.msg, sizeof rep.msg);
        if (cf__fd_write_all(fd, &rep, sizeof rep) != 0 || rep.status != 0
            || cf__fd_write_all(fd, cairo_image_surface_get_data(surf), bytes) != 0)
            break;
    }
    _exit(0);
}

void
cf__anim_workers_stop(workers_t *ws)
{
    for (int i = 0; i < ws->n; i++) {
        close(ws->fd[i]);
        kill(ws->pid[i], SIGTERM);
        while (waitpid(ws->pid[i], NULL, 0) < 0 && errno == EINTR)
            ;
    }
    ws->n = 0;
}

void
cf__anim_workers_start(anim_t *a, int n, workers_t *ws)
{
    ws->n = 0;
    fflush(NULL);
    for (int i = 0; i < n; i++) {
        int p[2];
        pid_t pid;
        if (pipe(p) != 0)
            break;
        pid = fork();
        if (pid < 0) {
            close(p[0]);
            close(p[1]);
            break;
        }
        if (pid == 0) {
            close(p[0]);
            for (int j = 0; j < ws->n; j++)
                close(ws->fd[j]);
            worker(a, i, n, p[1]);
        }
        close(p[1]);
        ws->pid[i] = pid;
        ws->fd[i] = p[0];
        ws->n++;
    }
    if (ws->n != n)
        cf__anim_workers_stop(ws);
}

int
cf__anim_worker_count(const anim_t *a)
{
    long cores = a->o->workers > 0 ? a->o->workers
                                   : sysconf(_SC_NPROCESSORS_ONLN);
    if (!(a->o->outputs & CF__ANIM_OUT_RASTER) || cores < 2
        || a->src->same_figure || a->src->frames < 4)
        return 1;
    return (int)(cores < CF__ANIM_MAX_WORKERS ? cores : CF__ANIM_MAX_WORKERS);
}

cf_status_t
cf__anim_workers_read(const workers_t *ws, unsigned k, cairo_surface_t *surf,
                      size_t bytes, cf_diag_t *diag)
{
    cf_status_t st = CF_STATUS_OK;
    reply_t rep;
    int fd = ws->fd[k % (unsigned)ws->n];
    cairo_surface_flush(surf);
    if (cf__fd_read_all(fd, &rep, sizeof rep) != 0
        || (rep.status == 0
            && cf__fd_read_all(fd, cairo_image_surface_get_data(surf), bytes) != 0))
        st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                         "the process drawing frame %u ended early", k + 1);
    else if (rep.status != 0)
        st = cf_diag_set(diag, (cf_status_t)rep.status, -1, "%s", rep.msg);
    cairo_surface_mark_dirty(surf);
    return st;
}

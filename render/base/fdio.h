/*
** Whole reads and writes of a file descriptor (pipes between a process
** and the children it forks: an animation's raster workers, the live
** server's runs), retried after a signal and after a short count.
*/
#ifndef CURVEFIG_RENDER_FDIO_H
#define CURVEFIG_RENDER_FDIO_H

#include <stddef.h>

/* The n bytes at p written to fd: 0, or -1 when a write failed (errno
** says why) or wrote nothing. */
int cf__fd_write_all(int fd, const void *p, size_t n);

/* n bytes read from fd into p: 0, or -1 when a read failed (errno says
** why) or the other end closed before n bytes came. */
int cf__fd_read_all(int fd, void *p, size_t n);

#endif

/*
** The web server of `curvefig live` (live.h), on libmicrohttpd: bound to
** 127.0.0.1, every path behind a random 128-bit token and a Host header
** naming this address, bodies capped.  One polling thread answers every
** connection (an idle connection costs a descriptor, not a thread, and is
** closed after HEADER_SECONDS without a complete request); a run and a
** long poll suspend their connection, and a thread of ours resumes it
** with the answer: the runner, which runs the script in a worker process
** (live-child.c) one run at a time and kills it at the time limit, and
** the watcher, which ends the long polls.
*/
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/random.h>
#include <time.h>
#include <unistd.h>

#include <microhttpd.h>

#include "live.h"
#include "web-text.h"   /* generated from render/web */

#define TOKEN_BYTES 16            /* 128 bits */
#define MAX_BODY CF__LIVE_MAX_VALUES /* values of a run */
#define WAIT_SECONDS 20
#define MAX_CONNECTIONS 512       /* within the default 1024 descriptors */
#define MAX_PER_IP 256
#define HEADER_SECONDS 5          /* idle time of a connection, before
                                  ** it has shown the token */
#define IDLE_SECONDS 60           /* ... and after */

/* What the browser may do with the page: run its own inline script and
** style, show data: images, talk to this server; nothing else (no frame
** may hold it, no form or base may point elsewhere). */
#define PAGE_CSP "default-src 'none'; script-src 'unsafe-inline'; " \
    "style-src 'unsafe-inline'; img-src data:; connect-src 'self'; "  \
    "base-uri 'none'; form-action 'none'; frame-ancestors 'none'"

enum { NEW, QUEUED, DONE };

/* One request: its body while it arrives; once suspended (a run, a long
** poll), its place in a queue; then the answer. */
typedef struct request {
    struct MHD_Connection *c;
    char *body;
    size_t len;
    bool too_large;
    int state;
    char since[64];               /* /wait: the version the page has */
    double deadline;              /* /wait: when to answer anyway */
    unsigned status;              /* the answer, once DONE */
    const char *type;
    char *answer;
    struct request *next;
} request_t;

typedef struct server {
    const char *script;
    const cf__tool_limits *limits;
    char token[2 * TOKEN_BYTES + 1];
    char *page;                   /* the HTML of the page */
    size_t page_len;
    _Atomic unsigned port;        /* for the Host header (0: not yet) */
    pthread_mutex_t lock;         /* the queues and stopping */
    pthread_cond_t work;          /* a run queued, or stopping */
    pthread_cond_t stop;          /* stopping (wakes the watcher) */
    request_t *runs, **runs_tail; /* suspended runs, in order */
    request_t *waits;             /* suspended long polls */
    bool stopping;
    int stop_pipe[2];             /* readable once stopping: ends a run */
} server_t;

static int
make_token(char out[2 * TOKEN_BYTES + 1])
{
    unsigned char b[TOKEN_BYTES];
    size_t got = 0;
    while (got < sizeof b) {
        ssize_t n = getrandom(b + got, sizeof b - got, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    if (got < sizeof b) {
        int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC);
        ssize_t n = fd >= 0 ? read(fd, b, sizeof b) : -1;
        if (fd >= 0)
            close(fd);
        if (n != (ssize_t)sizeof b)
            return -1;
    }
    for (size_t i = 0; i < sizeof b; i++)
        sprintf(out + 2 * i, "%02x", b[i]);
    return 0;
}

/* The lines of one embedded file. */
static size_t
lines_len(const char *const *lines)
{
    size_t n = 0;
    for (; *lines != NULL; lines++)
        n += strlen(*lines);
    return n;
}

static char *
add_lines(char *p, const char *const *lines)
{
    for (; *lines != NULL; lines++)
        p = stpcpy(p, *lines);
    return p;
}

/* The page: page.css, page.js (after its parts page-rotate.js and
** page-keys.js) and live.js inline, so that it is one request and needs
** nothing from the network. */
static int
make_page(server_t *sv)
{
    static const char head[] =
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
        "<title>curvefig live</title>\n"
        "<link rel=\"icon\" href=\"data:,\">\n<style>\n";
    static const char mid1[] = "</style>\n</head>\n<body>\n"
        "<div id=\"curvefig\"></div>\n<script>\n";
    static const char tail[] =
        "CurvefigPage(document.getElementById('curvefig'), "
        "new CurvefigLiveEngine());\n</script>\n</body></html>\n";
    size_t n = sizeof head + sizeof mid1 + sizeof tail + lines_len(web_css) +
               lines_len(web_page_rotate_js) + lines_len(web_page_keys_js) +
               lines_len(web_page_js) + lines_len(web_live_js);
    char *p = malloc(n);
    if (p == NULL)
        return -1;
    sv->page = p;
    p = stpcpy(p, head);
    p = add_lines(p, web_css);
    p = stpcpy(p, mid1);
    p = add_lines(p, web_page_rotate_js);
    p = add_lines(p, web_page_keys_js);
    p = add_lines(p, web_page_js);
    p = add_lines(p, web_live_js);
    p = stpcpy(p, tail);
    sv->page_len = (size_t)(p - sv->page);
    return 0;
}

static enum MHD_Result
reply(struct MHD_Connection *c, unsigned status, const char *type,
      const char *data, size_t len, bool copy)
{
    struct MHD_Response *r = MHD_create_response_from_buffer(
        len, (void *)data, copy ? MHD_RESPMEM_MUST_COPY
                                : MHD_RESPMEM_PERSISTENT);
    enum MHD_Result ret;
    if (r == NULL)
        return MHD_NO;
    MHD_add_response_header(r, "Content-Type", type);
    MHD_add_response_header(r, "Cache-Control", "no-store");
    MHD_add_response_header(r, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(r, "Referrer-Policy", "no-referrer");
    MHD_add_response_header(r, "Content-Security-Policy", PAGE_CSP);
    MHD_add_response_header(r, "X-Frame-Options", "DENY");
    ret = MHD_queue_response(c, status, r);
    MHD_destroy_response(r);
    return ret;
}

static enum MHD_Result
reply_text(struct MHD_Connection *c, unsigned status, const char *text)
{
    return reply(c, status, "text/plain; charset=utf-8", text, strlen(text),
                 false);
}

/* The token compared in time independent of where it differs. */
static bool
token_ok(const server_t *sv, const char *url, const char **rest)
{
    size_t n = strlen(sv->token);
    unsigned diff = 0;
    if (url[0] != '/' || strlen(url + 1) < n)
        return false;
    for (size_t i = 0; i < n; i++)
        diff |= (unsigned char)url[1 + i] ^ (unsigned char)sv->token[i];
    if (diff != 0 || (url[1 + n] != '/' && url[1 + n] != '\0'))
        return false;
    *rest = url + 1 + n;
    return true;
}

/* The Host header names this server: 127.0.0.1, localhost or [::1] with
** its port.  A page of another site that a DNS name pointed here
** (rebinding) sends its own name: refused, as a second wall beside the
** token. */
static bool
host_ok(server_t *sv, struct MHD_Connection *c)
{
    static const char *const names[] = { "127.0.0.1", "localhost", "[::1]" };
    const char *host = MHD_lookup_connection_value(c, MHD_HEADER_KIND,
                                                   MHD_HTTP_HEADER_HOST);
    unsigned port = sv->port;
    if (host == NULL || port == 0)
        return false;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        size_t n = strlen(names[i]);
        char want[16];
        if (strncasecmp(host, names[i], n) != 0 || host[n] != ':')
            continue;
        snprintf(want, sizeof want, "%u", port);
        if (strcmp(host + n + 1, want) == 0)
            return true;
    }
    return false;
}

/* Give a suspended request its answer (answer: malloc'd, or NULL for
** out of memory) and resume its connection; called with sv->lock held. */
static void
finish(request_t *rq, unsigned status, const char *type, char *answer)
{
    rq->status = answer != NULL ? status : MHD_HTTP_INTERNAL_SERVER_ERROR;
    rq->type = answer != NULL ? type : "text/plain; charset=utf-8";
    rq->answer = answer;
    rq->state = DONE;
    MHD_resume_connection(rq->c);
}

/* The runner: one run at a time, in the worker process, which is killed
** (and replaced) at the time limit or when the server stops. */
static void *
runner(void *arg)
{
    server_t *sv = arg;
    cf__live_worker worker;
    /* the worker, started (and warmed up) while the server waits: a run
    ** then costs the run, not the worker's start */
    cf__live_worker_init(&worker);
    cf__live_worker_start(&worker, sv->script, sv->limits);
    pthread_mutex_lock(&sv->lock);
    for (;;) {
        request_t *rq;
        bool bad;
        char *json;
        while (sv->runs == NULL && !sv->stopping)
            pthread_cond_wait(&sv->work, &sv->lock);
        if (sv->runs == NULL)
            break;
        rq = sv->runs;
        sv->runs = rq->next;
        if (sv->runs == NULL)
            sv->runs_tail = &sv->runs;
        if (sv->stopping) {
            finish(rq, MHD_HTTP_SERVICE_UNAVAILABLE, "text/plain; "
                   "charset=utf-8", strdup("the server is stopping\n"));
            continue;
        }
        pthread_mutex_unlock(&sv->lock);
        json = cf__live_run_child(sv->script, sv->limits,
                                  rq->body != NULL ? rq->body : "{}",
                                  rq->body != NULL ? rq->len : 2,
                                  sv->stop_pipe[0], &worker, &bad, NULL,
                                  0);
        /* a worker that was replaced: the next one started before the
        ** answer, so that it warms up while the page draws */
        cf__live_worker_start(&worker, sv->script, sv->limits);
        pthread_mutex_lock(&sv->lock);
        finish(rq, bad ? MHD_HTTP_BAD_REQUEST : MHD_HTTP_OK,
               "application/json", json);
    }
    pthread_mutex_unlock(&sv->lock);
    cf__live_worker_drop(&worker);
    return NULL;
}

/* The watcher: the long polls end when the script's version changes,
** after WAIT_SECONDS, or when the server stops. */
static void *
watcher(void *arg)
{
    server_t *sv = arg;
    pthread_mutex_lock(&sv->lock);
    while (!sv->stopping || sv->waits != NULL) {
        char version[64];
        double t = cf__live_clock();
        cf__live_version(sv->script, version);
        for (request_t **p = &sv->waits; *p != NULL;) {
            request_t *rq = *p;
            char body[100];
            if (!sv->stopping && strcmp(rq->since, version) == 0
                && t < rq->deadline) {
                p = &rq->next;
                continue;
            }
            *p = rq->next;
            snprintf(body, sizeof body, "{\"version\": \"%s\"}\n", version);
            finish(rq, MHD_HTTP_OK, "application/json", strdup(body));
        }
        if (!sv->stopping) {
            /* a tenth of a second, or until the server stops */
            struct timespec tick;
            clock_gettime(CLOCK_REALTIME, &tick);
            tick.tv_nsec += 100 * 1000 * 1000;
            if (tick.tv_nsec >= 1000 * 1000 * 1000) {
                tick.tv_sec++;
                tick.tv_nsec -= 1000 * 1000 * 1000;
            }
            pthread_cond_timedwait(&sv->stop, &sv->lock, &tick);
        }
    }
    pthread_mutex_unlock(&sv->lock);
    return NULL;
}

/* Suspend rq's connection and queue it: a run (the runner answers) or a
** long poll (the watcher does). */
static enum MHD_Result
suspend(server_t *sv, request_t *rq, bool run)
{
    rq->state = QUEUED;
    MHD_suspend_connection(rq->c);
    pthread_mutex_lock(&sv->lock);
    if (sv->stopping) {
        finish(rq, MHD_HTTP_SERVICE_UNAVAILABLE,
               "text/plain; charset=utf-8",
               strdup("the server is stopping\n"));
    } else if (run) {
        rq->next = NULL;
        *sv->runs_tail = rq;
        sv->runs_tail = &rq->next;
        pthread_cond_signal(&sv->work);
    } else {
        rq->next = sv->waits;
        sv->waits = rq;
    }
    pthread_mutex_unlock(&sv->lock);
    return MHD_YES;
}

static enum MHD_Result
do_wait(struct MHD_Connection *c, server_t *sv, request_t *rq)
{
    const char *since = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND,
                                                    "v");
    char now_v[64], body[100];
    cf__live_version(sv->script, now_v);
    if (since != NULL && strcmp(now_v, since) == 0) {
        snprintf(rq->since, sizeof rq->since, "%s", since);
        rq->deadline = cf__live_clock() + WAIT_SECONDS;
        return suspend(sv, rq, false);
    }
    snprintf(body, sizeof body, "{\"version\": \"%s\"}\n", now_v);
    return reply(c, MHD_HTTP_OK, "application/json", body, strlen(body), true);
}

static enum MHD_Result
handle(void *cls, struct MHD_Connection *c, const char *url,
       const char *method, const char *version, const char *upload,
       size_t *upload_size, void **con_cls)
{
    server_t *sv = cls;
    request_t *rq = *con_cls;
    const char *rest = NULL;
    bool post = strcmp(method, MHD_HTTP_METHOD_POST) == 0;
    (void)version;
    if (rq == NULL) {
        /* the first call: the headers only */
        if (!host_ok(sv, c))
            return reply_text(c, MHD_HTTP_FORBIDDEN, "forbidden: the Host "
                              "of the request is not this server's\n");
        if (!token_ok(sv, url, &rest))
            return reply_text(c, MHD_HTTP_FORBIDDEN, "forbidden: this "
                              "address needs the token curvefig live "
                              "printed\n");
        if (!post && strcmp(method, MHD_HTTP_METHOD_GET) != 0 &&
            strcmp(method, MHD_HTTP_METHOD_HEAD) != 0)
            return reply_text(c, MHD_HTTP_METHOD_NOT_ALLOWED,
                              "method not allowed\n");
        rq = calloc(1, sizeof *rq);
        if (rq == NULL)
            return MHD_NO;
        rq->c = c;
        *con_cls = rq;
        /* the client knows the token: the longer idle time */
        MHD_set_connection_option(c, MHD_CONNECTION_OPTION_TIMEOUT,
                                  (unsigned)IDLE_SECONDS);
        return MHD_YES;
    }
    if (rq->state == DONE) {
        /* resumed: the answer of the runner or the watcher */
        if (rq->answer == NULL)
            return reply_text(c, rq->status, "out of memory\n");
        return reply(c, rq->status, rq->type, rq->answer,
                     strlen(rq->answer), true);
    }
    if (post && *upload_size > 0) {
        if (!rq->too_large && rq->len + *upload_size <= MAX_BODY) {
            char *p = realloc(rq->body, rq->len + *upload_size + 1);
            if (p == NULL) {
                rq->too_large = true;
            } else {
                rq->body = p;
                memcpy(p + rq->len, upload, *upload_size);
                rq->len += *upload_size;
                p[rq->len] = '\0';
            }
        } else {
            rq->too_large = true;
        }
        *upload_size = 0;
        return MHD_YES;
    }
    token_ok(sv, url, &rest);
    if (strcmp(rest, "") == 0 || strcmp(rest, "/") == 0) {
        if (post)
            return reply_text(c, MHD_HTTP_METHOD_NOT_ALLOWED,
                              "the page takes GET\n");
        return reply(c, MHD_HTTP_OK, "text/html; charset=utf-8", sv->page,
                     sv->page_len, false);
    }
    if (strcmp(rest, "/run") == 0) {
        if (!post)
            return reply_text(c, MHD_HTTP_METHOD_NOT_ALLOWED,
                              "run takes POST with the values as JSON\n");
        if (rq->too_large)
            return reply_text(c, MHD_HTTP_CONTENT_TOO_LARGE,
                              "the values exceed 1 MiB\n");
        return suspend(sv, rq, true);
    }
    if (strcmp(rest, "/wait") == 0 && !post)
        return do_wait(c, sv, rq);
    return reply_text(c, MHD_HTTP_NOT_FOUND, "not found\n");
}

static void
done(void *cls, struct MHD_Connection *c, void **con_cls,
     enum MHD_RequestTerminationCode code)
{
    request_t *rq = *con_cls;
    (void)cls;
    (void)c;
    (void)code;
    if (rq != NULL) {
        free(rq->body);
        free(rq->answer);
        free(rq);
        *con_cls = NULL;
    }
}

int
cf__live_serve(const char *script, const cf__tool_limits *limits,
               unsigned port)
{
    server_t sv;
    struct sockaddr_in addr;
    struct MHD_Daemon *d;
    const union MHD_DaemonInfo *info;
    pthread_t run_thread, wait_thread;
    sigset_t stop;
    int sig;
    memset(&sv, 0, sizeof sv);
    sv.script = script;
    sv.limits = limits;
    sv.runs_tail = &sv.runs;
    if (make_token(sv.token) != 0 || make_page(&sv) != 0) {
        fprintf(stderr, "curvefig live: cannot make a random token\n");
        return 1;
    }
    if (pipe(sv.stop_pipe) != 0) {
        fprintf(stderr, "curvefig live: cannot make a pipe: %s\n",
                strerror(errno));
        free(sv.page);
        return 1;
    }
    fcntl(sv.stop_pipe[0], F_SETFD, FD_CLOEXEC);
    fcntl(sv.stop_pipe[1], F_SETFD, FD_CLOEXEC);
    pthread_mutex_init(&sv.lock, NULL);
    pthread_cond_init(&sv.work, NULL);
    pthread_cond_init(&sv.stop, NULL);
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    /* the server's threads inherit the mask: the signals come here */
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop, NULL);
    signal(SIGPIPE, SIG_IGN);
    d = MHD_start_daemon(MHD_USE_AUTO_INTERNAL_THREAD |
                             MHD_ALLOW_SUSPEND_RESUME,
                         (uint16_t)port, NULL, NULL, handle, &sv,
                         MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr,
                         MHD_OPTION_CONNECTION_LIMIT,
                         (unsigned)MAX_CONNECTIONS,
                         MHD_OPTION_PER_IP_CONNECTION_LIMIT,
                         (unsigned)MAX_PER_IP,
                         MHD_OPTION_CONNECTION_TIMEOUT,
                         (unsigned)HEADER_SECONDS,
                         MHD_OPTION_NOTIFY_COMPLETED, done, NULL,
                         MHD_OPTION_END);
    if (d == NULL) {
        fprintf(stderr, "curvefig live: cannot listen on 127.0.0.1:%u%s\n",
                port, port ? " (in use?)" : "");
        free(sv.page);
        return 1;
    }
    info = MHD_get_daemon_info(d, MHD_DAEMON_INFO_BIND_PORT);
    sv.port = info != NULL ? info->port : port;
    pthread_create(&run_thread, NULL, runner, &sv);
    pthread_create(&wait_thread, NULL, watcher, &sv);
    printf("curvefig live: %s\nopen http://127.0.0.1:%u/%s/\n(Ctrl-C "
           "stops the server)\n", script, sv.port, sv.token);
    fflush(stdout);
    while (sigwait(&stop, &sig) != 0)
        ;
    /* a run under way is killed, every suspended request answered */
    pthread_mutex_lock(&sv.lock);
    sv.stopping = true;
    pthread_cond_broadcast(&sv.work);
    pthread_cond_broadcast(&sv.stop);
    pthread_mutex_unlock(&sv.lock);
    if (write(sv.stop_pipe[1], "x", 1) != 1)
        fprintf(stderr, "curvefig live: cannot stop the run\n");
    pthread_join(run_thread, NULL);
    pthread_join(wait_thread, NULL);
    MHD_stop_daemon(d);
    pthread_cond_destroy(&sv.work);
    pthread_cond_destroy(&sv.stop);
    pthread_mutex_destroy(&sv.lock);
    close(sv.stop_pipe[0]);
    close(sv.stop_pipe[1]);
    free(sv.page);
    return 0;
}

/*
** The web server of `curvefig live` (live.h), on libmicrohttpd: bound to
** 127.0.0.1, every path behind a random 128-bit token, one script run at
** a time, bodies capped, a thread per connection (so that the long poll
** of /wait holds one thread, not the server).
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
#include <sys/random.h>
#include <time.h>
#include <unistd.h>

#include <microhttpd.h>

#include "live.h"
#include "web-text.h"   /* generated from render/web */

#define TOKEN_BYTES 16            /* 128 bits */
#define MAX_BODY ((size_t)1 << 20) /* values of a run */
#define WAIT_SECONDS 20
#define MAX_CONNECTIONS 64

typedef struct server {
    const char *script;
    const cf_script_limits_t *limits;
    char token[2 * TOKEN_BYTES + 1];
    char *page;                   /* the HTML of the page */
    size_t page_len;
    pthread_mutex_t run_lock;     /* one script run at a time */
    _Atomic bool stopping;        /* the long polls end */
} server_t;

/* The state of one request while its body arrives. */
typedef struct request {
    char *body;
    size_t len;
    bool too_large;
} request_t;

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

/* The page: page.css, page.js and live.js inline, so that it is one
** request and needs nothing from the network. */
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
               lines_len(web_page_js) + lines_len(web_live_js);
    char *p = malloc(n);
    if (p == NULL)
        return -1;
    sv->page = p;
    p = stpcpy(p, head);
    p = add_lines(p, web_css);
    p = stpcpy(p, mid1);
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

static enum MHD_Result
do_run(struct MHD_Connection *c, server_t *sv, const request_t *rq)
{
    bool bad;
    char *json;
    enum MHD_Result ret;
    pthread_mutex_lock(&sv->run_lock);
    json = cf__live_run(sv->script, sv->limits, rq->body != NULL ? rq->body
                                                                 : "{}",
                        rq->body != NULL ? rq->len : 2, &bad, NULL, 0);
    pthread_mutex_unlock(&sv->run_lock);
    if (json == NULL)
        return reply_text(c, MHD_HTTP_INTERNAL_SERVER_ERROR, "out of memory\n");
    ret = reply(c, bad ? MHD_HTTP_BAD_REQUEST : MHD_HTTP_OK,
                "application/json", json, strlen(json), true);
    free(json);
    return ret;
}

static enum MHD_Result
do_wait(struct MHD_Connection *c, server_t *sv)
{
    const char *since = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND,
                                                    "v");
    char now[64], body[100];
    struct timespec tick = { 0, 100 * 1000 * 1000 };
    cf__live_version(sv->script, now);
    for (int i = 0; since != NULL && strcmp(now, since) == 0 &&
                    i < WAIT_SECONDS * 10 && !sv->stopping; i++) {
        nanosleep(&tick, NULL);
        cf__live_version(sv->script, now);
    }
    snprintf(body, sizeof body, "{\"version\": \"%s\"}\n", now);
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
        *con_cls = rq;
        return MHD_YES;
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
        return do_run(c, sv, rq);
    }
    if (strcmp(rest, "/wait") == 0 && !post)
        return do_wait(c, sv);
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
        free(rq);
        *con_cls = NULL;
    }
}

int
cf__live_serve(const char *script, const cf_script_limits_t *limits,
               unsigned port)
{
    server_t sv;
    struct sockaddr_in addr;
    struct MHD_Daemon *d;
    const union MHD_DaemonInfo *info;
    sigset_t stop;
    int sig;
    memset(&sv, 0, sizeof sv);
    sv.script = script;
    sv.limits = limits;
    if (make_token(sv.token) != 0 || make_page(&sv) != 0) {
        fprintf(stderr, "curvefig live: cannot make a random token\n");
        return 1;
    }
    pthread_mutex_init(&sv.run_lock, NULL);
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
    d = MHD_start_daemon(MHD_USE_THREAD_PER_CONNECTION |
                             MHD_USE_INTERNAL_POLLING_THREAD,
                         (uint16_t)port, NULL, NULL, handle, &sv,
                         MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr,
                         MHD_OPTION_CONNECTION_LIMIT,
                         (unsigned)MAX_CONNECTIONS,
                         MHD_OPTION_CONNECTION_TIMEOUT,
                         (unsigned)(WAIT_SECONDS + 10),
                         MHD_OPTION_NOTIFY_COMPLETED, done, NULL,
                         MHD_OPTION_END);
    if (d == NULL) {
        fprintf(stderr, "curvefig live: cannot listen on 127.0.0.1:%u%s\n",
                port, port ? " (in use?)" : "");
        free(sv.page);
        return 1;
    }
    info = MHD_get_daemon_info(d, MHD_DAEMON_INFO_BIND_PORT);
    printf("curvefig live: %s\nopen http://127.0.0.1:%u/%s/\n(Ctrl-C "
           "stops the server)\n", script, info != NULL ? info->port : port,
           sv.token);
    fflush(stdout);
    while (sigwait(&stop, &sig) != 0)
        ;
    sv.stopping = true;
    MHD_stop_daemon(d);
    pthread_mutex_destroy(&sv.run_lock);
    free(sv.page);
    return 0;
}

/*
 * live_http.c — the server of `ev3sim run --live` (live.h) through GNU
 * libmicrohttpd (the program only: the test configurations, ARM ones
 * included, link the library without it, and Debian has no 32-bit build).
 *
 * It listens on 127.0.0.1 only, on a socket of its own (so a busy port is
 * told as bind(2) tells it), and answers from libmicrohttpd's thread:
 *   GET  /             the page (ev3sim/live_page.html, in the program)
 *   GET  /api/world    the app, the robot and its mat
 *   GET  /api/status?since=N   the state now and the plot's rows after row N
 *   POST /api/cmd?do=CMD[&arg=ARG]   press/release a button, pace, pause,
 *                      resume, step, stop (ev3sim_live_command)
 */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <errno.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>
#include "ev3sim/live.h"

/* The page, linked into the program as it is (a NUL after it). */
__asm__(".section .rodata\n"
	".balign 16\n"
	"ev3sim_live_page:\n"
	".incbin \"ev3sim/live_page.html\"\n"
	".byte 0\n"
	".previous\n");
extern const char ev3sim_live_page[];

#define STATUS_MAX (512U * 1024U)   /* an answer: the display (6 KB) and up to 1000 rows */
#define WORLD_MAX  1024U

static struct MHD_Daemon *daemon_;

/* Queues a response of status with body (taken: freed by libmicrohttpd). */
static enum MHD_Result answer(struct MHD_Connection *c, unsigned status, const char *type, char *body, size_t n)
{
	struct MHD_Response *r = MHD_create_response_from_buffer(n, body, MHD_RESPMEM_MUST_FREE);
	enum MHD_Result ret;

	if (r == NULL) {
		free(body);
		return MHD_NO;
	}
	MHD_add_response_header(r, "Content-Type", type);
	MHD_add_response_header(r, "Cache-Control", "no-store");
	ret = MHD_queue_response(c, status, r);
	MHD_destroy_response(r);
	return ret;
}

/* Answers with a copy of text. */
static enum MHD_Result answer_text(struct MHD_Connection *c, unsigned status, const char *type, const char *text)
{
	size_t n = strlen(text);
	char *body = malloc(n + 1);

	if (body == NULL)
		return MHD_NO;
	memcpy(body, text, n + 1);
	return answer(c, status, type, body, n);
}

/* One request (libmicrohttpd's access handler). */
static enum MHD_Result handle(void *cls, struct MHD_Connection *c, const char *url, const char *method,
			      const char *version, const char *upload_data, size_t *upload_size, void **req)
{
	static int seen;
	char *body;
	size_t n;

	(void)cls;
	(void)version;
	(void)upload_data;
	if (*req == NULL) {
		/* the headers only: a POST's body, if any, comes in later calls */
		*req = &seen;
		if (strcmp(method, "POST") == 0)
			return MHD_YES;
	}
	if (*upload_size != 0) {
		*upload_size = 0;       /* no command has a body: read and dropped */
		return MHD_YES;
	}
	if (strcmp(method, "GET") == 0 && strcmp(url, "/") == 0)
		return answer_text(c, MHD_HTTP_OK, "text/html; charset=utf-8", ev3sim_live_page);
	if (strcmp(method, "GET") == 0 && strcmp(url, "/api/world") == 0) {
		if ((body = malloc(WORLD_MAX)) == NULL)
			return MHD_NO;
		n = ev3sim_live_world_json(body, WORLD_MAX);
		return answer(c, MHD_HTTP_OK, "application/json", body, n);
	}
	if (strcmp(method, "GET") == 0 && strcmp(url, "/api/status") == 0) {
		const char *since = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "since");

		if ((body = malloc(STATUS_MAX)) == NULL)
			return MHD_NO;
		n = ev3sim_live_status_json(since != NULL ? strtoull(since, NULL, 10) : 0, body, STATUS_MAX);
		return answer(c, MHD_HTTP_OK, "application/json", body, n);
	}
	if (strcmp(method, "POST") == 0 && strcmp(url, "/api/cmd") == 0) {
		const char *cmd = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "do");
		const char *arg = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "arg");
		ER ercd = ev3sim_live_command(cmd, arg);

		if (ercd == E_OK)
			return answer_text(c, MHD_HTTP_OK, "application/json", "{\"ok\":true}");
		return answer_text(c, ercd == E_OBJ ? MHD_HTTP_SERVICE_UNAVAILABLE : MHD_HTTP_BAD_REQUEST,
				   "application/json", ercd == E_OBJ ? "{\"error\":\"the run has ended\"}" :
				   "{\"error\":\"bad command or argument\"}");
	}
	return answer_text(c, MHD_HTTP_NOT_FOUND, "text/plain", "not found\n");
}

/* Listens on 127.0.0.1:port; serves from libmicrohttpd's thread. */
static ER live_start(unsigned port, unsigned *bound, char *err, size_t errlen)
{
	struct sockaddr_in a = { .sin_family = AF_INET, .sin_port = htons((uint16_t)port) };
	socklen_t alen = sizeof(a);
	int one = 1;
	int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);

	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	if (fd < 0) {
		snprintf(err, errlen, "cannot make a socket: %s", strerror(errno));
		return E_SYS;
	}
	/* a port left in TIME_WAIT by the last run is free; one a program listens on is not */
	(void)setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
	if (bind(fd, (struct sockaddr *)&a, sizeof(a)) != 0 || listen(fd, 16) != 0 ||
	    getsockname(fd, (struct sockaddr *)&a, &alen) != 0) {
		snprintf(err, errlen, "cannot listen on 127.0.0.1:%u: %s", port, strerror(errno));
		close(fd);
		return E_SYS;
	}
	daemon_ = MHD_start_daemon(MHD_USE_INTERNAL_POLLING_THREAD, 0, NULL, NULL, handle, NULL,
				   MHD_OPTION_LISTEN_SOCKET, fd, MHD_OPTION_END);
	if (daemon_ == NULL) {
		snprintf(err, errlen, "libmicrohttpd cannot serve on 127.0.0.1:%u", port);
		close(fd);
		return E_SYS;
	}
	*bound = ntohs(a.sin_port);
	return E_OK;
}

/* Stops serving (libmicrohttpd closes the socket and joins its thread). */
static void live_stop(void)
{
	if (daemon_ != NULL)
		MHD_stop_daemon(daemon_);
	daemon_ = NULL;
}

static const struct ev3sim_live_server live_server = { live_start, live_stop };

/* Installs the server before the command line runs (a constructor, as the image writers'). */
__attribute__((constructor)) static void live_http_install(void)
{
	ev3sim_live_server = &live_server;
}

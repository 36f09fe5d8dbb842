/*
 * live_http.c — the server of `ev3sim run --live` (live.h) through GNU
 * libmicrohttpd (the program only: the test configurations, ARM ones
 * included, link the library without it, and Debian has no 32-bit build
 * of libmicrohttpd).
 *
 * libmicrohttpd is loaded (dlopen) when a run asks for --live, not linked:
 * it and the TLS library it needs cost a program that does not serve
 * nothing, not even their relocations at start-up.  It listens on 127.0.0.1
 * only, on a socket of its own (so a busy port is told as bind(2) tells
 * it), and answers from libmicrohttpd's thread:
 *   GET  /             the page (ev3sim/live_page.html, in the program)
 *   GET  /api/world    the app, the robot and its mat
 *   GET  /api/status?since=N   the state now and the plot's rows after row N
 *   POST /api/cmd?do=CMD[&arg=ARG]   press/release a button, pace, pause,
 *                      resume, step, stop (ev3sim_live_command)
 */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <dlfcn.h>
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
#define WORLD_MAX  (32U * 1024U)   /* a world of up to 256 obstacles (live.c) */

/* Debian's libmicrohttpd (bookworm: libmicrohttpd12). */
#define MHD_LIBRARY "libmicrohttpd.so.12"

static struct MHD_Daemon *daemon_;

/* The calls used, looked up in the library when it is loaded (prototypes: microhttpd.h). */
static struct {
	void *lib;
	struct MHD_Daemon *(*start_daemon)(unsigned int flags, uint16_t port, MHD_AcceptPolicyCallback apc,
					   void *apc_cls, MHD_AccessHandlerCallback dh, void *dh_cls, ...);
	void (*stop_daemon)(struct MHD_Daemon *daemon);
	struct MHD_Response *(*create_response_from_buffer)(size_t size, void *buffer,
							     enum MHD_ResponseMemoryMode mode);
	enum MHD_Result (*add_response_header)(struct MHD_Response *response, const char *header,
					       const char *content);
	enum MHD_Result (*queue_response)(struct MHD_Connection *connection, unsigned int status_code,
					  struct MHD_Response *response);
	void (*destroy_response)(struct MHD_Response *response);
	const char *(*lookup_connection_value)(struct MHD_Connection *connection, enum MHD_ValueKind kind,
					       const char *key);
} mhd;

/* Loads libmicrohttpd and looks its calls up (once); false with the reason in err. */
static bool mhd_load(char *err, size_t errlen)
{
	static const char *const names[] = {
		"MHD_start_daemon", "MHD_stop_daemon", "MHD_create_response_from_buffer", "MHD_add_response_header",
		"MHD_queue_response", "MHD_destroy_response", "MHD_lookup_connection_value",
	};
	void *fn[sizeof(names) / sizeof(names[0])];

	if (mhd.lib != NULL)
		return true;
	mhd.lib = dlopen(MHD_LIBRARY, RTLD_NOW | RTLD_LOCAL);
	if (mhd.lib == NULL) {
		snprintf(err, errlen, "cannot load GNU libmicrohttpd (%s; make deps installs it)", dlerror());
		return false;
	}
	for (size_t i = 0; i < sizeof(names) / sizeof(names[0]); i++)
		if ((fn[i] = dlsym(mhd.lib, names[i])) == NULL) {
			snprintf(err, errlen, "%s has no %s", MHD_LIBRARY, names[i]);
			dlclose(mhd.lib);
			mhd.lib = NULL;
			return false;
		}
	/* POSIX gives dlsym's result for a function as a pointer that converts to the function's type */
	*(void **)&mhd.start_daemon = fn[0];
	*(void **)&mhd.stop_daemon = fn[1];
	*(void **)&mhd.create_response_from_buffer = fn[2];
	*(void **)&mhd.add_response_header = fn[3];
	*(void **)&mhd.queue_response = fn[4];
	*(void **)&mhd.destroy_response = fn[5];
	*(void **)&mhd.lookup_connection_value = fn[6];
	return true;
}

/* Queues a response of status with body (taken: freed by libmicrohttpd). */
static enum MHD_Result answer(struct MHD_Connection *c, unsigned status, const char *type, char *body, size_t n)
{
	struct MHD_Response *r = mhd.create_response_from_buffer(n, body, MHD_RESPMEM_MUST_FREE);
	enum MHD_Result ret;

	if (r == NULL) {
		free(body);
		return MHD_NO;
	}
	mhd.add_response_header(r, "Content-Type", type);
	mhd.add_response_header(r, "Cache-Control", "no-store");
	ret = mhd.queue_response(c, status, r);
	mhd.destroy_response(r);
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
		const char *since = mhd.lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "since");

		if ((body = malloc(STATUS_MAX)) == NULL)
			return MHD_NO;
		n = ev3sim_live_status_json(since != NULL ? strtoull(since, NULL, 10) : 0, body, STATUS_MAX);
		return answer(c, MHD_HTTP_OK, "application/json", body, n);
	}
	if (strcmp(method, "POST") == 0 && strcmp(url, "/api/cmd") == 0) {
		const char *cmd = mhd.lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "do");
		const char *arg = mhd.lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "arg");
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
	if (!mhd_load(err, errlen)) {
		if (fd >= 0)
			close(fd);
		return E_SYS;
	}
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
	daemon_ = mhd.start_daemon(MHD_USE_INTERNAL_POLLING_THREAD, 0, NULL, NULL, handle, NULL,
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
		mhd.stop_daemon(daemon_);
	daemon_ = NULL;
}

static const struct ev3sim_live_server live_server = { live_start, live_stop };

/* Installs the server before the command line runs (a constructor, as the image writers'). */
__attribute__((constructor)) static void live_http_install(void)
{
	ev3sim_live_server = &live_server;
}

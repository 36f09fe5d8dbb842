/*
 * test_app_live.c — `ev3sim run --live` (ev3sim/src/live.c, the server
 * ev3sim/live_http.c): the app tests/ev3sim/apps/live waits for ENTER, then
 * writes on the display and drives the tribot.
 *
 *   - a run with --live in which nothing is clicked computes what the same
 *     run without it does: the same summary, CSV and VCD, byte for byte;
 *   - a busy port and a program without a server are refused with a message
 *     and status 1, --pace without --live with status 2;
 *   - over HTTP: the page and its JSON; the pace holds virtual time to wall
 *     time; pause holds it still, a single step moves it 10 ms;
 *   - in a real browser (headless Chromium, driven through its DevTools
 *     protocol): the page loads, a mouse click on its ENTER button presses
 *     ENTER in the simulation, the display changes and the robot drives off,
 *     as the page's own DOM shows; its Stop button ends the run with the
 *     summary.
 *
 * The server is linked where Debian has libmicrohttpd (host, host-san);
 * elsewhere (host32, the ARM configuration under qemu-arm) the test checks
 * that --live is refused and skips the rest with that reason.  Chromium is
 * a requirement (make deps installs it): without it the browser's tests fail.
 */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <fcntl.h>
#include <ftw.h>
#include <math.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <time.h>
#include "ev3sim_test.h"
#include "ev3sim/live.h"
#include "ev3sim/run.h"

extern const struct rtos_cfg ev3rt_app_cfg;

#define WAIT_S 30               /* the longest wait for a server, a browser or a state */

static struct et_run run;
static char work[] = "/tmp/ev3lx_live_XXXXXX";

static int live_main(int argc, char **argv)
{
	return ev3sim_run_main(argc, argv, "live", &ev3rt_app_cfg);
}

/* Wall-clock seconds (monotonic). */
static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void sleep_ms(unsigned ms)
{
	struct timespec ts = { (time_t)(ms / 1000U), (long)(ms % 1000U) * 1000000L };

	nanosleep(&ts, NULL);
}

/* Whole file at path into buf (NUL-terminated, truncated); its length, 0 if none. */
static size_t read_file(const char *path, char *buf, size_t len)
{
	FILE *f = fopen(path, "rb");
	size_t n;

	buf[0] = '\0';
	if (f == NULL)
		return 0;
	n = fread(buf, 1, len - 1, f);
	buf[n] = '\0';
	fclose(f);
	return n;
}

/* True if the two files hold the same bytes (and exist). */
static bool same_file(const char *a, const char *b)
{
	static char x[4 << 20], y[4 << 20];
	size_t nx = read_file(a, x, sizeof(x)), ny = read_file(b, y, sizeof(y));

	return nx > 0 && nx == ny && memcmp(x, y, nx) == 0;
}

/* The summary line of r without its last field (sim_speed, host-dependent). */
static const char *summary_of(const struct et_run *r, char *buf, size_t len)
{
	char *sp;

	et_last_line(r, buf, len);
	sp = strstr(buf, " sim_speed=");
	if (sp != NULL)
		*sp = '\0';
	return buf;
}

/* ---- HTTP and WebSocket, as far as the test needs them ---- */

/* A TCP connection to 127.0.0.1:port, -1 if none. */
static int connect_local(unsigned port)
{
	struct sockaddr_in a = { .sin_family = AF_INET, .sin_port = htons((uint16_t)port) };
	int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);

	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	if (fd >= 0 && connect(fd, (struct sockaddr *)&a, sizeof(a)) != 0) {
		close(fd);
		fd = -1;
	}
	return fd;
}

/* Reads an HTTP answer from fd into buf: up to its Content-Length's end, or
 * until the peer closes (Chromium keeps the connection open), or WAIT_S. */
static size_t read_answer(int fd, char *buf, size_t len)
{
	size_t n = 0;
	struct pollfd p = { fd, POLLIN, 0 };

	buf[0] = '\0';
	while (n + 1 < len && poll(&p, 1, WAIT_S * 1000) == 1) {
		ssize_t k = read(fd, buf + n, len - 1 - n);
		const char *end, *cl;

		if (k <= 0)
			break;
		n += (size_t)k;
		buf[n] = '\0';
		end = strstr(buf, "\r\n\r\n");
		cl = strcasestr(buf, "\r\nContent-Length:");
		if (end != NULL && cl != NULL && cl < end &&
		    n >= (size_t)(end + 4 - buf) + strtoul(cl + strlen("\r\nContent-Length:"), NULL, 10))
			break;
	}
	buf[n] = '\0';
	return n;
}

/* One HTTP/1.0 request; the body of a 200 answer in body, false otherwise. */
static bool http(unsigned port, const char *method, const char *path, char *body, size_t len)
{
	static char reply[1 << 20];
	char req[512];
	int fd = connect_local(port);
	const char *b;

	body[0] = '\0';
	if (fd < 0)
		return false;
	snprintf(req, sizeof(req), "%s %s HTTP/1.1\r\nHost: 127.0.0.1:%u\r\nContent-Length: 0\r\nConnection: close\r\n\r\n",
		 method, path, port);
	if (write(fd, req, strlen(req)) != (ssize_t)strlen(req)) {
		close(fd);
		return false;
	}
	read_answer(fd, reply, sizeof(reply));
	close(fd);
	b = strstr(reply, "\r\n\r\n");
	if (strncmp(reply, "HTTP/1.", 7) != 0 || strncmp(reply + 8, " 200", 4) != 0 || b == NULL)
		return false;
	snprintf(body, len, "%s", b + 4);
	return true;
}

/* The number after "key": in a JSON text (NAN if it is not there). */
static double json_num(const char *json, const char *key)
{
	char pat[64];
	const char *p;

	snprintf(pat, sizeof(pat), "\"%s\":", key);
	p = strstr(json, pat);
	return p != NULL ? strtod(p + strlen(pat), NULL) : NAN;
}

/* The live status's virtual time, NAN if it cannot be had. */
static double status_t(unsigned port)
{
	static char body[1 << 20];

	return http(port, "GET", "/api/status?since=1000000000", body, sizeof(body)) ? json_num(body, "t_s") : NAN;
}

/* A WebSocket connection (RFC 6455) to Chromium's DevTools at ws://127.0.0.1:port/path. */
static int ws_open(unsigned port, const char *path)
{
	char req[512], reply[1024];
	int fd = connect_local(port);
	size_t n = 0;
	struct pollfd p = { fd, POLLIN, 0 };

	if (fd < 0)
		return -1;
	snprintf(req, sizeof(req), "GET %s HTTP/1.1\r\nHost: 127.0.0.1:%u\r\nUpgrade: websocket\r\n"
		 "Connection: Upgrade\r\nSec-WebSocket-Key: ZXYzbHggbGl2ZSB0ZXN0IQ==\r\n"
		 "Sec-WebSocket-Version: 13\r\n\r\n", path, port);
	if (write(fd, req, strlen(req)) != (ssize_t)strlen(req))
		goto fail;
	/* the handshake's answer, byte by byte up to its blank line: frames follow it */
	while (n + 1 < sizeof(reply) && (n < 4 || memcmp(reply + n - 4, "\r\n\r\n", 4) != 0)) {
		if (poll(&p, 1, WAIT_S * 1000) != 1 || read(fd, reply + n, 1) != 1)
			goto fail;
		n++;
	}
	reply[n] = '\0';
	if (strncmp(reply, "HTTP/1.1 101", 12) == 0)
		return fd;
fail:
	close(fd);
	return -1;
}

/* Sends text as one masked text frame (a client's frames are masked). */
static bool ws_send(int fd, const char *text)
{
	static uint8_t frame[1 << 16];
	static const uint8_t mask[4] = { 0x37, 0xa1, 0x5c, 0x02 };
	size_t len = strlen(text), h = 0;

	if (len + 8 > sizeof(frame))
		return false;
	frame[h++] = 0x81;
	if (len < 126) {
		frame[h++] = (uint8_t)(0x80 | len);
	} else {
		frame[h++] = 0x80 | 126;
		frame[h++] = (uint8_t)(len >> 8);
		frame[h++] = (uint8_t)len;
	}
	memcpy(frame + h, mask, 4);
	h += 4;
	for (size_t i = 0; i < len; i++)
		frame[h + i] = (uint8_t)text[i] ^ mask[i % 4];
	return write(fd, frame, h + len) == (ssize_t)(h + len);
}

/* Reads exactly n bytes; false on a close or after WAIT_S. */
static bool read_n(int fd, void *buf, size_t n)
{
	struct pollfd p = { fd, POLLIN, 0 };
	size_t got = 0;

	while (got < n) {
		ssize_t k;

		if (poll(&p, 1, WAIT_S * 1000) != 1 || (k = read(fd, (char *)buf + got, n - got)) <= 0)
			return false;
		got += (size_t)k;
	}
	return true;
}

/* Receives one message (a text frame) into buf, NUL-terminated; false on error. */
static bool ws_recv(int fd, char *buf, size_t len)
{
	uint8_t h[2], ext[8];
	uint64_t n;

	if (!read_n(fd, h, 2))
		return false;
	n = h[1] & 0x7f;
	if (n == 126) {
		if (!read_n(fd, ext, 2))
			return false;
		n = (uint64_t)ext[0] << 8 | ext[1];
	} else if (n == 127) {
		if (!read_n(fd, ext, 8))
			return false;
		n = 0;
		for (int i = 0; i < 8; i++)
			n = n << 8 | ext[i];
	}
	if (n + 1 > len)
		return false;
	if (!read_n(fd, buf, (size_t)n))
		return false;
	buf[n] = '\0';
	return true;
}

/* One DevTools call: sends method with params (a JSON object) and returns its answer in buf. */
static bool cdp(int fd, const char *method, const char *params, char *buf, size_t len)
{
	static unsigned id;
	char msg[4096], want[32];

	id++;
	snprintf(msg, sizeof(msg), "{\"id\":%u,\"method\":\"%s\",\"params\":%s}", id, method, params);
	snprintf(want, sizeof(want), "{\"id\":%u,", id);
	if (!ws_send(fd, msg))
		return false;
	/* events come in between: skipped */
	while (ws_recv(fd, buf, len))
		if (strncmp(buf, want, strlen(want)) == 0)
			return strstr(buf, "\"error\"") == NULL;
	return false;
}

/* Evaluates a JavaScript expression giving a string in the page: the string in out. */
static bool page_eval(int fd, const char *expr, char *out, size_t len)
{
	static char reply[1 << 16];
	char params[2048];
	const char *v;

	snprintf(params, sizeof(params), "{\"expression\":\"%s\",\"returnByValue\":true}", expr);
	out[0] = '\0';
	if (!cdp(fd, "Runtime.evaluate", params, reply, sizeof(reply)))
		return false;
	v = strstr(reply, "\"value\":\"");
	if (v == NULL)
		return false;
	v += strlen("\"value\":\"");
	snprintf(out, len, "%.*s", (int)strcspn(v, "\""), v);
	return true;
}

/* The page's view: the display's dark pixels, the robot's x, the time, the left LED, the state. */
struct view {
	double dark, x, t;
	char led[32], state[512];
};

#define VIEW_EXPR \
	"[document.getElementById('lcd').dataset.dark, document.getElementById('pose').dataset.x, " \
	"document.body.dataset.t, document.getElementById('led-left').className, " \
	"document.getElementById('state').textContent].join('|')"

static bool page_view(int fd, struct view *v)
{
	char s[1024], *f[5], *save = NULL;
	int n = 0;

	if (!page_eval(fd, VIEW_EXPR, s, sizeof(s)))
		return false;
	for (char *tok = strtok_r(s, "|", &save); tok != NULL && n < 5; tok = strtok_r(NULL, "|", &save))
		f[n++] = tok;
	if (n < 4)
		return false;
	v->dark = strtod(f[0], NULL);
	v->x = f[1][0] != '\0' ? strtod(f[1], NULL) : NAN;
	v->t = f[2][0] != '\0' ? strtod(f[2], NULL) : NAN;
	snprintf(v->led, sizeof(v->led), "%s", f[3]);
	snprintf(v->state, sizeof(v->state), "%s", n > 4 ? f[4] : "");
	return true;
}

/* Clicks the centre of the element with id in the page as a mouse does (press, hold, release). */
static bool page_click(int fd, const char *id, unsigned hold_ms)
{
	static char reply[1 << 16];
	char expr[256], rect[256], params[256];
	double x, y, w, h;

	snprintf(expr, sizeof(expr), "(r => [r.x, r.y, r.width, r.height].join(','))"
		 "(document.getElementById('%s').getBoundingClientRect())", id);
	if (!page_eval(fd, expr, rect, sizeof(rect)) || sscanf(rect, "%lf,%lf,%lf,%lf", &x, &y, &w, &h) != 4)
		return false;
	x += w / 2;
	y += h / 2;
	snprintf(params, sizeof(params), "{\"type\":\"mouseMoved\",\"x\":%.1f,\"y\":%.1f}", x, y);
	if (!cdp(fd, "Input.dispatchMouseEvent", params, reply, sizeof(reply)))
		return false;
	snprintf(params, sizeof(params), "{\"type\":\"mousePressed\",\"x\":%.1f,\"y\":%.1f,\"button\":\"left\","
		 "\"buttons\":1,\"clickCount\":1}", x, y);
	if (!cdp(fd, "Input.dispatchMouseEvent", params, reply, sizeof(reply)))
		return false;
	sleep_ms(hold_ms);
	snprintf(params, sizeof(params), "{\"type\":\"mouseReleased\",\"x\":%.1f,\"y\":%.1f,\"button\":\"left\","
		 "\"buttons\":0,\"clickCount\":1}", x, y);
	return cdp(fd, "Input.dispatchMouseEvent", params, reply, sizeof(reply));
}

/* ---- processes ---- */

/* Starts main_fn(args) in a child with stdout and stderr to files in work; its pid. */
static pid_t start_run(const char *const *args, const char *out, const char *err)
{
	char *argv[32];
	int argc = 0;
	pid_t pid;

	argv[argc++] = (char *)"ev3sim";
	while (*args != NULL && argc < 31)
		argv[argc++] = (char *)*args++;
	argv[argc] = NULL;
	fflush(NULL);
	pid = fork();
	if (pid == 0) {
		int o = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644), e = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);

		if (o < 0 || e < 0)
			_exit(126);
		alarm(ET_HANG_S);
		dup2(o, STDOUT_FILENO);
		dup2(e, STDERR_FILENO);
		_exit(live_main(argc, argv));
	}
	return pid;
}

/* Waits up to WAIT_S for the file at path to hold "prefix<number>"; the number, 0 if it does not. */
static unsigned wait_for_number(const char *path, const char *prefix)
{
	static char text[1 << 16];
	double end = now_s() + WAIT_S;

	do {
		const char *p;

		read_file(path, text, sizeof(text));
		if ((p = strstr(text, prefix)) != NULL)
			return (unsigned)strtoul(p + strlen(prefix), NULL, 10);
		sleep_ms(50);
	} while (now_s() < end);
	return 0;
}

/* Waits for the child's end (up to WAIT_S, then kills it); its exit status, -1 if killed. */
static int wait_child(pid_t pid)
{
	double end = now_s() + WAIT_S;
	int ws;

	while (now_s() < end) {
		if (waitpid(pid, &ws, WNOHANG) == pid)
			return WIFEXITED(ws) ? WEXITSTATUS(ws) : -1;
		sleep_ms(20);
	}
	kill(pid, SIGKILL);
	waitpid(pid, &ws, 0);
	return -1;
}

/* The first program named name along PATH, in buf; false if there is none. */
static bool find_program(const char *name, char *buf, size_t len)
{
	const char *path = getenv("PATH");

	while (path != NULL && *path != '\0') {
		size_t n = strcspn(path, ":");

		snprintf(buf, len, "%.*s/%s", (int)n, path, name);
		if (access(buf, X_OK) == 0)
			return true;
		path += n + (path[n] == ':');
	}
	return false;
}

/* ---- the tests ---- */

/* Nothing clicked: --live computes what the same run without it does. */
static void test_same_run(void)
{
	char a_csv[128], b_csv[128], a_vcd[128], b_vcd[128], sa[1024], sb[1024];
	const char *a[] = { "--robot", "tribot", "--seconds", "3", "--click", "enter:1s", "--quiet", "--csv", a_csv,
			    "--trace", a_vcd, NULL };
	const char *b[] = { "--robot", "tribot", "--seconds", "3", "--click", "enter:1s", "--quiet", "--csv", b_csv,
			    "--trace", b_vcd, "--live=0", "--pace", "fast", NULL };
	bool ran;

	snprintf(a_csv, sizeof(a_csv), "%s/a.csv", work);
	snprintf(b_csv, sizeof(b_csv), "%s/b.csv", work);
	snprintf(a_vcd, sizeof(a_vcd), "%s/a.vcd", work);
	snprintf(b_vcd, sizeof(b_vcd), "%s/b.vcd", work);
	ran = et_run_main(&run, a, live_main, NULL) && run.status == 0;
	summary_of(&run, sa, sizeof(sa));
	ok(ran && strstr(sa, "travel_m=0.3") != NULL, "without --live: ENTER at 1 s, the tribot drives (%s)", sa);
	ran = et_run_main(&run, b, live_main, NULL) && run.status == 0;
	summary_of(&run, sb, sizeof(sb));
	ok(ran && strstr(run.err, "ev3sim run: live view at http://127.0.0.1:") != NULL,
	   "with --live=0 --pace fast it serves on a free port of 127.0.0.1 and runs");
	ok(ran && strcmp(sa, sb) == 0, "nothing clicked: the same summary (%s)", sb);
	ok(same_file(a_csv, b_csv), "the same CSV, byte for byte");
	ok(same_file(a_vcd, b_vcd), "the same VCD (pins, interrupts, the task timeline), byte for byte");
}

/* A busy port and --pace alone are refused. */
static void test_refusals(void)
{
	struct sockaddr_in a = { .sin_family = AF_INET };
	socklen_t alen = sizeof(a);
	int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
	char opt[32], want[96];
	const char *busy[] = { "--seconds", "1", opt, NULL };
	const char *pace[] = { "--seconds", "1", "--pace", "5", NULL };
	bool ran;

	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	if (fd < 0 || bind(fd, (struct sockaddr *)&a, sizeof(a)) != 0 || listen(fd, 1) != 0 ||
	    getsockname(fd, (struct sockaddr *)&a, &alen) != 0)
		tap_bail_out("cannot listen on a port of 127.0.0.1 for the busy port's test");
	snprintf(opt, sizeof(opt), "--live=%u", ntohs(a.sin_port));
	snprintf(want, sizeof(want), "ev3sim run: --live: cannot listen on 127.0.0.1:%u: Address already in use",
		 ntohs(a.sin_port));
	ran = et_run_main(&run, busy, live_main, NULL);
	ok(ran && run.status == 1 && strstr(run.err, want) != NULL, "a busy port: '%s', status 1 (%d)", want,
	   run.status);
	close(fd);
	ran = et_run_main(&run, pace, live_main, NULL);
	ok(ran && run.status == 2 && strstr(run.err, "--pace: only with --live") != NULL,
	   "--pace without --live: status 2 (%d)", run.status);
}

/* Over HTTP: the page, the pace, pause and a single step. */
static void test_http(unsigned port)
{
	static char body[1 << 20];
	double t0, t1, w0, w1;

	ok(http(port, "GET", "/", body, sizeof(body)) && strstr(body, "<title>ev3sim live</title>") != NULL &&
	   strstr(body, "id=\"btn-enter\"") != NULL, "GET / serves the page");
	ok(http(port, "GET", "/api/world", body, sizeof(body)) &&
	   strstr(body, "\"app\":\"live\",\"robot\":\"tribot\"") != NULL &&
	   strstr(body, "\"mat\":{\"kind\":\"stadium\",\"straight_mm\":1000,\"radius_mm\":400") != NULL,
	   "GET /api/world: the app, the robot and its mat (%.120s)", body);
	ok(!http(port, "POST", "/api/cmd?do=press&arg=middle", body, sizeof(body)) &&
	   !http(port, "GET", "/nothing", body, sizeof(body)), "a bad command and an unknown path are refused");
	t0 = status_t(port);
	w0 = now_s();
	sleep_ms(1000);
	t1 = status_t(port);
	w1 = now_s();
	ok(t1 - t0 > 0.7 * (w1 - w0) && t1 - t0 < 1.3 * (w1 - w0) + 0.05,
	   "at the default pace virtual time keeps to wall time (%.3f s in %.3f s)", t1 - t0, w1 - w0);
	ok(http(port, "POST", "/api/cmd?do=pause", body, sizeof(body)), "pause");
	sleep_ms(100);
	t0 = status_t(port);
	sleep_ms(300);
	t1 = status_t(port);
	ok(t0 == t1, "paused, virtual time stands still (%.3f, %.3f)", t0, t1);
	ok(http(port, "POST", "/api/cmd?do=step", body, sizeof(body)), "a single step");
	sleep_ms(200);
	t1 = status_t(port);
	ok(fabs(t1 - t0 - 0.01) < 1e-6, "it runs one step of 10 ms (%.3f -> %.3f)", t0, t1);
	ok(http(port, "POST", "/api/cmd?do=resume", body, sizeof(body)), "resume");
}

/* A run in a world: the page is given the world's mat, walls and goal, and the pose in it. */
static void test_world_view(void)
{
	static char body[1 << 16];
	const char *args[] = { "--world", "maze", "--seconds", "600", "--live=0", NULL };
	char out[128], err[128];
	unsigned port;
	double end;
	pid_t pid;

	snprintf(out, sizeof(out), "%s/world.out", work);
	snprintf(err, sizeof(err), "%s/world.err", work);
	pid = start_run(args, out, err);
	port = pid > 0 ? wait_for_number(err, "ev3sim run: live view at http://127.0.0.1:") : 0;
	ok(port != 0 && http(port, "GET", "/api/world", body, sizeof(body)) &&
	   strstr(body, "\"robot\":\"maze\"") != NULL &&
	   strstr(body, "\"mat\":{\"kind\":\"world\",\"mat_kind\":\"plain\"") != NULL &&
	   strstr(body, "{\"kind\":\"segment\"") != NULL && strstr(body, "{\"kind\":\"circle\"") != NULL &&
	   strstr(body, "\"goal\":[") != NULL,
	   "in a world, GET /api/world gives its mat, walls, obstacles and goal (%.100s)", body);
	/* the pose is there from the run's first step on: wait for it, as a page would */
	end = now_s() + WAIT_S;
	while (port != 0 && !(http(port, "GET", "/api/status", body, sizeof(body)) &&
			      strstr(body, "\"pose\":{\"x_mm\":") != NULL) && now_s() < end)
		sleep_ms(50);
	ok(port != 0 && strstr(body, "\"pose\":{\"x_mm\":") != NULL, "and /api/status the robot's pose in it (%.80s)",
	   body);
	if (port != 0)
		(void)http(port, "POST", "/api/cmd?do=stop", body, sizeof(body));
	is_int(wait_child(pid), 0, "the world's run stops from the page, status 0");
}

/* In headless Chromium: click ENTER on the page, read the display and the pose
 * back, click Stop; the browser's process group (it is still running), -1 if none. */
static pid_t test_browser(unsigned port, const char *run_log)
{
	static char text[1 << 16], list[1 << 16];
	char chromium[512], url[64], dir[160], log[160], *ws_path;
	unsigned cdp_port;
	struct view before = { 0 }, after = { 0 };
	double end;
	bool ready = false, went = false;
	pid_t browser;
	int fd;

	if (!find_program("chromium", chromium, sizeof(chromium))) {
		ok(false, "chromium is installed (make deps installs it: Debian's chromium package)");
		return -1;
	}
	snprintf(url, sizeof(url), "http://127.0.0.1:%u/", port);
	snprintf(dir, sizeof(dir), "%s/chromium", work);
	snprintf(log, sizeof(log), "%s/chromium.log", work);
	fflush(NULL);
	browser = fork();
	if (browser == 0) {
		int e = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
		char user_dir[200];

		snprintf(user_dir, sizeof(user_dir), "--user-data-dir=%s", dir);
		if (e < 0)
			_exit(126);
		dup2(e, STDOUT_FILENO);
		dup2(e, STDERR_FILENO);
		setpgid(0, 0);
		execl(chromium, "chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
		      "--no-first-run", "--no-default-browser-check", "--window-size=1400,1100",
		      "--remote-debugging-port=0", user_dir, url, (char *)NULL);
		_exit(127);
	}
	cdp_port = wait_for_number(log, "DevTools listening on ws://127.0.0.1:");
	ok(cdp_port != 0, "headless Chromium starts with its DevTools on port %u", cdp_port);
	/* the page's target: its WebSocket in /json/list */
	end = now_s() + WAIT_S;
	ws_path = NULL;
	while (cdp_port != 0 && ws_path == NULL && now_s() < end) {
		char want[96], *p = NULL;

		/* the page's entry: its "url", then its "webSocketDebuggerUrl" ws://HOST:PORT/devtools/page/ID */
		snprintf(want, sizeof(want), "\"url\": \"%s\"", url);
		if (http(cdp_port, "GET", "/json/list", list, sizeof(list)) && (p = strstr(list, want)) != NULL &&
		    (p = strstr(p, "\"webSocketDebuggerUrl\": \"ws://")) != NULL &&
		    (p = strstr(p, "/devtools/")) != NULL) {
			p[strcspn(p, "\"")] = '\0';
			ws_path = p;
		} else {
			sleep_ms(100);
		}
	}
	fd = ws_path != NULL ? ws_open(cdp_port, ws_path) : -1;
	ok(fd >= 0, "its DevTools connection to the page (%s)", ws_path ? ws_path : "no page target");
	/* the page shows the app waiting: "Press ENTER", the LEDs orange, the robot at the start */
	end = now_s() + WAIT_S;
	while (fd >= 0 && !ready && now_s() < end) {
		ready = page_view(fd, &before) && before.t > 0.5 && before.dark > 0 && !isnan(before.x) &&
			strstr(before.led, "orange") != NULL;
		if (!ready)
			sleep_ms(100);
	}
	ok(ready, "the page shows the display (%.0f dark pixels), the orange LEDs (%s) and the pose (x %.1f mm) at %.2f s",
	   before.dark, before.led, before.x, before.t);
	ok(fd >= 0 && page_click(fd, "btn-enter", 150), "a mouse click on the page's ENTER button");
	end = now_s() + WAIT_S;
	while (fd >= 0 && !went && now_s() < end) {
		went = page_view(fd, &after) && after.dark != before.dark && after.x > before.x + 20.0 &&
		       strstr(after.led, "green") != NULL;
		if (!went)
			sleep_ms(100);
	}
	ok(went, "the app saw ENTER: the display changed (%.0f -> %.0f dark pixels), the LEDs are %s, "
	   "the robot drove (x %.1f -> %.1f mm)", before.dark, after.dark, after.led, before.x, after.x);
	read_file(run_log, text, sizeof(text));
	ok(strstr(text, "NOTICE: live: ENTER") != NULL, "the app logged its ENTER");
	ok(fd >= 0 && page_click(fd, "stop", 20), "a click on the page's Stop button");
	if (fd >= 0)
		close(fd);
	return browser;
}

/* nftw's step of removing a tree: removes one entry. */
static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
	(void)st;
	(void)flag;
	(void)ftw;
	return remove(path);
}

int main(void)
{
	char out[128], err[128], opt[] = "--live=0", line[1024];
	const char *args[] = { "--robot", "tribot", "--seconds", "600", opt, NULL };
	const char *bare[] = { "--seconds", "1", "--live", NULL };
	unsigned port;
	pid_t pid, browser;
	int status;

	signal(SIGPIPE, SIG_IGN);
	if (mkdtemp(work) == NULL)
		tap_bail_out("cannot make a scratch directory");
	if (ev3sim_live_server == NULL) {
		bool ran = et_run_main(&run, bare, live_main, NULL);

		ok(ran && run.status == 1 && strstr(run.err, "--live: this program has no HTTP server") != NULL,
		   "without a server in the program --live is refused, status 1 (%d)", run.status);
		tap_skip(1, "the live view's server: Debian's libmicrohttpd is for the 64-bit host only "
			 "(host and host-san link it)");
		return tap_done();
	}
	test_same_run();
	test_refusals();
	test_world_view();
	snprintf(out, sizeof(out), "%s/run.out", work);
	snprintf(err, sizeof(err), "%s/run.err", work);
	pid = start_run(args, out, err);
	port = pid > 0 ? wait_for_number(err, "ev3sim run: live view at http://127.0.0.1:") : 0;
	ok(port != 0, "ev3sim run --live=0 prints the page's address (port %u)", port);
	if (port == 0)
		tap_bail_out("no live view to test");
	test_http(port);
	browser = test_browser(port, out);
	/* the page's Stop ends the run; then the browser goes */
	status = wait_child(pid);
	if (browser > 0) {
		kill(-browser, SIGTERM);
		if (wait_child(browser) == -1)
			kill(-browser, SIGKILL);
	}
	read_file(out, run.out, sizeof(run.out));
	et_last_line(&run, line, sizeof(line));
	ok(status == 0 && strstr(line, "app=live robot=tribot ") != NULL && strstr(line, " bugs=0 ") != NULL,
	   "the page's Stop ends the run with its summary, status 0 (%d: %s)", status, line);
	ok(strstr(line, " stopped_at_s=") != NULL, "which says when the page stopped it");
	(void)nftw(work, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
	return tap_done();
}

/*
 * brick_io.c — the SD card as a host directory and the serial port as a host
 * file or terminal, behind the API's storage and serial service calls
 * (brick_io.h, ev3api_brick_io.h).
 */
#define _GNU_SOURCE    /* accept4, SOCK_NONBLOCK */
#define _FILE_OFFSET_BITS 64   /* 32-bit hosts (qemu-arm): 64-bit inodes and offsets from readdir and stat */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>
#include "ev3api_brick_io.h"
#include "ev3sim/brick_io.h"
#include "ev3sim/serial_log.h"

static struct {
	char *root;                         /* realpath of the card, NULL: none */
	DIR *dirs[BRICK_IO_MAX_DIRS];
	char *dir_paths[BRICK_IO_MAX_DIRS]; /* host paths of the open directories */
	int serial_fd;                      /* -1: not connected */
	bool serial_is_uart;                /* the port is serial_log's polled UART model */
	bool serial_is_file;                /* a regular file: output only */
	int serial_write_errno;             /* the first failed write's errno since the setup, 0: none */
} io = { .serial_fd = -1 };

/* A serial link's far end (Bluetooth SPP, USB CDC): a connected socket to a host program. */
struct peer_link {
	int fd;                             /* -1: not connected */
	bool hung_up;                       /* the far end left, and no read has seen the end yet */
};

/* A port whose far end is a program on the host that connects to a Unix
 * socket: the PC paired over Bluetooth SPP (--bt) or plugged into the
 * USB port as a CDC device (--usb). */
struct peer_port {
	const char *option;                 /* the command line's name for it */
	char *path;                         /* the socket's path, NULL: no peer can come */
	int listen_fd;                      /* -1: none */
	struct peer_link peer;
};

static struct peer_port bt = { .option = "--bt", .listen_fd = -1, .peer.fd = -1 };
static struct peer_port usb = { .option = "--usb", .listen_fd = -1, .peer.fd = -1 };

/*
 * The brick as SPP master (SIO_PORT_SPP_MASTER_TEST): it connects to a
 * program listening on a Unix socket (--bt-master), another ev3sim's --bt
 * among them.  An attempt takes virtual time as paging does: a slave that
 * is there answers after SPP_PAGE_ANSWER_MS, on average half the default
 * page scan interval of 1.28 s (Bluetooth Core Specification, Vol 4 Part E,
 * Write_Page_Scan_Activity); with none, the attempt fails after the default
 * page timeout, 0x2000 slots of 0.625 ms (Write_Page_Timeout).
 */
#define SPP_PAGE_ANSWER_MS  640U
#define SPP_PAGE_TIMEOUT_MS 5120U

static struct {
	bool has_slave;                     /* --bt-master gave the slave's socket */
	struct sockaddr_un slave;           /* its address */
	struct peer_link link;
	int answer_fd;                      /* the socket of an attempt a slave answered, -1: none */
	bool attempting;
	SYSTIM attempt_ends;                /* when the attempt under way ends */
} spp = { .link.fd = -1, .answer_fd = -1 };

/* Closes a link's socket; the link is then as if never connected. */
static void link_close(struct peer_link *link)
{
	if (link->fd >= 0)
		close(link->fd);
	link->fd = -1;
	link->hung_up = false;
}

/* Closes a peer port's sockets and removes its socket's file. */
static void peer_port_close(struct peer_port *port)
{
	link_close(&port->peer);
	if (port->listen_fd >= 0)
		close(port->listen_fd);
	if (port->path != NULL)
		unlink(port->path);
	free(port->path);
	port->path = NULL;
	port->listen_fd = -1;
}

/* The SPP master idle: its link closed (the slave sees it go), an attempt under way ended. */
static void spp_idle(void)
{
	link_close(&spp.link);
	if (spp.answer_fd >= 0)
		close(spp.answer_fd);
	spp.answer_fd = -1;
	spp.attempting = false;
}

/* Closes the peers' sockets, removes the listening sockets' files, forgets the SPP master's slave. */
static void peers_teardown(void)
{
	peer_port_close(&bt);
	peer_port_close(&usb);
	spp_idle();
	spp.has_slave = false;
}

/* A Unix socket address for path, or E_PAR with the reason (naming option) in err. */
static ER unix_address(const char *option, const char *path, struct sockaddr_un *addr, char *err, size_t errlen)
{
	memset(addr, 0, sizeof(*addr));
	addr->sun_family = AF_UNIX;
	if (strlen(path) >= sizeof(addr->sun_path)) {
		snprintf(err, errlen, "%s: a socket path has at most %zu bytes (%zu given)", option,
			 sizeof(addr->sun_path) - 1, strlen(path));
		return E_PAR;
	}
	strcpy(addr->sun_path, path);
	return E_OK;
}

/* Listens for port's peer on a Unix socket at path: E_OK, or E_PAR / E_OBJ
 * with the reason (naming the option) in err. */
static ER peer_port_listen(struct peer_port *port, const char *path, char *err, size_t errlen)
{
	struct sockaddr_un addr;
	struct stat st;

	peer_port_close(port);
	if (unix_address(port->option, path, &addr, err, errlen) != E_OK)
		return E_PAR;
	/* a socket left by an earlier run is replaced; any other file is not */
	if (lstat(path, &st) == 0) {
		if (!S_ISSOCK(st.st_mode)) {
			snprintf(err, errlen, "%s %s: exists and is not a socket", port->option, path);
			return E_OBJ;
		}
		unlink(path);
	}
	port->listen_fd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	if (port->listen_fd < 0 || bind(port->listen_fd, (struct sockaddr *)&addr, sizeof(addr)) != 0 ||
	    listen(port->listen_fd, 1) != 0) {
		snprintf(err, errlen, "%s %s: %s", port->option, path, strerror(errno));
		if (port->listen_fd >= 0)
			close(port->listen_fd);
		port->listen_fd = -1;
		return E_OBJ;
	}
	port->path = strdup(path);
	if (port->path == NULL) {
		snprintf(err, errlen, "%s %s: out of memory", port->option, path);
		peer_port_close(port);
		unlink(path);
		return E_NOMEM;
	}
	return E_OK;
}

ER brick_io_bt_listen(const char *path, char *err, size_t errlen)
{
	return peer_port_listen(&bt, path, err, errlen);
}

ER brick_io_usb_listen(const char *path, char *err, size_t errlen)
{
	return peer_port_listen(&usb, path, err, errlen);
}

ER brick_io_bt_master(const char *path, char *err, size_t errlen)
{
	spp.has_slave = unix_address("--bt-master", path, &spp.slave, err, errlen) == E_OK;
	return spp.has_slave ? E_OK : E_PAR;
}

/* The far end went away: the link is down until it connects again, and
 * the next read sees the end of the stream, as on EV3RT. */
static void link_drop(struct peer_link *link)
{
	close(link->fd);
	link->fd = -1;
	link->hung_up = true;
}

/* Whether the link's far end is still there (one that hung up is dropped;
 * what it sent before is read first). */
static bool link_up(struct peer_link *link)
{
	char byte;

	if (link->fd >= 0 && recv(link->fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0)
		link_drop(link);
	return link->fd >= 0;
}

/* Whether a program is connected to port's socket: one waiting to connect is taken. */
static bool port_peer(struct peer_port *port)
{
	if (!link_up(&port->peer) && port->listen_fd >= 0)
		/* cppcheck-suppress nullPointer ; accept4 takes NULL for a peer address it need not return (POSIX accept) */
		port->peer.fd = accept4(port->listen_fd, NULL, NULL, SOCK_NONBLOCK | SOCK_CLOEXEC);
	return port->peer.fd >= 0;
}

/* Ends the master's connection attempt once its time has come: the link is
 * up if a slave answered. */
static void spp_settle(void)
{
	SYSTIM now;

	if (!spp.attempting || get_tim(&now) != E_OK || now < spp.attempt_ends)
		return;
	spp.attempting = false;
	if (spp.answer_fd >= 0) {
		link_close(&spp.link);
		spp.link.fd = spp.answer_fd;
		spp.answer_fd = -1;
	}
}

/* Whether the master's link to its slave is up. */
static bool spp_peer(void)
{
	spp_settle();
	return link_up(&spp.link);
}

void brick_io_teardown(void)
{
	for (uint_t i = 0; i < BRICK_IO_MAX_DIRS; i++) {
		if (io.dirs[i] != NULL)
			closedir(io.dirs[i]);
		free(io.dir_paths[i]);
		io.dirs[i] = NULL;
		io.dir_paths[i] = NULL;
	}
	free(io.root);
	io.root = NULL;
	if (io.serial_fd >= 0)
		close(io.serial_fd);
	io.serial_fd = -1;
	io.serial_is_uart = false;
	peers_teardown();
}

void brick_io_serial_to_uart(void)
{
	if (io.serial_fd >= 0)
		close(io.serial_fd);
	io.serial_fd = -1;
	io.serial_is_uart = true;
}

int brick_io_serial_write_errno(void)
{
	return io.serial_write_errno;
}

ER brick_io_setup(const char *sd_dir, const char *serial_path, char *err, size_t errlen)
{
	struct stat st;

	brick_io_teardown();
	io.serial_write_errno = 0;
	if (sd_dir != NULL) {
		io.root = realpath(sd_dir, NULL);
		if (io.root == NULL || stat(io.root, &st) != 0 || !S_ISDIR(st.st_mode)) {
			snprintf(err, errlen, "--sd %s: not a directory", sd_dir);
			brick_io_teardown();
			return E_OBJ;
		}
	}
	if (serial_path != NULL) {
		bool exists = stat(serial_path, &st) == 0;

		io.serial_is_file = !exists || S_ISREG(st.st_mode);
		io.serial_fd = open(serial_path, io.serial_is_file ? O_WRONLY | O_CREAT | O_TRUNC :
				    O_RDWR | O_NOCTTY | O_NONBLOCK, 0644);
		if (io.serial_fd < 0) {
			snprintf(err, errlen, "--serial %s: %s", serial_path, strerror(errno));
			brick_io_teardown();
			return E_OBJ;
		}
	}
	return E_OK;
}

/*
 * Copies the caller's path into out (BRICK_IO_MAX_PATH bytes), checking that
 * the calling task may read every byte of it: E_MACV for NULL or unreadable
 * memory, E_PAR for an empty path or one longer than TMAX_FILENAME_LEN.
 * A provider cannot trust its caller (an app may make the call itself).
 */
static ER copy_caller_path(const char *path, char *out)
{
	uint_t i;

	if (path == NULL)
		return E_MACV;
	/* one probe covers the common case; near the end of a region, byte by byte */
	if (prb_mem(path, BRICK_IO_MAX_PATH, TSK_SELF, TPM_READ) != E_OK) {
		for (i = 0; i < BRICK_IO_MAX_PATH; i++) {
			if (prb_mem(path + i, 1, TSK_SELF, TPM_READ) != E_OK)
				return E_MACV;
			if (path[i] == '\0')
				break;
		}
	}
	for (i = 0; i < BRICK_IO_MAX_PATH && path[i] != '\0'; i++)
		out[i] = path[i];
	if (i == 0 || i == BRICK_IO_MAX_PATH)
		return E_PAR;
	out[i] = '\0';
	return E_OK;
}

/*
 * The host path of the card's path (absolute or relative to the root),
 * malloc'd: E_OBJ without a card, E_PAR for a ".." above the root or a path
 * leading out of the card through a symbolic link, E_NOEXS if nothing is
 * there, E_NOMEM.
 */
static ER resolve(const char *path, char **out)
{
	size_t rootlen, len;
	char *joined, *real;

	if (io.root == NULL)
		return E_OBJ;
	rootlen = len = strlen(io.root);
	if ((joined = malloc(rootlen + strlen(path) + 2)) == NULL)
		return E_NOMEM;
	memcpy(joined, io.root, rootlen + 1);
	/* lexically, component by component: "." stays, ".." pops but never the root */
	for (const char *p = path; *p != '\0';) {
		size_t n = strcspn(p, "/");

		if (n == 2 && p[0] == '.' && p[1] == '.') {
			if (len == rootlen) {
				free(joined);
				return E_PAR;
			}
			while (joined[len - 1] != '/')
				len--;
			joined[--len] = '\0';
		} else if (n > 0 && !(n == 1 && p[0] == '.')) {
			joined[len++] = '/';
			memcpy(joined + len, p, n);
			len += n;
			joined[len] = '\0';
		}
		p += n + (p[n] == '/');
	}
	real = realpath(joined, NULL);
	free(joined);
	if (real == NULL)
		return errno == ENOMEM ? E_NOMEM : E_NOEXS;
	if (strncmp(real, io.root, rootlen) != 0 || (real[rootlen] != '/' && real[rootlen] != '\0')) {
		free(real);
		return E_PAR;
	}
	*out = real;
	return E_OK;
}

/*
 * The host path of a card entry that need not exist (the last component is
 * not followed): the card's path of its directory resolved, then its name.
 * E_PAR for a name that is empty, "." or "..", else as resolve.
 */
static ER resolve_entry(const char *path, char **out)
{
	size_t len = strlen(path), name_at;
	char *dir, *host_dir;
	ER ercd;

	while (len > 0 && path[len - 1] == '/')
		len--;
	name_at = len;
	while (name_at > 0 && path[name_at - 1] != '/')
		name_at--;
	if (name_at == len || (len - name_at == 1 && path[name_at] == '.') ||
	    (len - name_at == 2 && path[name_at] == '.' && path[name_at + 1] == '.'))
		return E_PAR;
	if ((dir = strndup(path, name_at)) == NULL)
		return E_NOMEM;
	ercd = resolve(dir, &host_dir);
	free(dir);
	if (ercd != E_OK)
		return ercd;
	*out = malloc(strlen(host_dir) + (len - name_at) + 2);
	if (*out == NULL) {
		free(host_dir);
		return E_NOMEM;
	}
	sprintf(*out, "%s/%.*s", host_dir, (int)(len - name_at), path + name_at);
	free(host_dir);
	return E_OK;
}

ER brick_io_card_path(const char *path, enum brick_io_card_use use, char **host)
{
	struct stat st;
	ER ercd;

	if (io.root == NULL)
		return E_OBJ;
	if (path == NULL || *path == '\0' || strlen(path) >= BRICK_IO_MAX_PATH)
		return E_PAR;
	if (use == BRICK_IO_CARD_ENTRY)
		return resolve_entry(path, host);
	ercd = resolve(path, host);
	if (ercd != E_NOEXS || use != BRICK_IO_CARD_CREATE)
		return ercd;
	ercd = resolve_entry(path, host);
	/* a name that is there but leads nowhere is a symbolic link: it could create a file off the card */
	if (ercd == E_OK && lstat(*host, &st) == 0) {
		free(*host);
		return E_PAR;
	}
	return ercd;
}

/* The caller's path, resolved; the common head of the file and directory calls. */
static ER caller_path(intptr_t p_path, char **host)
{
	char name[BRICK_IO_MAX_PATH];
	ER ercd;

	if (sns_ctx())
		return E_CTX;
	if ((ercd = copy_caller_path((const char *)p_path, name)) != E_OK)
		return ercd;
	return resolve(name, host);
}

static ER_UINT svc_file_size(intptr_t p_path, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	struct stat st;
	char *host;
	ER ercd;

	(void)p2; (void)p3; (void)p4; (void)p5; (void)cdmid;
	if ((ercd = caller_path(p_path, &host)) != E_OK)
		return ercd;
	ercd = stat(host, &st) != 0 ? E_NOEXS : !S_ISREG(st.st_mode) ? E_OBJ :
	       st.st_size > INT32_MAX ? E_NOMEM : (ER)st.st_size;
	free(host);
	return ercd;
}

static ER_UINT svc_file_read(intptr_t p_path, intptr_t offset, intptr_t p_buf, intptr_t p_len, intptr_t p5,
			     ID cdmid)
{
	uint_t len = (uint_t)p_len;
	ssize_t got;
	char *host;
	ER ercd;
	int fd;

	(void)p5; (void)cdmid;
	if ((ercd = caller_path(p_path, &host)) != E_OK)
		return ercd;
	if (offset < 0 || p_len <= 0 || len > BRICK_IO_MAX_XFER)
		ercd = E_PAR;
	else if ((void *)p_buf == NULL || prb_mem((void *)p_buf, len, TSK_SELF, TPM_WRITE) != E_OK)
		ercd = E_MACV;
	else if ((fd = open(host, O_RDONLY)) < 0)
		ercd = E_NOEXS;
	else {
		got = pread(fd, (void *)p_buf, len, (off_t)offset);
		close(fd);
		ercd = got < 0 ? E_OBJ : (ER)got;
	}
	free(host);
	return ercd;
}

static ER_UINT svc_dir_open(intptr_t p_path, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	char *host;
	ER ercd;
	uint_t i;

	(void)p2; (void)p3; (void)p4; (void)p5; (void)cdmid;
	if ((ercd = caller_path(p_path, &host)) != E_OK)
		return ercd;
	for (i = 0; i < BRICK_IO_MAX_DIRS && io.dirs[i] != NULL; i++)
		;
	if (i == BRICK_IO_MAX_DIRS) {
		free(host);
		return E_NOMEM;
	}
	if ((io.dirs[i] = opendir(host)) == NULL) {
		ercd = errno == ENOTDIR ? E_OBJ : E_NOEXS;
		free(host);
		return ercd;
	}
	io.dir_paths[i] = host;
	return (ER)(i + 1);
}

/* A FAT directory entry's date and time (what EV3RT's card reports) of t, UTC. */
static void fat_time(time_t t, uint16_t *date, uint16_t *hms)
{
	struct tm tm;

	if (gmtime_r(&t, &tm) == NULL || tm.tm_year < 80) {
		*date = (0 << 9) | (1 << 5) | 1;    /* 1980-01-01, FAT's epoch */
		*hms = 0;
		return;
	}
	*date = (uint16_t)(((tm.tm_year - 80) << 9) | ((tm.tm_mon + 1) << 5) | tm.tm_mday);
	*hms = (uint16_t)((tm.tm_hour << 11) | (tm.tm_min << 5) | (tm.tm_sec / 2));
}

static ER_UINT svc_dir_read(intptr_t dirid, intptr_t p_info, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	fileinfo_t *info = (fileinfo_t *)p_info;
	struct dirent *e;
	struct stat st;
	char *full;
	DIR *d;

	(void)p3; (void)p4; (void)p5; (void)cdmid;
	if (sns_ctx())
		return E_CTX;
	if (dirid < 1 || dirid > (intptr_t)BRICK_IO_MAX_DIRS || (d = io.dirs[dirid - 1]) == NULL)
		return E_ID;
	if (info == NULL || prb_mem(info, sizeof(*info), TSK_SELF, TPM_WRITE) != E_OK)
		return E_MACV;
	do {
		errno = 0;
		/* cppcheck-suppress readdirCalled ; one simulation thread, and readdir_r is deprecated in glibc */
		if ((e = readdir(d)) == NULL)
			return errno != 0 ? E_OBJ : E_NOEXS;
	} while (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0);
	if ((full = malloc(strlen(io.dir_paths[dirid - 1]) + strlen(e->d_name) + 2)) == NULL)
		return E_NOMEM;
	sprintf(full, "%s/%s", io.dir_paths[dirid - 1], e->d_name);
	memset(info, 0, sizeof(*info));
	if (stat(full, &st) == 0) {
		info->size = S_ISREG(st.st_mode) && (uint64_t)st.st_size <= UINT32_MAX ? (uint32_t)st.st_size : 0;
		fat_time(st.st_mtime, &info->date, &info->time);
		info->is_dir = S_ISDIR(st.st_mode);
		info->is_readonly = (st.st_mode & S_IWUSR) == 0;
	}
	info->is_hidden = e->d_name[0] == '.';
	snprintf(info->name, sizeof(info->name), "%s", e->d_name);
	free(full);
	return E_OK;
}

static ER_UINT svc_dir_close(intptr_t dirid, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	(void)p2; (void)p3; (void)p4; (void)p5; (void)cdmid;
	if (sns_ctx())
		return E_CTX;
	if (dirid < 1 || dirid > (intptr_t)BRICK_IO_MAX_DIRS || io.dirs[dirid - 1] == NULL)
		return E_ID;
	closedir(io.dirs[dirid - 1]);
	free(io.dir_paths[dirid - 1]);
	io.dirs[dirid - 1] = NULL;
	io.dir_paths[dirid - 1] = NULL;
	return E_OK;
}

/* Whether port has a far end: the sensor-port UART when --serial gave one or
 * serial_log models it; Bluetooth and USB while a program is connected to
 * --bt's or --usb's socket; the SPP master while its link to the slave is up. */
static bool serial_connected(intptr_t port)
{
	if (port == EV3_SERIAL_BT)
		return port_peer(&bt);
	if (port == EV3_SERIAL_USB_CDC)
		return port_peer(&usb);
	if (port == BRICK_IO_SERIAL_SPP_MASTER)
		return spp_peer();
	return (port == EV3_SERIAL_DEFAULT || port == EV3_SERIAL_UART) &&
	       (io.serial_fd >= 0 || io.serial_is_uart);
}

/* The socket link of a Bluetooth or USB port, NULL for the UART's. */
static struct peer_link *peer_link_of(intptr_t port)
{
	return port == EV3_SERIAL_BT ? &bt.peer : port == EV3_SERIAL_USB_CDC ? &usb.peer :
	       port == BRICK_IO_SERIAL_SPP_MASTER ? &spp.link : NULL;
}

/* A Bluetooth link's write: what the far end's socket takes (0: full); a
 * far end gone is a disconnection, and the bytes are lost as on the air. */
static ER_UINT link_write(struct peer_link *link, const void *buf, size_t len)
{
	ssize_t put = send(link->fd, buf, len, MSG_NOSIGNAL);

	if (put >= 0)
		return (ER_UINT)put;
	if (errno == EAGAIN || errno == EWOULDBLOCK)
		return 0;
	link_drop(link);
	return (ER_UINT)len;
}

/* A Bluetooth link's read: what the far end sent (0: nothing yet); once
 * after the far end left, the end of the stream (E_OBJ); while it is not
 * connected, the reader waits. */
static ER_UINT link_read(struct peer_link *link, bool connected, void *buf, size_t len)
{
	ssize_t got;

	if (!connected) {
		if (!link->hung_up)
			return 0;
		link->hung_up = false;
		return E_OBJ;
	}
	got = recv(link->fd, buf, len, 0);
	if (got > 0)
		return (ER_UINT)got;
	if (got < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
		return 0;
	link_drop(link);
	return link_read(link, false, buf, len);
}

/* The head of both directions: context, port, length and buffer. */
static ER serial_check(intptr_t port, intptr_t p_buf, intptr_t p_len, MODE access)
{
	if (sns_ctx())
		return E_CTX;
	if ((uintptr_t)port > BRICK_IO_SERIAL_LAST)
		return E_ID;
	if (p_len < 0 || p_len > (intptr_t)BRICK_IO_MAX_XFER)
		return E_PAR;
	if (p_len > 0 && ((void *)p_buf == NULL || prb_mem((void *)p_buf, (SIZE)p_len, TSK_SELF, access) != E_OK))
		return E_MACV;
	return E_OK;
}

static ER_UINT svc_serial_write(intptr_t port, intptr_t p_buf, intptr_t p_len, intptr_t p4, intptr_t p5,
				ID cdmid)
{
	struct peer_link *link;
	ssize_t put;
	ER ercd;

	(void)p4; (void)p5; (void)cdmid;
	if ((ercd = serial_check(port, p_buf, p_len, TPM_READ)) != E_OK)
		return ercd;
	if (!serial_connected(port))
		return p_len == 0 ? E_OBJ : p_len;    /* nothing listens: the bytes are lost, as on the wire */
	if (p_len == 0)
		return E_OK;
	if ((link = peer_link_of(port)) != NULL)
		return link_write(link, (const void *)p_buf, (size_t)p_len);
	if (io.serial_is_uart)
		return serial_log_send((const char *)p_buf, (uint_t)p_len);
	put = write(io.serial_fd, (const void *)p_buf, (size_t)p_len);
	if (put < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
		return 0;
	if (put < 0) {
		if (io.serial_write_errno == 0)
			io.serial_write_errno = errno;
		return E_OBJ;
	}
	return (ER_UINT)put;
}

static ER_UINT svc_serial_read(intptr_t port, intptr_t p_buf, intptr_t p_len, intptr_t p4, intptr_t p5,
			       ID cdmid)
{
	struct peer_link *link;
	ssize_t got;
	ER ercd;

	(void)p4; (void)p5; (void)cdmid;
	if ((ercd = serial_check(port, p_buf, p_len, TPM_WRITE)) != E_OK || p_len == 0)
		return ercd;
	if ((link = peer_link_of(port)) != NULL)
		return link_read(link, serial_connected(port), (void *)p_buf, (size_t)p_len);
	if (!serial_connected(port))
		return 0;           /* nothing arrives from no far end: the reader waits */
	if (io.serial_is_file || io.serial_is_uart)
		return E_OBJ;       /* output only: the far end says nothing */
	got = read(io.serial_fd, (void *)p_buf, (size_t)p_len);
	if (got < 0)
		return errno == EAGAIN || errno == EWOULDBLOCK ? 0 : E_OBJ;
	return got == 0 ? E_OBJ : (ER_UINT)got;
}

/*
 * Starts the SPP master's attempt to connect to the slave at addr with the
 * PIN pin (1 to BRICK_IO_MAX_PIN bytes): E_OK, at once if the link is up;
 * E_CTX while an attempt is under way or from a non-task context; E_MACV
 * for memory the caller may not read; E_PAR for a bad PIN.  The slave is
 * --bt-master's socket whatever addr says: the simulated air has one slave.
 */
static ER_UINT svc_spp_connect(intptr_t p_addr, intptr_t p_pin, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	const char *pin = (const char *)p_pin;
	SYSTIM now;
	uint_t n;

	(void)p3; (void)p4; (void)p5; (void)cdmid;
	if (sns_ctx() || spp.attempting)
		return E_CTX;
	if ((void *)p_addr == NULL || prb_mem((void *)p_addr, 6, TSK_SELF, TPM_READ) != E_OK || pin == NULL)
		return E_MACV;
	for (n = 0; n <= BRICK_IO_MAX_PIN; n++) {
		if (prb_mem(pin + n, 1, TSK_SELF, TPM_READ) != E_OK)
			return E_MACV;
		if (pin[n] == '\0')
			break;
	}
	if (n == 0 || n > BRICK_IO_MAX_PIN)
		return E_PAR;
	if (spp_peer())
		return E_OK;
	if (get_tim(&now) != E_OK)
		return E_CTX;
	if (spp.has_slave) {
		spp.answer_fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
		if (spp.answer_fd >= 0 && connect(spp.answer_fd, (struct sockaddr *)&spp.slave, sizeof(spp.slave)) != 0) {
			close(spp.answer_fd);
			spp.answer_fd = -1;
		}
		if (spp.answer_fd >= 0)
			(void)fcntl(spp.answer_fd, F_SETFL, O_NONBLOCK);
	}
	spp.attempting = true;
	spp.attempt_ends = now + (spp.answer_fd >= 0 ? SPP_PAGE_ANSWER_MS : SPP_PAGE_TIMEOUT_MS);
	return E_OK;
}

/* 1 while the SPP master's connection attempt is under way, else 0. */
static ER_UINT svc_spp_connecting(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	(void)p1; (void)p2; (void)p3; (void)p4; (void)p5; (void)cdmid;
	if (sns_ctx())
		return E_CTX;
	spp_settle();
	return spp.attempting ? 1 : 0;
}

/* The SPP master back to idle (EV3RT 1.x's ev3_spp_master_reset). */
static ER_UINT svc_spp_reset(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	(void)p1; (void)p2; (void)p3; (void)p4; (void)p5; (void)cdmid;
	if (sns_ctx())
		return E_CTX;
	spp_idle();
	return E_OK;
}

static const struct rtos_svc_cfg brick_io_svcs[] = {
	{ BRICK_IO_FN_FILE_SIZE, svc_file_size, 1024 },
	{ BRICK_IO_FN_FILE_READ, svc_file_read, 1024 },
	{ BRICK_IO_FN_DIR_OPEN, svc_dir_open, 1024 },
	{ BRICK_IO_FN_DIR_READ, svc_dir_read, 1024 },
	{ BRICK_IO_FN_DIR_CLOSE, svc_dir_close, 1024 },
	{ BRICK_IO_FN_SERIAL_WRITE, svc_serial_write, 1024 },
	{ BRICK_IO_FN_SERIAL_READ, svc_serial_read, 1024 },
	{ BRICK_IO_FN_SPP_CONNECT, svc_spp_connect, 1024 },
	{ BRICK_IO_FN_SPP_CONNECTING, svc_spp_connecting, 1024 },
	{ BRICK_IO_FN_SPP_RESET, svc_spp_reset, 1024 },
};

const struct rtos_cfg brick_io_cfg = {
	.name = "brick_io",
	.svcs = RTOS_TABLE(brick_io_svcs),
	.svc_first = BRICK_IO_FN_FIRST, .svc_count = BRICK_IO_FN_COUNT,
};

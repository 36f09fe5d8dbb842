/*
 * test_app_files.c — `ev3sim run`'s command line (ev3sim_run_main) with
 * tests/ev3sim/apps/files linked in: every output that cannot be written
 * (standard output, --csv, --audio, --trace, --serial on a full disk) is
 * reported naming it, with status 1; a FIFO without a reader is refused at
 * once, one with a reader takes the streamed WAV; --audio's WAV is streamed
 * with its sizes written at the end; --fault's limit; and the app's C
 * library file calls land on the simulated SD card (--sd), never in the
 * host's current directory.
 */
#include "ev3sim_test.h"
#include <dirent.h>
#include <sys/stat.h>
#include "host_sim/devices/ev3_speaker.h"
#include "ev3sim/run.h"

/* The app's configuration, generated from its app.cfg. */
extern const struct rtos_cfg ev3rt_app_cfg;

static struct et_run run;
static char tmp[] = "/tmp/ev3sim-files-XXXXXX";

static int files_main(int argc, char **argv)
{
	return ev3sim_run_main(argc, argv, "files", &ev3rt_app_cfg);
}

/* Runs the app with args, stdout to stdout_path (NULL: captured). */
static bool run_files(const char *const *args, const char *stdout_path)
{
	return et_run_main(&run, args, files_main, stdout_path);
}

/* Every output on a full disk: status 1 and a message naming it. */
static void test_full_disk(void)
{
	static const char *const outputs[][2] = {
		{ "--csv", "/dev/full" }, { "--audio", "/dev/full" }, { "--trace", "/dev/full" },
		{ "--serial", "/dev/full" },
	};
	const char *plain[] = { "--seconds", "1", "--quiet", NULL };

	ok(run_files(plain, "/dev/full") && run.status == 1 &&
	   strstr(run.err, "ev3sim run: cannot write the standard output: No space left on device"),
	   "standard output on a full disk: status 1, named");
	if (run.status != 1)
		tap_diag("status %d, stderr: %s", run.status, run.err);
	for (unsigned i = 0; i < sizeof(outputs) / sizeof(outputs[0]); i++) {
		const char *args[] = { "--seconds", "1", "--quiet", outputs[i][0], outputs[i][1], NULL };

		ok(run_files(args, NULL) && run.status == 1 && strstr(run.err, "cannot write") &&
		   strstr(run.err, "/dev/full"), "%s /dev/full: status 1, the output named", outputs[i][0]);
		if (run.status != 1)
			tap_diag("status %d, stderr: %s", run.status, run.err);
	}
}

/* Outputs to a FIFO: refused at once without a reader; the WAV streamed to one with a reader. */
static void test_fifo(void)
{
	char fifo[64];
	int fd;

	snprintf(fifo, sizeof(fifo), "%s/fifo", tmp);
	if (mkfifo(fifo, 0600) != 0) {
		tap_skip(5, "cannot make a FIFO");
		return;
	}
	{
		const char *csv[] = { "--seconds", "1", "--quiet", "--csv", fifo, NULL };
		const char *wav[] = { "--seconds", "1", "--quiet", "--audio", fifo, NULL };
		const char *vcd[] = { "--seconds", "1", "--quiet", "--trace", fifo, NULL };

		ok(run_files(csv, NULL) && run.status == 1 && strstr(run.err, "a FIFO no process is reading") &&
		   strstr(run.err, fifo), "--csv to a FIFO without a reader: refused at once, named");
		ok(run_files(wav, NULL) && run.status == 1 && strstr(run.err, "a FIFO no process is reading") &&
		   strstr(run.err, fifo), "--audio to a FIFO without a reader: refused at once, named");
		ok(run_files(vcd, NULL) && run.status == 1 && strstr(run.err, ": a FIFO ("),
		   "--trace to a FIFO: refused before the run");
	}
	/* a reader (this test, holding the FIFO's read end; half a second's WAV fits the pipe's 64 KiB) */
	if ((fd = et_fifo_reader(fifo)) >= 0) {
		const char *args[] = { "--seconds", "0.5", "--quiet", "--audio", fifo, NULL };
		static char wav[65536];
		size_t n;

		ok(run_files(args, NULL) && run.status == 0, "--audio to a FIFO with a reader: done");
		n = et_fifo_drain(fd, wav, sizeof(wav));
		ok(n == 44 + EV3_SPEAKER_RATE && memcmp(wav, "RIFF\xff\xff\xff\xff", 8) == 0,
		   "the reader got the header, its sizes 'to the end', and 0.5 s of samples (%zu bytes)", n);
		close(fd);
	} else {
		tap_skip(2, "cannot open the FIFO");
	}
	unlink(fifo);
}

/* Reads a little-endian 32-bit value at p. */
static uint32_t le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* --audio to a file: the sizes patched at the end; the app's A4 is in it. */
static void test_wav(void)
{
	char wav[64];
	const char *args[] = { "--seconds", "2", "--quiet", "--audio", wav, NULL };
	unsigned char h[44];
	unsigned long high = 0;
	FILE *f;
	int c0, c1;

	snprintf(wav, sizeof(wav), "%s/out.wav", tmp);
	ok(run_files(args, NULL) && run.status == 0, "--audio FILE: done");
	f = fopen(wav, "rb");
	ok(f && fread(h, 1, sizeof(h), f) == sizeof(h) && memcmp(h, "RIFF", 4) == 0 &&
	   le32(h + 40) == 2 * 2 * EV3_SPEAKER_RATE && le32(h + 4) == 36 + le32(h + 40),
	   "the header's sizes are the 2 s recorded");
	while (f && (c0 = getc(f)) != EOF && (c1 = getc(f)) != EOF)
		high += (unsigned long)(c0 | c1 << 8);
	/* volume 50 (25 % duty) for the 200 ms tone */
	ok(high > 0.25 * 0.2 * EV3_SPEAKER_RATE * EV3_SPEAKER_FULL * 0.95 &&
	   high < 0.25 * 0.2 * EV3_SPEAKER_RATE * EV3_SPEAKER_FULL * 1.05, "the tone is in the samples");
	if (f)
		fclose(f);
	unlink(wav);
}

/* --fault up to 16 times, the 17th refused. */
static void test_fault_limit(void)
{
	const char *args[64] = { "--seconds", "0.1", "--quiet" };
	unsigned n = 3;

	for (unsigned i = 0; i < EV3SIM_RUN_MAX_FAULTS; i++) {
		args[n++] = "--fault";
		args[n++] = "gyro-drift:0.1";
	}
	args[n] = NULL;
	ok(run_files(args, NULL) && run.status == 0, "16 faults are accepted");
	args[n++] = "--fault";
	args[n++] = "gyro-drift:0.1";
	args[n] = NULL;
	ok(run_files(args, NULL) && run.status == 2 && strstr(run.err, "too many faults (16)"),
	   "the 17th is refused, naming the limit");
}

/* Whether path holds exactly text. */
static bool holds(const char *path, const char *text)
{
	char buf[64] = "";
	FILE *f = fopen(path, "r");
	size_t n = f ? fread(buf, 1, sizeof(buf) - 1, f) : 0;

	if (f)
		fclose(f);
	buf[n] = '\0';
	return f != NULL && strcmp(buf, text) == 0;
}

/* Whether directory dir has no entries. */
static bool empty_dir(const char *dir)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	unsigned n = 0;

	/* cppcheck-suppress readdirCalled ; one thread, and readdir_r is deprecated in glibc */
	while (d && (e = readdir(d)) != NULL)
		n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
	if (d)
		closedir(d);
	return d != NULL && n == 0;
}

/* The app's file calls on the card (--sd), in a current directory of their own. */
static void test_card(void)
{
	static const char *const steps[] = {
		"mkdir /ev3rt", "mkdir /ev3rt/files", "fopen /ev3rt/files/log.txt", "fopen relative",
		"fopen /top.txt", "open", "rename", "stat", "read back", "write_text gone.txt", "remove", "unlink",
	};
	char card[64], cwd[64], here[4096], path[256], line[96];
	const char *args[] = { "--seconds", "1", "--sd", card, NULL };
	const char *no_card[] = { "--seconds", "1", NULL };

	snprintf(card, sizeof(card), "%s/card", tmp);
	snprintf(cwd, sizeof(cwd), "%s/cwd", tmp);
	if (mkdir(card, 0700) != 0 || mkdir(cwd, 0700) != 0 || !getcwd(here, sizeof(here)) || chdir(cwd) != 0)
		tap_bail_out("cannot set up the card and the current directory");
	ok(run_files(args, NULL) && run.status == 0, "the app runs with --sd");
	for (unsigned i = 0; i < sizeof(steps) / sizeof(steps[0]); i++) {
		snprintf(line, sizeof(line), "NOTICE: files: %s ok", steps[i]);
		ok(strstr(run.out, line) != NULL, "%s on the card", steps[i]);
	}
	ok(strstr(run.out, "files: listed 3") != NULL, "opendir lists the three files left");
	ok(strstr(run.out, "files: escape failed") && strstr(run.out, "files: escape relative failed"),
	   "a '..' above the card's root fails");
	snprintf(path, sizeof(path), "%s/ev3rt/files/log.txt", card);
	ok(holds(path, "logged\n"), "/ev3rt/files/log.txt is the card's");
	snprintf(path, sizeof(path), "%s/ev3rt/files/relative.txt", card);
	ok(holds(path, "relative\n"), "a relative path starts at the card's root");
	snprintf(path, sizeof(path), "%s/ev3rt/files/moved.txt", card);
	ok(holds(path, "top\n"), "renamed from the card's root");
	snprintf(path, sizeof(path), "%s/top.txt", card);
	ok(access(path, F_OK) != 0, "and gone from there");
	snprintf(path, sizeof(path), "%s/escaped.txt", tmp);
	ok(access(path, F_OK) != 0 && access("/escaped.txt", F_OK) != 0, "nothing escaped above the card");
	ok(empty_dir(cwd), "nothing in the current directory");

	ok(run_files(no_card, NULL) && run.status == 0, "the app runs without a card");
	ok(strstr(run.out, "files: fopen /ev3rt/files/log.txt failed (19)") != NULL,
	   "without a card fopen fails with ENODEV");
	ok(empty_dir(cwd) && access("/ev3rt/files", F_OK) != 0, "and nothing is written on the host");
	if (chdir(here) != 0)
		tap_bail_out("cannot go back");
	snprintf(path, sizeof(path), "rm -rf '%s' '%s'", card, cwd);
	if (system(path) != 0)
		tap_diag("could not remove %s", tmp);
}

int main(void)
{
	tap_plan(5 + 5 + 3 + 2 + 1 + 12 + 8 + 3);
	if (!mkdtemp(tmp))
		tap_bail_out("no temporary directory");
	test_full_disk();
	test_fifo();
	test_wav();
	test_fault_limit();
	test_card();
	rmdir(tmp);
	return tap_done();
}

/*
 * test_aintc.c — interrupt requests as the AINTC traces them: a request is a
 * 1-ns pulse on its irq signal; several in one nanosecond are one pulse; a
 * request at the nanosecond its predecessor falls is a fall and a rise; the
 * signal's value, change count and last change read the same whether a VCD
 * is open or not (without one, the falls are kept lazily), and the VCD shows
 * each rise and fall.
 */
#define _XOPEN_SOURCE 700
#include <string.h>

#include "tap.h"
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"
#include "text_files_test.h"

#define LINE      60U
#define NSAMPLES  16U

struct sample {
	uint64_t t, value, changes, last;
	bool pending;
};

static struct {
	struct sample s[NSAMPLES];
	unsigned n;
	unsigned isr_runs;
} rec;

static void isr(intptr_t x)
{
	(void)x;
	rec.isr_runs++;
}

static const struct rtos_int_cfg ints[] = { { LINE, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, LINE, isr, 1 } };
static const struct rtos_cfg cfg = { .name = "aintc", .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs) };

/* Records the line's signal as hs_signal_* read it now. */
static void sample(void *arg)
{
	struct hs_signal *sig = hs_trace_find("irq", "int60");
	struct sample *s = &rec.s[rec.n < NSAMPLES ? rec.n++ : NSAMPLES - 1U];

	(void)arg;
	s->t = hs_now();
	s->value = hs_signal_value(sig);
	s->changes = hs_signal_changes(sig);
	s->last = hs_signal_last_change(sig);
	s->pending = hs_intc_pending(LINE);
}

/* Requests the line (arg: how many times in this nanosecond), then samples. */
static void request(void *arg)
{
	for (uintptr_t i = 0; i < (uintptr_t)arg; i++)
		hs_intc_raise(LINE);
	sample(NULL);
}

/* Runs the request pattern, writing vcd if not NULL; false if boot failed. */
static bool run(const char *vcd)
{
	static const struct { uint64_t t; uintptr_t requests; } plan[] = {
		{ 1000, 3 }, { 3000, 1 }, { 3001, 1 }, { 3001, 1 }, { 9000, 2 },
	};
	static const uint64_t reads[] = { 1001, 2000, 3002, 5000, 9001 };
	struct hs_scenario scn = { .rtos = &cfg, .vcd_path = vcd };

	memset(&rec, 0, sizeof(rec));
	if (hs_sim_boot(&scn) != E_OK)
		return false;
	for (unsigned i = 0; i < sizeof(plan) / sizeof(plan[0]); i++)
		hs_sim_at(plan[i].t, request, (void *)plan[i].requests);
	for (unsigned i = 0; i < sizeof(reads) / sizeof(reads[0]); i++)
		hs_sim_at(reads[i], sample, NULL);
	hs_sim_run_until(20000);
	sample(NULL);
	hs_sim_shutdown();
	return true;
}

/* The changes of the 1-bit signal `$var wire 1 ID name` in the VCD text in,
 * each under its timestamp ("#1000\n0\n1\n#1001\n0\n"), into out: the file has
 * the RTOS's timeline too (the ISR's runs), whose changes sit between them. */
static void signal_changes(const char *in, const char *name, char *out, size_t len)
{
	const char *time = NULL, *written = NULL;
	char id[8] = "", var_id[8], var[64];
	size_t n = 0;

	out[0] = '\0';
	for (const char *line = in; *line != '\0'; line += strcspn(line, "\n") + (line[strcspn(line, "\n")] == '\n')) {
		size_t l = strcspn(line, "\n");

		if (sscanf(line, "$var wire 1 %7s %63s $end", var_id, var) == 2 && strcmp(var, name) == 0)
			snprintf(id, sizeof(id), "%s", var_id);
		if (line[0] == '#') {
			time = line;
		} else if (id[0] != '\0' && l == 1 + strlen(id) && (line[0] == '0' || line[0] == '1') &&
			   strncmp(line + 1, id, strlen(id)) == 0 && n + 48 < len) {
			if (time != NULL && time != written) {
				n += (size_t)snprintf(out + n, len - n, "%.*s\n", (int)strcspn(time, "\n"), time);
				written = time;
			}
			n += (size_t)snprintf(out + n, len - n, "%c\n", line[0]);
		}
	}
}

int main(void)
{
	char dir[] = "/tmp/test_aintc_XXXXXX";
	static char vcd_text[1 << 16];
	char vcd_path[64], vcd[4096];
	struct sample lazy[NSAMPLES];
	unsigned n_lazy;
	const struct sample *last;

	tap_plan(8);
	tf_make_scratch_dir(dir);
	snprintf(vcd_path, sizeof(vcd_path), "%s/run.vcd", dir);

	if (!run(NULL))
		tap_bail_out("boot failed");
	memcpy(lazy, rec.s, sizeof(lazy));
	n_lazy = rec.n;
	is_int(rec.isr_runs, 5, "one delivery per event with requests, however many it made");
	ok(lazy[0].t == 1000 && lazy[0].value == 1 && lazy[0].changes == 2 && lazy[0].last == 1000,
	   "three requests in one nanosecond: one rise (after the declaration's 0)");
	ok(lazy[1].t == 1001 && lazy[1].value == 0 && lazy[1].changes == 3 && lazy[1].last == 1001,
	   "it falls 1 ns later, read without any other trace activity");
	ok(lazy[4].t == 3001 && lazy[4].value == 1 && lazy[4].changes == 6 && lazy[4].last == 3001,
	   "a request as the previous pulse falls: a fall and a rise at the same time");
	last = &lazy[n_lazy - 1U];
	ok(last->t == 20000 && last->value == 0 && last->changes == 9 && last->last == 9001 && !last->pending,
	   "at the end: low, 4 pulses counted, the last fall at 9001 ns, nothing latched");

	if (!run(vcd_path))
		tap_bail_out("boot with a VCD failed");
	ok(rec.n == n_lazy && memcmp(rec.s, lazy, sizeof(lazy)) == 0,
	   "with a VCD open the signal reads the same at every sample");
	tf_read_text(vcd_path, vcd_text, sizeof(vcd_text));
	signal_changes(vcd_text, "int60", vcd, sizeof(vcd));
	ok(strstr(vcd, "#1000\n0\n1\n#1001\n0\n#3000\n1\n") && strstr(vcd, "#9000\n1\n#9001\n0\n"),
	   "the VCD has the rises and falls (the first after the declaration's 0)");
	ok(strstr(vcd, "#3001\n0\n1\n#3002\n0\n") != NULL,
	   "the VCD has the fall at 3001 ns before the rise in the same nanosecond");
	tf_remove_tree(dir);
	return tap_done();
}

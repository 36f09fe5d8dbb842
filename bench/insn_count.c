/*
 * insn_count.c — counts the ARM instructions of measured calls in a QEMU
 * execution log (`qemu-arm -d in_asm,exec,nochain`, optionally -singlestep).
 *
 *   insn_count [-r ROOT] SYMS [-m FUNC]... [-w OPEN CLOSE] [-p] < log
 *
 * SYMS is `arm-linux-gnueabi-nm -n -S -l --defined-only` of the binary: it
 * gives every function's address range and source file (ROOT, the
 * repository's absolute path, is cut off the file names before they are
 * classified; -r comes before SYMS).  The log is read as
 * a stream (a FIFO in practice: it is gigabytes for 10 000 calls):
 *   - "IN:" blocks (in_asm) give each translation block's instructions: their
 *     number, and whether the block ends in a call (bl, blx, mov lr,pc + jump);
 *   - "Trace" lines (exec, with nochain every executed block is logged) give
 *     each executed block's PC;
 *   - "Stopped execution of TB chain before" takes back the block just logged
 *     (it was not executed; QEMU runs and logs it again).
 * A measured call starts when a block at the entry of a FUNC is entered by a
 * call while a window is open (between calls of OPEN and CLOSE), and ends
 * when the block at its return address runs.  Inside, a shadow call stack
 * follows calls, tail calls and returns, so each instruction is attributed
 * to its function and to a class (docs/bench.md has the rules):
 *   api, hack, driver, linux_compat    api/src/, hacks/, ev3_drivers/ (the
 *            drivers' code, compiled inside the hacks), linux_compat/   counted
 *   kernel   the kernel's service calls (rtos_stub svc/system/sem/flg/task/
 *            time/interrupt.c, rtos_host_now, rtos_host_cal_svc) counted
 *   libc     the C library (memcpy, division helpers)          counted
 *   access   sil_host_read/sil_host_write: one register access, counted as
 *            1 instruction, everything below them excluded
 *   lock     sil_host_loc_int (3) / sil_host_unl_int (1): the CPSR
 *            instructions of SIL_LOC_INT/SIL_UNL_INT on the AM1808
 *   sim      host_sim, the host kernel's simulation internals (event queue,
 *            coroutines, run loop, trace, bug reports, boot, syslog), the
 *            rest of sil_host.c, and anything they call       excluded
 * Output, one CSV record per line:
 *   call,FUNC,calls,raw_avg,raw_min,raw_max,eq_avg,eq_min,eq_max,eq_p50,eq_p90,eq_p99
 *   class,FUNC,CLASS,raw_per_call,eq_per_call
 *   fn,FUNC,FUNCTION,CLASS,raw_per_call,eq_per_call      (every function reached)
 *   libc,FUNC,CALLER,eq_per_call     counted C library code by the function it works for
 *   all,FUNCTION,CLASS,instructions                    (-p: the whole log, per function)
 *   log,blocks,instructions,instructions_in_calls,windows_closed
 */
#define _POSIX_C_SOURCE 200809L
#include <inttypes.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum fn_class {
	CL_API, CL_HACK, CL_DRIVER, CL_LXC, CL_KERNEL, CL_LIBC, CL_ACCESS, CL_LOCK, CL_BENCH,
	CL_SIM, NCLASS
};

static const char *const class_name[NCLASS] = {
	"api", "hack", "driver", "linux_compat", "kernel", "libc", "access", "lock", "bench", "sim",
};

struct sym {
	uint32_t addr, end;
	char *name;
	enum fn_class cls;
	unsigned equiv_cost;     /* access/lock stand-ins: instructions they count as */
};

static struct sym *syms;
static size_t nsyms;

/* What the translation log said about the block starting at pc. */
struct tb_info {
	uint32_t pc;             /* 0: empty slot */
	uint32_t end;            /* address after its last instruction */
	uint16_t ninsns;
	bool ends_in_call;
	int32_t sym;             /* index in syms, -1 if outside every function */
};

#define TB_HASH_BITS 20
#define TB_HASH_SIZE (1U << TB_HASH_BITS)
static struct tb_info *tbs;

#define MAX_MEASURED 8
#define MAX_DEPTH    512

struct measured {
	const char *name;
	int32_t sym;
	uint64_t calls;
	uint64_t raw_sum, raw_min, raw_max;
	uint64_t eq_sum, eq_min, eq_max;
	uint64_t *fn_raw, *fn_eq;           /* per symbol, summed over calls */
	uint64_t *libc_eq;                  /* counted C library instructions per calling function */
	uint64_t *eq_each;                  /* every call's count, for the percentiles */
	size_t eq_each_cap;
	uint64_t cls_raw[NCLASS], cls_eq[NCLASS];
};

static struct measured meas[MAX_MEASURED];
static uint64_t *all_insns;     /* -p: per symbol over the whole log */
static unsigned nmeas;

struct frame {
	uint32_t ret;
	bool excluded;
	int32_t owner;          /* the function the frame's C library code works for */
};

/* The state of the stream. */
static struct {
	int32_t open_sym, close_sym;
	bool window;
	struct measured *call;        /* the call in progress, or NULL */
	struct frame stack[MAX_DEPTH];
	unsigned depth;
	uint64_t raw, eq;
	const struct tb_info *prev;   /* the block executed before */
	uint64_t blocks, insns, insns_in_calls;
	unsigned windows_closed;
} st;

/* ---- symbols ---- */

static const char *repo_root;   /* -r: source paths are taken relative to it */

static bool has_prefix(const char *s, const char *prefix)
{
	return strncmp(s, prefix, strlen(prefix)) == 0;
}

/* The class of a function from its source file (relative to the repository) and name. */
static enum fn_class classify(const char *name, const char *path, unsigned *cost)
{
	static const struct { const char *dir; enum fn_class cls; } target_dirs[] = {
		{ "api/src/", CL_API }, { "hacks/", CL_HACK }, { "ev3_drivers/", CL_DRIVER },
		{ "linux_compat/", CL_LXC },
	};
	static const char *const svc_files[] = {
		"rtos_stub/src/host/svc.c", "rtos_stub/src/host/system.c", "rtos_stub/src/host/sem.c",
		"rtos_stub/src/host/flg.c", "rtos_stub/src/host/task.c", "rtos_stub/src/host/time.c",
		"rtos_stub/src/host/interrupt.c",
	};

	*cost = 0;
	if (strcmp(name, "sil_host_read") == 0 || strcmp(name, "sil_host_write") == 0) {
		*cost = 1;
		return CL_ACCESS;
	}
	if (strcmp(name, "sil_host_loc_int") == 0) {
		*cost = 3;
		return CL_LOCK;
	}
	if (strcmp(name, "sil_host_unl_int") == 0) {
		*cost = 1;
		return CL_LOCK;
	}
	/* the clock, and the extended service call's dispatch (HRP2's trap handler
	 * on the brick; cal_svc is an inline trap there, this function on the host) */
	if (strcmp(name, "rtos_host_now") == 0 || strcmp(name, "rtos_host_cal_svc") == 0)
		return CL_KERNEL;
	if (path == NULL)
		return CL_LIBC;
	for (size_t i = 0; i < sizeof(target_dirs) / sizeof(target_dirs[0]); i++)
		if (has_prefix(path, target_dirs[i].dir))
			return target_dirs[i].cls;
	if (strncmp(name, "rtos_host_", 10) == 0 || strncmp(name, "hs_", 3) == 0)
		return CL_SIM;
	/* service-call files, minus the coroutine switch of the host kernel */
	for (size_t i = 0; i < sizeof(svc_files) / sizeof(svc_files[0]); i++)
		if (strcmp(path, svc_files[i]) == 0)
			return strcmp(name, "task_switch") == 0 || strcmp(name, "switch_from_task") == 0 ?
			       CL_SIM : CL_KERNEL;
	if (has_prefix(path, "bench/"))
		return CL_BENCH;
	if (has_prefix(path, "rtos_stub/") || has_prefix(path, "host_sim/"))
		return CL_SIM;
	return CL_LIBC;
}

static int sym_cmp(const void *a, const void *b)
{
	const struct sym *x = a, *y = b;

	return x->addr < y->addr ? -1 : x->addr > y->addr;
}

/* Reads nm's output: "ADDR [SIZE] TYPE NAME[\tPATH:LINE]", text symbols only. */
static void load_syms(const char *path)
{
	FILE *f = fopen(path, "r");
	char *line = NULL;
	size_t cap = 0, alloc = 0;

	if (!f) {
		perror(path);
		exit(2);
	}
	while (getline(&line, &cap, f) > 0) {
		char *p = line, *tok[4], *file = NULL, *tab;
		int n = 0;
		unsigned long addr, size = 0;
		char type;
		const char *name;

		line[strcspn(line, "\n")] = '\0';
		tab = strchr(line, '\t');
		if (tab) {
			*tab = '\0';
			file = tab + 1;
			*strrchr(file, ':') = '\0';
			/* absolute, or "./"-relative when the build mapped its directory to "." */
			if (repo_root && has_prefix(file, repo_root) && file[strlen(repo_root)] == '/')
				file += strlen(repo_root) + 1;
			else if (has_prefix(file, "./"))
				file += 2;
		}
		while (n < 4 && (tok[n] = strtok(n ? NULL : p, " ")) != NULL)
			n++;
		if (n == 4) {
			addr = strtoul(tok[0], NULL, 16);
			size = strtoul(tok[1], NULL, 16);
			type = tok[2][0];
			name = tok[3];
		} else if (n == 3) {
			addr = strtoul(tok[0], NULL, 16);
			type = tok[1][0];
			name = tok[2];
		} else {
			continue;
		}
		if (type != 't' && type != 'T' && type != 'w' && type != 'W')
			continue;
		if (nsyms == alloc) {
			alloc = alloc ? alloc * 2 : 4096;
			syms = realloc(syms, alloc * sizeof(*syms));
			if (!syms)
				exit(2);
		}
		syms[nsyms].addr = (uint32_t)addr;
		syms[nsyms].end = size ? (uint32_t)(addr + size) : 0;
		syms[nsyms].name = strdup(name);
		syms[nsyms].cls = classify(name, file, &syms[nsyms].equiv_cost);
		nsyms++;
	}
	free(line);
	fclose(f);
	qsort(syms, nsyms, sizeof(*syms), sym_cmp);
	/* symbols without a size reach to the next symbol */
	for (size_t i = 0; i < nsyms; i++)
		if (syms[i].end == 0)
			syms[i].end = i + 1 < nsyms ? syms[i + 1].addr : syms[i].addr + 4;
}

/* The function containing pc, or -1. */
static int32_t sym_at(uint32_t pc)
{
	size_t lo = 0, hi = nsyms;

	while (lo < hi) {
		size_t mid = (lo + hi) / 2;

		if (syms[mid].addr <= pc)
			lo = mid + 1;
		else
			hi = mid;
	}
	if (lo == 0 || pc >= syms[lo - 1].end)
		return -1;
	return (int32_t)(lo - 1);
}

static int32_t sym_named(const char *name)
{
	for (size_t i = 0; i < nsyms; i++)
		if (strcmp(syms[i].name, name) == 0)
			return (int32_t)i;
	fprintf(stderr, "insn_count: no function %s in the symbol table\n", name);
	exit(2);
}

/* ---- translation blocks ---- */

static struct tb_info *tb_slot(uint32_t pc)
{
	uint32_t h = (pc * 2654435761U) >> (32 - TB_HASH_BITS);

	for (;;) {
		struct tb_info *t = &tbs[h];

		if (t->pc == pc || t->pc == 0)
			return t;
		h = (h + 1) & (TB_HASH_SIZE - 1);
	}
}

/* A block executed without a translation record (-singlestep without in_asm):
 * one instruction, call unknown. */
static const struct tb_info *tb_lookup(uint32_t pc)
{
	struct tb_info *t = tb_slot(pc);

	if (t->pc == 0) {
		t->pc = pc;
		t->end = pc + 4;
		t->ninsns = 1;
		t->ends_in_call = false;
		t->sym = sym_at(pc);
	}
	return t;
}

/* The translation being read from an "IN:" block. */
static struct {
	bool active;
	uint32_t first, last;
	unsigned n, last_bytes;
	bool prev_sets_lr, last_is_call;
} tr;

static void tr_finish(void)
{
	struct tb_info *t;

	if (!tr.active || tr.n == 0) {
		tr.active = false;
		return;
	}
	t = tb_slot(tr.first);
	t->pc = tr.first;
	t->end = tr.last + tr.last_bytes;
	t->ninsns = (uint16_t)tr.n;
	t->ends_in_call = tr.last_is_call;
	t->sym = sym_at(tr.first);
	tr.active = false;
}

/* Whether a mnemonic is a call: bl, blx, or either with a condition (blne, blxeq). */
static bool is_call_mnemonic(const char *mn)
{
	static const char conds[] = "eqnecshsccloplmivsvchilsgeltgtleal";
	size_t len = strcspn(mn, " \t\n");
	const char *cond;

	if (strncmp(mn, "bl", 2) != 0)
		return false;
	if (len == 2 || (len == 3 && mn[2] == 'x'))
		return true;
	if (len == 4)
		cond = mn + 2;
	else if (len == 5 && mn[2] == 'x')
		cond = mn + 3;
	else
		return false;
	for (size_t i = 0; conds[i]; i += 2)
		if (cond[0] == conds[i] && cond[1] == conds[i + 1])
			return true;
	return false;
}

/* "0x00012308:  e3a0b000  mov      fp, #0" inside an IN: block. */
static void tr_insn(const char *line)
{
	char *p;
	uint32_t addr = (uint32_t)strtoul(line + 2, &p, 16);
	const char *enc, *mn;
	size_t enc_len;
	bool is_call, writes_pc;

	if (*p != ':')
		return;
	enc = p + 1;
	while (*enc == ' ')
		enc++;
	enc_len = strspn(enc, "0123456789abcdef");
	mn = enc + enc_len;
	while (*mn == ' ')
		mn++;
	is_call = is_call_mnemonic(mn);
	writes_pc = strstr(mn, "pc") != NULL && (strncmp(mn, "ldr", 3) == 0 || strncmp(mn, "bx", 2) == 0 ||
						  strncmp(mn, "mov", 3) == 0);
	if (tr.n == 0)
		tr.first = addr;
	tr.last = addr;
	tr.last_bytes = enc_len == 4 ? 2U : 4U;
	tr.last_is_call = is_call || (tr.prev_sets_lr && writes_pc);
	tr.prev_sets_lr = strncmp(mn, "mov", 3) == 0 && strstr(mn, "lr, pc") != NULL;
	tr.n++;
}

/* ---- counting ---- */

static void call_end(void)
{
	struct measured *m = st.call;

	m->calls++;
	m->raw_sum += st.raw;
	m->eq_sum += st.eq;
	if (m->calls == 1 || st.raw < m->raw_min)
		m->raw_min = st.raw;
	if (st.raw > m->raw_max)
		m->raw_max = st.raw;
	if (m->calls == 1 || st.eq < m->eq_min)
		m->eq_min = st.eq;
	if (st.eq > m->eq_max)
		m->eq_max = st.eq;
	if (m->calls > m->eq_each_cap) {
		m->eq_each_cap = m->eq_each_cap ? m->eq_each_cap * 2 : 1024;
		m->eq_each = realloc(m->eq_each, m->eq_each_cap * sizeof(uint64_t));
		if (!m->eq_each)
			exit(2);
	}
	m->eq_each[m->calls - 1] = st.eq;
	st.call = NULL;
}

/* One executed block. */
static void exec_block(const struct tb_info *t)
{
	const struct tb_info *prev = st.prev;
	bool entered_by_call = prev && prev->ends_in_call && t->pc != prev->end;
	const struct sym *s = t->sym >= 0 ? &syms[t->sym] : NULL;
	bool at_entry = s && s->addr == t->pc;

	st.prev = t;
	st.blocks++;
	st.insns += t->ninsns;
	if (t->sym >= 0 && all_insns)
		all_insns[t->sym] += t->ninsns;
	if (t->sym >= 0 && t->sym == st.open_sym && at_entry)
		st.window = true;
	else if (t->sym >= 0 && t->sym == st.close_sym && at_entry && st.window) {
		st.window = false;
		st.windows_closed++;
	}

	if (st.call == NULL) {
		if (!st.window || !at_entry || !entered_by_call)
			return;
		for (unsigned i = 0; i < nmeas; i++) {
			if (meas[i].sym == t->sym) {
				st.call = &meas[i];
				st.depth = 1;
				st.stack[0].ret = prev->end;
				st.stack[0].excluded = false;
				st.stack[0].owner = t->sym;
				st.raw = st.eq = 0;
				break;
			}
		}
		if (st.call == NULL)
			return;
	} else {
		/* a return to a frame on the shadow stack (the innermost that matches) */
		for (unsigned d = st.depth; d-- > 0;) {
			if (st.stack[d].ret == t->pc) {
				st.depth = d;
				break;
			}
		}
		if (st.depth == 0) {
			call_end();
			return;
		}
		if (entered_by_call) {
			struct frame *top = &st.stack[st.depth - 1];
			bool excl = top->excluded || (s && (s->cls == CL_SIM || s->equiv_cost));

			if (s && s->equiv_cost && !top->excluded)
				st.eq += s->equiv_cost, st.call->cls_eq[s->cls] += s->equiv_cost;
			if (st.depth < MAX_DEPTH) {
				bool callee_libc = !s || s->cls == CL_LIBC;
				bool caller_libc = prev->sym < 0 || syms[prev->sym].cls == CL_LIBC;

				st.stack[st.depth].ret = prev->end;
				st.stack[st.depth].excluded = excl;
				st.stack[st.depth].owner = !callee_libc ? t->sym :
							   caller_libc ? top->owner : prev->sym;
				st.depth++;
			}
		} else if (at_entry && prev && prev->sym != t->sym &&
			   (s->cls == CL_SIM || s->equiv_cost) && !st.stack[st.depth - 1].excluded) {
			/* a tail call into excluded code: the rest of this frame is excluded */
			st.stack[st.depth - 1].excluded = true;
			if (s->equiv_cost)
				st.eq += s->equiv_cost, st.call->cls_eq[s->cls] += s->equiv_cost;
		}
	}

	st.raw += t->ninsns;
	st.insns_in_calls += t->ninsns;
	{
		enum fn_class c = s ? s->cls : CL_LIBC;  /* unnamed code is the C library's */
		bool counted = !st.stack[st.depth - 1].excluded;

		st.call->cls_raw[c] += t->ninsns;
		if (t->sym >= 0)
			st.call->fn_raw[t->sym] += t->ninsns;
		if (counted) {
			st.eq += t->ninsns;
			st.call->cls_eq[c] += t->ninsns;
			if (t->sym >= 0)
				st.call->fn_eq[t->sym] += t->ninsns;
			if (c == CL_LIBC && st.stack[st.depth - 1].owner >= 0)
				st.call->libc_eq[st.stack[st.depth - 1].owner] += t->ninsns;
		}
	}
}

/* The PC in "Trace 0: 0x... [cs_base/PC/flags/cflags] sym". */
static bool trace_pc(const char *line, uint32_t *pc)
{
	const char *b = strchr(line, '['), *slash;

	if (!b || !(slash = strchr(b, '/')))
		return false;
	*pc = (uint32_t)strtoul(slash + 1, NULL, 16);
	return true;
}

static void read_log(FILE *in)
{
	char *line = NULL;
	size_t cap = 0;
	const struct tb_info *pending = NULL;   /* executed unless the next line takes it back */

	while (getline(&line, &cap, in) > 0) {
		uint32_t pc;

		if (line[0] == 'T' && strncmp(line, "Trace ", 6) == 0) {
			tr_finish();
			if (!trace_pc(line, &pc))
				continue;
			if (pending)
				exec_block(pending);
			pending = tb_lookup(pc);
		} else if (line[0] == 'S' && strncmp(line, "Stopped execution", 17) == 0) {
			const char *b = strchr(line, '[');

			if (pending && b && (uint32_t)strtoul(b + 1, NULL, 16) == pending->pc)
				pending = NULL;
		} else if (strncmp(line, "IN:", 3) == 0) {
			tr_finish();
			memset(&tr, 0, sizeof(tr));
			tr.active = true;
		} else if (tr.active && line[0] == '0' && line[1] == 'x') {
			tr_insn(line);
		} else if (tr.active && (line[0] == '\n' || line[0] == '-')) {
			tr_finish();
		}
	}
	if (pending)
		exec_block(pending);
	free(line);
}

static double per_call(uint64_t v, uint64_t calls)
{
	return calls ? (double)v / (double)calls : 0.0;
}

static int u64_cmp(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return x < y ? -1 : x > y;
}

/* The p-th percentile of the sorted counts (nearest rank). */
static uint64_t percentile(const uint64_t *sorted, uint64_t n, unsigned p)
{
	uint64_t rank = (n * p + 99U) / 100U;

	return n ? sorted[rank ? rank - 1 : 0] : 0;
}

static void report(void)
{
	for (unsigned i = 0; i < nmeas; i++) {
		struct measured *m = &meas[i];

		if (m->calls)
			qsort(m->eq_each, m->calls, sizeof(uint64_t), u64_cmp);
		printf("call,%s,%" PRIu64 ",%.1f,%" PRIu64 ",%" PRIu64 ",%.1f,%" PRIu64 ",%" PRIu64
		       ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 "\n",
		       m->name, m->calls, per_call(m->raw_sum, m->calls), m->raw_min, m->raw_max,
		       per_call(m->eq_sum, m->calls), m->eq_min, m->eq_max,
		       percentile(m->eq_each, m->calls, 50), percentile(m->eq_each, m->calls, 90),
		       percentile(m->eq_each, m->calls, 99));
		for (unsigned c = 0; c < NCLASS; c++)
			if (m->cls_raw[c] || m->cls_eq[c])
				printf("class,%s,%s,%.1f,%.1f\n", m->name, class_name[c],
				       per_call(m->cls_raw[c], m->calls), per_call(m->cls_eq[c], m->calls));
		for (size_t s = 0; s < nsyms; s++)
			if (m->fn_raw[s])
				printf("fn,%s,%s,%s,%.1f,%.1f\n", m->name, syms[s].name,
				       class_name[syms[s].cls], per_call(m->fn_raw[s], m->calls),
				       per_call(m->fn_eq[s], m->calls));
		for (size_t s = 0; s < nsyms; s++)
			if (m->libc_eq[s])
				printf("libc,%s,%s,%.1f\n", m->name, syms[s].name,
				       per_call(m->libc_eq[s], m->calls));
	}
	for (size_t i = 0; all_insns && i < nsyms; i++)
		if (all_insns[i])
			printf("all,%s,%s,%" PRIu64 "\n", syms[i].name, class_name[syms[i].cls], all_insns[i]);
	printf("log,%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%u\n", st.blocks, st.insns, st.insns_in_calls,
	       st.windows_closed);
}

int main(int argc, char **argv)
{
	const char *open_name = NULL, *close_name = NULL;
	int first = 1;

	if (argc > 2 && strcmp(argv[1], "-r") == 0) {
		repo_root = argv[2];
		first = 3;
	}
	if (argc <= first) {
		fprintf(stderr, "usage: insn_count [-r ROOT] SYMS [-m FUNC]... [-w OPEN CLOSE] [-p] < log\n");
		return 2;
	}
	load_syms(argv[first]);
	tbs = calloc(TB_HASH_SIZE, sizeof(*tbs));
	if (!tbs)
		return 2;
	st.open_sym = st.close_sym = -1;
	st.window = true;
	for (int i = first + 1; i < argc; i++) {
		if (strcmp(argv[i], "-m") == 0 && i + 1 < argc && nmeas < MAX_MEASURED) {
			meas[nmeas].name = argv[++i];
			meas[nmeas].sym = sym_named(meas[nmeas].name);
			meas[nmeas].fn_raw = calloc(nsyms, sizeof(uint64_t));
			meas[nmeas].fn_eq = calloc(nsyms, sizeof(uint64_t));
			meas[nmeas].libc_eq = calloc(nsyms, sizeof(uint64_t));
			if (!meas[nmeas].fn_raw || !meas[nmeas].fn_eq || !meas[nmeas].libc_eq)
				return 2;
			nmeas++;
		} else if (strcmp(argv[i], "-p") == 0) {
			all_insns = calloc(nsyms, sizeof(uint64_t));
			if (!all_insns)
				return 2;
		} else if (strcmp(argv[i], "-w") == 0 && i + 2 < argc) {
			open_name = argv[++i];
			close_name = argv[++i];
		} else {
			fprintf(stderr, "insn_count: bad argument %s\n", argv[i]);
			return 2;
		}
	}
	if (open_name) {
		st.open_sym = sym_named(open_name);
		st.close_sym = sym_named(close_name);
		st.window = false;
	}
	read_log(stdin);
	report();
	return 0;
}

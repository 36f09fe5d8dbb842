/*
 * test_fuzz_cfg.c — fuzz harness: the configurator's pass 1 and its output
 * (cfg_gen) on any text, as the C preprocessor leaves an app.cfg (ev3cfg
 * refuses a NUL byte before, so the text ends at the first one).  Every
 * error is reported and counted, never a crash or a read out of bounds; a
 * configuration without errors numbers every ATT_MOD and writes its files.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cfg_gen.h"

#define FUZZ_NAME "cfg"

/* INCLUDE("file"): a small configuration of its own, at most two deep. */
static int include_fixed(struct cfg_ctx *ctx, const char *file, const char *from_file, int from_line, void *arg)
{
	int *depth = arg;

	(void)from_file;
	(void)from_line;
	if (*depth >= 2)
		return 0;
	(*depth)++;
	cfg_parse(ctx, "# 1 \"inc.cfg\"\nCRE_SEM(INCLUDED_SEM, { TA_TPRI, 0, 1 });\nINCLUDE(\"again.cfg\");\n", file);
	(*depth)--;
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const char *const objects[] = { "obj/app.o", "obj/lib/util.o" };
	static FILE *sink;
	char *text = malloc(size + 1);
	struct cfg_ctx *ctx;
	int depth = 0;

	if (text == NULL)
		return 0;
	if (sink == NULL && (sink = fopen("/dev/null", "w")) == NULL)
		abort();
	memcpy(text, data, size);
	text[size] = '\0';
	ctx = cfg_new(sink, include_fixed, &depth);
	if (cfg_parse(ctx, text, "app.cfg") < 0 || cfg_finish(ctx) < 0 || cfg_bind_modules(ctx, objects, 2) < 0)
		abort();
	if (cfg_errors(ctx) == 0) {
		cfg_write_header(ctx, sink, "fuzz_cfg");
		cfg_write_source(ctx, sink, "fuzz_cfg", "kernel_cfg.c");
		for (int m = 1; m <= cfg_module_count(ctx); m++) {
			if (cfg_module_path(ctx, m) == NULL || cfg_module_object(ctx, m) == NULL)
				abort();
			cfg_write_module_script(ctx, sink, m);
		}
	}
	cfg_free(ctx);
	free(text);
	return 0;
}

#include "fuzz_replay.h"

/*
 * ev3cfg — the app.cfg configurator: a host tool the build runs to turn a
 * TOPPERS-style configuration file into kernel tables.
 *
 *   ev3cfg -o OUTDIR [-I dir]... [-D name[=value]]... [--cpp CMD] [--symbol NAME]
 *          [--kernel auto|hrp2|hrp3] [--time-hint FILE:LINE:CALL] [--library] [--object path.o]... app.cfg
 *
 * app.cfg is run through the C preprocessor (CMD, default "cpp", with
 * -DTOPPERS_MACRO_ONLY -DTOPPERS_CFG1 -DTOPPERS_CFG1_OUT and the -I/-D options:
 * TOPPERS_CFG1_OUT keeps ev3api.h from including the kernel_cfg.h this pass
 * writes, as in TOPPERS's configurator), then its static
 * APIs are read: INCLUDE, DOMAIN, CRE_TSK, CRE_SEM, CRE_FLG, CRE_DTQ, CRE_PDQ,
 * CRE_MTX, CRE_CYC, CRE_ALM, EV3_CRE_CYC, ATT_MOD, ATT_INI, ATT_TER, DEF_SVC,
 * CFG_INT, ATT_ISR, ATA_SEC, and ev3lx's EV3LX_INCLUDE_TABLE(symbol) (an existing
 * struct rtos_cfg, such as the platform's, joined to this one).  Anything
 * else in a .cfg file's text is an error, HRP2's other static APIs by name;
 * so is a NUL byte.  It writes:
 *
 *   OUTDIR/kernel_profile.h  the kernel profile the app is built for, which the
 *                          build includes first in every source of the app:
 *                          EV3LX_KERNEL_HRP3 for TOPPERS/HRP3 (EV3RT 1.x, time in us),
 *                          from --kernel, or (auto, the default) HRP3 when a CRE_CYC
 *                          or CRE_ALM is in HRP3's notification form
 *   OUTDIR/kernel_cfg.h    #define of every object ID and domain; the apps include it
 *   OUTDIR/kernel_cfg.c    the rtos_cfg tables and `const struct rtos_cfg NAME`
 *                          (default ev3rt_app_cfg), INCLUDEing the tables named
 *   OUTDIR/modules.txt     one line "path/object.o OUTDIR/ev3mod_N.ld" per ATT_MOD
 *                          (ATT_MOD("x.o") names the --object whose file name is x.o)
 *   OUTDIR/ev3mod_N.ld     the relocatable-link script that gathers that object's
 *                          code and data where kernel_cfg.c finds their bounds
 *
 * --library reads a library's fragment (cfg/ev3lx.cfg, which a firmware's
 * .cfg INCLUDEs for HRP2's configurator): its IDs are counted from the top of
 * each kind's range, (TNUM_TSKID - n) in kernel_cfg.h, so that the library
 * built with them boots beside any application's configuration, whose IDs
 * start at 1.
 *
 * Errors name the file, line and static API ("app.cfg:7: error: CRE_TSK
 * (MAIN_TASK): ..."); value errors are found by the compiler on kernel_cfg.c
 * and reported at the same place (#line).  Exit status 0, 1 on configuration
 * errors, 2 on usage or I/O errors.
 *
 * The build drives it through mk/ev3rt_app.mk's function ev3rt_app (see
 * docs/ev3rt-apps.md, "The configurator"): configure, compile the app and
 * kernel_cfg.c, relink every ATT_MOD object with its script, link.
 */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cfg_gen.h"

#define MAX_ARGS 128
#define MAX_INCLUDED 32

struct tool {
	const char *cpp;
	const char *incdirs[MAX_ARGS];
	int nincdirs;
	const char *defs[MAX_ARGS];
	int ndefs;
	const char *objects[MAX_ARGS];  /* --object: the app's objects, for ATT_MOD */
	int nobjects;
	char *included[MAX_INCLUDED];   /* configuration files read so far */
	int nincluded;
};

/* Reads a whole file or command output (its length in *lenp); NULL on error. */
static char *read_stream(FILE *f, size_t *lenp)
{
	size_t cap = 8192, len = 0;
	char *buf = malloc(cap);

	if (buf == NULL)
		return NULL;
	for (;;) {
		size_t n;

		if (cap - len < 4096) {
			char *nb = realloc(buf, cap *= 2);

			if (nb == NULL) {
				free(buf);
				return NULL;
			}
			buf = nb;
		}
		n = fread(buf + len, 1, cap - len - 1, f);
		len += n;
		if (n == 0)
			break;
	}
	buf[len] = '\0';
	*lenp = len;
	return buf;
}

/* Reports a NUL byte in a file's text (C text has none, and it would end the
 * text early); true if there is one. */
static bool has_nul(const char *path, const char *text, size_t len)
{
	const char *nul = memchr(text, '\0', len);
	int line = 1;
	const char *line_start = text;

	if (nul == NULL)
		return false;
	for (const char *c = text; c < nul; c++)
		if (*c == '\n') {
			line++;
			line_start = c + 1;
		}
	fprintf(stderr, "%s:%d:%d: error: NUL byte: not C text\n", path, line, (int)(nul - line_start) + 1);
	return true;
}

/* Appends s to the command line, single-quoted for the shell. */
static void append_quoted(char *cmd, size_t size, const char *s)
{
	size_t len = strlen(cmd);

	if (len + 2 < size)
		cmd[len++] = '\'';
	for (; *s && len + 5 < size; s++) {
		if (*s == '\'') {
			memcpy(cmd + len, "'\\''", 4);
			len += 4;
		} else {
			cmd[len++] = *s;
		}
	}
	if (len + 2 < size)
		cmd[len++] = '\'';
	cmd[len++] = ' ';
	cmd[len] = '\0';
}

/* Copies the #include directives of a configuration file into kernel_cfg.c's list. */
static void collect_c_includes(struct cfg_ctx *ctx, const char *raw)
{
	for (const char *line = raw; *line != '\0';) {
		size_t n = strcspn(line, "\n");
		char buf[1024];
		char *p = buf, *end;

		snprintf(buf, sizeof(buf), "%.*s", (int)(n < sizeof(buf) ? n : sizeof(buf) - 1), line);
		line += n + (line[n] == '\n');
		while (isspace((unsigned char)*p))
			p++;
		if (*p != '#')
			continue;
		end = p + 1;
		while (isspace((unsigned char)*end))
			end++;
		if (strncmp(end, "include", 7) != 0)
			continue;
		end = p + strlen(p);
		while (end > p && isspace((unsigned char)end[-1]))
			*--end = '\0';
		cfg_add_c_include(ctx, p);
	}
}

/* Preprocesses and parses one configuration file; returns the errors it
 * printed itself (cfg_parse counts its own in ctx). */
static int process_file(struct cfg_ctx *ctx, struct tool *tool, const char *path)
{
	char cmd[8192] = "";
	FILE *f, *pipe;
	char *raw, *text;
	size_t len;
	int status;

	if ((f = fopen(path, "r")) == NULL) {
		fprintf(stderr, "ev3cfg: %s: %s\n", path, strerror(errno));
		return 1;
	}
	raw = read_stream(f, &len);
	fclose(f);
	if (raw == NULL)
		return 1;
	if (has_nul(path, raw, len)) {
		free(raw);
		return 1;
	}
	collect_c_includes(ctx, raw);
	free(raw);
	snprintf(cmd, sizeof(cmd), "%s -x c -DTOPPERS_MACRO_ONLY -DTOPPERS_CFG1 -DTOPPERS_CFG1_OUT ", tool->cpp);
	for (int i = 0; i < tool->nincdirs; i++) {
		strncat(cmd, "-I", sizeof(cmd) - strlen(cmd) - 1);
		append_quoted(cmd, sizeof(cmd), tool->incdirs[i]);
	}
	for (int i = 0; i < tool->ndefs; i++) {
		strncat(cmd, "-D", sizeof(cmd) - strlen(cmd) - 1);
		append_quoted(cmd, sizeof(cmd), tool->defs[i]);
	}
	append_quoted(cmd, sizeof(cmd), path);
	if ((pipe = popen(cmd, "r")) == NULL) {
		fprintf(stderr, "ev3cfg: cannot run %s\n", tool->cpp);
		return 1;
	}
	text = read_stream(pipe, &len);
	status = pclose(pipe);
	if (text == NULL || status != 0) {
		fprintf(stderr, "%s:1: error: the C preprocessor failed (%s)\n", path, tool->cpp);
		free(text);
		return 1;
	}
	if (has_nul(path, text, len)) {
		free(text);
		return 1;
	}
	cfg_parse(ctx, text, path);
	free(text);
	return 0;
}

static bool file_exists(const char *path)
{
	struct stat st;

	return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* INCLUDE("file"): beside the including file, else along the -I path. */
static int include_file(struct cfg_ctx *ctx, const char *file, const char *from_file, int from_line, void *arg)
{
	struct tool *tool = arg;
	char path[4096];
	const char *slash = strrchr(from_file, '/');
	bool found = false;

	if (file[0] == '/') {
		snprintf(path, sizeof(path), "%s", file);
		found = file_exists(path);
	} else {
		snprintf(path, sizeof(path), "%.*s%s", slash != NULL ? (int)(slash - from_file + 1) : 0, from_file, file);
		found = file_exists(path);
		for (int i = 0; !found && i < tool->nincdirs; i++) {
			snprintf(path, sizeof(path), "%s/%s", tool->incdirs[i], file);
			found = file_exists(path);
		}
	}
	if (!found) {
		fprintf(stderr, "%s:%d: error: INCLUDE: \"%s\" not found beside the file or along -I (E_NOEXS)\n",
			from_file, from_line, file);
		return 1;
	}
	for (int i = 0; i < tool->nincluded; i++)
		if (strcmp(tool->included[i], path) == 0) {
			fprintf(stderr, "%s:%d: error: INCLUDE: \"%s\" is included twice (E_OBJ)\n",
				from_file, from_line, file);
			return 1;
		}
	if (tool->nincluded == MAX_INCLUDED) {
		fprintf(stderr, "%s:%d: error: INCLUDE: more than %d files\n", from_file, from_line, MAX_INCLUDED);
		return 1;
	}
	tool->included[tool->nincluded++] = strdup(path);
	return process_file(ctx, tool, path);
}

/* Closes a generated file; 0, or -1 if it could not be written (reported). */
static int close_out(FILE *f, const char *dir, const char *name)
{
	bool failed = ferror(f) != 0;

	if (fclose(f) != 0 || failed) {
		fprintf(stderr, "ev3cfg: %s/%s: cannot write\n", dir, name);
		return -1;
	}
	return 0;
}

/* Opens dir/name for writing; NULL (reported) if it cannot. */
static FILE *open_out(const char *dir, const char *name)
{
	char path[4096];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	if ((f = fopen(path, "w")) == NULL)
		fprintf(stderr, "ev3cfg: %s: %s\n", path, strerror(errno));
	return f;
}

/* Writes the generated files into outdir; 0, or 2 on an I/O error (reported). */
static int write_outputs(const struct cfg_ctx *ctx, const char *outdir, const char *symbol)
{
	FILE *f, *ld;

	if ((f = open_out(outdir, "kernel_profile.h")) == NULL)
		return 2;
	cfg_write_profile(ctx, f);
	if (close_out(f, outdir, "kernel_profile.h") != 0 || (f = open_out(outdir, "kernel_cfg.h")) == NULL)
		return 2;
	cfg_write_header(ctx, f, symbol);
	if (close_out(f, outdir, "kernel_cfg.h") != 0 || (f = open_out(outdir, "kernel_cfg.c")) == NULL)
		return 2;
	cfg_write_source(ctx, f, symbol, "kernel_cfg.c");
	if (close_out(f, outdir, "kernel_cfg.c") != 0 || (f = open_out(outdir, "modules.txt")) == NULL)
		return 2;
	for (int m = 1; m <= cfg_module_count(ctx); m++) {
		char name[64];

		snprintf(name, sizeof(name), "ev3mod_%d.ld", m);
		fprintf(f, "%s %s/%s\n", cfg_module_path(ctx, m), outdir, name);
		if ((ld = open_out(outdir, name)) == NULL) {
			fclose(f);
			return 2;
		}
		cfg_write_module_script(ctx, ld, m);
		if (close_out(ld, outdir, name) != 0) {
			fclose(f);
			return 2;
		}
	}
	return close_out(f, outdir, "modules.txt") != 0 ? 2 : 0;
}

/*
 * --time-hint FILE:LINE:CALL — a wait the app's source writes in microseconds
 * (the build found e.g. tslp_tsk(1000000) there: 1000 s in HRP2's
 * milliseconds, 1 s in HRP3's microseconds).  With --kernel auto and an
 * app.cfg that names no time event, it decides HRP3, and says so; 0, or 1
 * if the hint is malformed (reported).
 */
static int apply_time_hint(struct cfg_ctx *ctx, const char *input, const char *hint)
{
	char file[4096], call[128];
	int line = 0;
	const char *colon = strchr(hint, ':');

	if (colon == NULL || (size_t)(colon - hint) >= sizeof(file) ||
	    sscanf(colon + 1, "%d:%127[^\n]", &line, call) != 2 || line <= 0) {
		fprintf(stderr, "ev3cfg: --time-hint %s: expected FILE:LINE:CALL\n", hint);
		return 1;
	}
	memcpy(file, hint, (size_t)(colon - hint));
	file[colon - hint] = '\0';
	if (cfg_profile_from_source(ctx, file, line, call))
		fprintf(stderr, "%s:%d: note: %s waits in microseconds and %s names no time event: the app is "
			"built for TOPPERS/HRP3 (EV3RT 1.x); --kernel hrp2 builds it for HRP2\n", file, line, call,
			input);
	return 0;
}

static int usage(void)
{
	fputs("usage: ev3cfg -o OUTDIR [-I dir]... [-D name[=value]]... [--cpp CMD] [--symbol NAME]\n"
	      "              [--kernel auto|hrp2|hrp3] [--time-hint FILE:LINE:CALL] [--library] [--object path.o]...\n"
	      "              app.cfg\n", stderr);
	return 2;
}

int main(int argc, char **argv)
{
	struct tool tool = { .cpp = "cpp" };
	const char *outdir = NULL, *symbol = "ev3rt_app_cfg", *input = NULL;
	struct cfg_ctx *ctx;
	int errors, status, profile = CFG_PROFILE_AUTO;
	const char *time_hint = NULL;
	bool library = false;

	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];
		const char *val = NULL;

		if (strcmp(a, "--library") == 0) {
			library = true;
			continue;
		}
		if ((strncmp(a, "-I", 2) == 0 || strncmp(a, "-D", 2) == 0) && a[2] != '\0') {
			val = a + 2;
		} else if (strcmp(a, "-I") == 0 || strcmp(a, "-D") == 0 || strcmp(a, "-o") == 0 ||
			   strcmp(a, "--cpp") == 0 || strcmp(a, "--symbol") == 0 || strcmp(a, "--object") == 0 ||
			   strcmp(a, "--kernel") == 0 || strcmp(a, "--time-hint") == 0) {
			if (++i == argc)
				return usage();
			val = argv[i];
		} else if (a[0] == '-' || input != NULL) {
			return usage();
		} else {
			input = a;
			continue;
		}
		if (a[1] == 'I' && tool.nincdirs < MAX_ARGS)
			tool.incdirs[tool.nincdirs++] = val;
		else if (a[1] == 'D' && tool.ndefs < MAX_ARGS)
			tool.defs[tool.ndefs++] = val;
		else if (a[1] == 'o')
			outdir = val;
		else if (strcmp(a, "--cpp") == 0)
			tool.cpp = val;
		else if (strcmp(a, "--symbol") == 0)
			symbol = val;
		else if (strcmp(a, "--object") == 0 && tool.nobjects < MAX_ARGS)
			tool.objects[tool.nobjects++] = val;
		else if (strcmp(a, "--time-hint") == 0)
			time_hint = val;
		else if (strcmp(a, "--kernel") == 0 && strcmp(val, "auto") == 0)
			profile = CFG_PROFILE_AUTO;
		else if (strcmp(a, "--kernel") == 0 && strcmp(val, "hrp2") == 0)
			profile = CFG_PROFILE_HRP2;
		else if (strcmp(a, "--kernel") == 0 && strcmp(val, "hrp3") == 0 && tool.ndefs < MAX_ARGS) {
			/* the configuration is read as the app's sources are compiled */
			profile = CFG_PROFILE_HRP3;
			tool.defs[tool.ndefs++] = "EV3LX_KERNEL_HRP3=1";
		} else if (strcmp(a, "--kernel") == 0) {
			fprintf(stderr, "ev3cfg: --kernel %s: expected auto, hrp2 or hrp3\n", val);
			return 2;
		} else
			return usage();
	}
	if (input == NULL || outdir == NULL)
		return usage();
	ctx = cfg_new(stderr, include_file, &tool);
	cfg_set_profile(ctx, profile);
	cfg_set_library(ctx, library);
	tool.included[tool.nincluded++] = strdup(input);
	errors = process_file(ctx, &tool, input);
	cfg_finish(ctx);
	cfg_bind_modules(ctx, tool.objects, tool.nobjects);
	if (time_hint != NULL)
		errors += apply_time_hint(ctx, input, time_hint);
	errors += cfg_errors(ctx);
	if (errors > 0) {
		fprintf(stderr, "ev3cfg: %s: %d error%s\n", input, errors, errors == 1 ? "" : "s");
		status = 1;
	} else {
		status = write_outputs(ctx, outdir, symbol);
	}
	cfg_free(ctx);
	for (int i = 0; i < tool.nincluded; i++)
		free(tool.included[i]);
	return status;
}

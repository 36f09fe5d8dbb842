/*
 * cfg_gen.c — the app.cfg configurator's core (see cfg_gen.h).
 *
 * Like the TOPPERS configurator it works in two passes.  Pass 1 (here)
 * reads the static API calls from the preprocessed text, checks their shape
 * (parameter counts, IDs, what must be NULL, which domain may hold what),
 * numbers the objects and writes kernel_cfg.h and kernel_cfg.c.  Pass 2 is
 * the C compiler: the parameters are copied into kernel_cfg.c as written, and
 * every value check that is an integer constant expression (priorities,
 * attributes, sizes) is a _Static_assert placed by #line at the static API's
 * own file and line, so a bad value is reported as "app.cfg:12: ... CRE_TSK
 * (MAIN_TASK): ...".  What only the kernel can see (ID collisions with
 * library tables) is checked again at boot by rtos_host_boot.
 */
#include "cfg_gen.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

enum tok_kind { TK_EOF, TK_ID, TK_NUM, TK_STR, TK_PUNCT };

struct tok {
	enum tok_kind kind;
	char *text;
	bool space;          /* whitespace before it (for copying expressions) */
	bool cfg_text;       /* from a configuration file, not a header it #includes */
	bool bol;            /* first on its line */
	const char *file;
	int line, col;
};

enum api {
	API_CRE_TSK, API_CRE_SEM, API_CRE_FLG, API_CRE_DTQ, API_CRE_PDQ, API_CRE_MTX,
	API_CRE_CYC, API_CRE_ALM, API_EV3_CRE_CYC, API_ATT_MOD, API_ATT_INI, API_ATT_TER,
	API_DEF_SVC, API_CFG_INT, API_ATT_ISR, API_ATA_SEC, API_INCLUDE, API_INCLUDE_TABLE, API_COUNT
};

/* One static API: its name, whether its first parameter names an object ID,
 * and the element counts accepted in its { } packet (0: no packet). */
struct api_desc {
	const char *name;
	bool has_id;         /* first parameter is the object's ID name */
	bool has_value;      /* first parameter is a plain value (DEF_SVC fncd, CFG_INT intno) */
	int min_elems, max_elems;
	const char *elems;   /* packet element names, for messages */
};

static const struct api_desc apis[API_COUNT] = {
	[API_CRE_TSK] = { "CRE_TSK", true, false, 6, 8, "tskatr, exinf, task, itskpri, stksz, stk[, sstksz, sstk]" },
	[API_CRE_SEM] = { "CRE_SEM", true, false, 3, 3, "sematr, isemcnt, maxsem" },
	[API_CRE_FLG] = { "CRE_FLG", true, false, 2, 2, "flgatr, iflgptn" },
	[API_CRE_DTQ] = { "CRE_DTQ", true, false, 3, 3, "dtqatr, dtqcnt, dtqmb" },
	[API_CRE_PDQ] = { "CRE_PDQ", true, false, 4, 4, "pdqatr, pdqcnt, maxdpri, pdqmb" },
	[API_CRE_MTX] = { "CRE_MTX", true, false, 1, 2, "mtxatr[, ceilpri]" },
	[API_CRE_CYC] = { "CRE_CYC", true, false, 4, 5, "cycatr, exinf, cychdr, cyctim, cycphs" },
	[API_CRE_ALM] = { "CRE_ALM", true, false, 2, 3, "almatr, exinf, almhdr" },
	[API_EV3_CRE_CYC] = { "EV3_CRE_CYC", true, false, 5, 5, "cycatr, exinf, cychdr, cyctim, cycphs" },
	[API_ATT_MOD] = { "ATT_MOD", false, false, 0, 0, NULL },
	[API_ATT_INI] = { "ATT_INI", false, false, 3, 3, "iniatr, exinf, inirtn" },
	[API_ATT_TER] = { "ATT_TER", false, false, 3, 3, "teratr, exinf, terrtn" },
	[API_DEF_SVC] = { "DEF_SVC", false, true, 3, 3, "svcatr, svcrtn, stksz" },
	[API_CFG_INT] = { "CFG_INT", false, true, 2, 2, "intatr, intpri" },
	[API_ATT_ISR] = { "ATT_ISR", false, false, 5, 5, "isratr, exinf, intno, isr, isrpri" },
	[API_ATA_SEC] = { "ATA_SEC", false, false, 2, 2, "mematr, memreg" },
	[API_INCLUDE] = { "INCLUDE", false, false, 0, 0, NULL },
	[API_INCLUDE_TABLE] = { "EV3LX_INCLUDE_TABLE", false, false, 0, 0, NULL },
};

/* The static APIs of TOPPERS/HRP2 that ev3lx does not implement, with what
 * they configure: kernel/kernel_api.csv of EV3RT's HRP2 (ev3rt-git/ev3rt-hrp2)
 * and its message-buffer extension (extension/messagebuf/kernel/kernel_api.csv).
 * A configuration naming one is refused rather than run without it. */
static const struct { const char *name, *what; } unsupported_apis[] = {
	{ "DEF_TEX", "task exception routines" },
	{ "CRE_MPF", "fixed-sized memory pools" },
	{ "CRE_MBF", "message buffers" },
	{ "DEF_OVR", "the overrun handler" },
	{ "SAC_TSK", "access control vectors" }, { "SAC_SEM", "access control vectors" },
	{ "SAC_FLG", "access control vectors" }, { "SAC_DTQ", "access control vectors" },
	{ "SAC_PDQ", "access control vectors" }, { "SAC_MTX", "access control vectors" },
	{ "SAC_MBF", "access control vectors" }, { "SAC_MPF", "access control vectors" },
	{ "SAC_CYC", "access control vectors" }, { "SAC_ALM", "access control vectors" },
	{ "SAC_SYS", "access control vectors" },
	{ "AID_TSK", "IDs for dynamically created objects" }, { "AID_SEM", "IDs for dynamically created objects" },
	{ "AID_FLG", "IDs for dynamically created objects" }, { "AID_DTQ", "IDs for dynamically created objects" },
	{ "AID_PDQ", "IDs for dynamically created objects" }, { "AID_MTX", "IDs for dynamically created objects" },
	{ "AID_MPF", "IDs for dynamically created objects" }, { "AID_CYC", "IDs for dynamically created objects" },
	{ "AID_ALM", "IDs for dynamically created objects" }, { "AID_ISR", "IDs for dynamically created objects" },
	{ "ATT_REG", "memory regions (a domain's memory is its ATT_MOD objects')" },
	{ "DEF_SRG", "memory regions (a domain's memory is its ATT_MOD objects')" },
	{ "ATT_SEC", "sections (a domain's memory is its ATT_MOD objects')" },
	{ "LNK_SEC", "sections (a domain's memory is its ATT_MOD objects')" },
	{ "ATA_MOD", "access permissions of modules (ATT_MOD gives the domain's own)" },
	{ "ATT_MEM", "memory objects (a domain's memory is its ATT_MOD objects')" },
	{ "ATA_MEM", "memory objects (a domain's memory is its ATT_MOD objects')" },
	{ "ATT_PMA", "memory objects (a domain's memory is its ATT_MOD objects')" },
	{ "ATA_PMA", "memory objects (a domain's memory is its ATT_MOD objects')" },
	{ "DEF_INH", "interrupt handlers (use ATT_ISR)" },
	{ "DEF_EXC", "CPU exception handlers" },
	{ "LMT_DOM", "domain priority limits (a user domain's tasks start at TMIN_APP_TPRI)" },
	{ "DEF_ICS", "the interrupt context stack (the kernel allocates it)" },
	{ "DEF_KMM", "the kernel memory area (the kernel allocates it)" },
};

/* Static APIs of other TOPPERS kernels that EV3RT app authors meet, and what
 * HRP2 offers instead (ASP's specification). */
static const struct { const char *name, *why; } foreign_apis[] = {
	{ "CRE_MBX", "TOPPERS/HRP2 has no mailboxes (CRE_MBX is TOPPERS/ASP's); a data queue, CRE_DTQ, carries data" },
};

/* The static APIs only TOPPERS/HRP3 has (ev3rt-git/ev3rt-hrp3,
 * kernel/kernel_api.def), which ev3lx does not implement, with what they
 * configure.  Each says the configuration is an HRP3 one. */
static const struct { const char *name, *what; } hrp3_only_apis[] = {
	{ "ACV_DOM", "a domain's access vector" },
	{ "CRE_ISR", "interrupt service routines created by ID (HRP2's ATT_ISR attaches one)" },
	{ "DEF_SCY", "the system cycle of time-window scheduling" },
	{ "CRE_SOM", "system operating modes" },
	{ "ATT_TWD", "time windows" },
	{ "DEF_MPK", "the kernel's memory pool" },
};

/* HRP3's notification modes (include/kernel.h of ev3rt-git/ev3rt-hrp3): the
 * low four bits say what a time event does, the next four what is done when
 * that fails (TENFY_*). */
static const struct { const char *name; unsigned value; } nfy_names[] = {
	{ "TNFY_HANDLER", 0x00 }, { "TNFY_SETVAR", 0x01 }, { "TNFY_INCVAR", 0x02 }, { "TNFY_ACTTSK", 0x03 },
	{ "TNFY_WUPTSK", 0x04 }, { "TNFY_SIGSEM", 0x05 }, { "TNFY_SETFLG", 0x06 }, { "TNFY_SNDDTQ", 0x07 },
	{ "TENFY_SETVAR", 0x10 }, { "TENFY_INCVAR", 0x20 }, { "TENFY_ACTTSK", 0x30 }, { "TENFY_WUPTSK", 0x40 },
	{ "TENFY_SIGSEM", 0x50 }, { "TENFY_SETFLG", 0x60 }, { "TENFY_SNDDTQ", 0x70 },
};
#define NFY_HANDLER 0x00U
#define NFY_SETVAR  0x01U
#define NFY_INCVAR  0x02U
#define NFY_ACTTSK  0x03U
#define NFY_WUPTSK  0x04U
#define NFY_SIGSEM  0x05U
#define NFY_SETFLG  0x06U
#define NFY_SNDDTQ  0x07U
#define ENFY_SETVAR 0x10U
#define ENFY_INCVAR 0x20U
#define ENFY_ACTTSK 0x30U
#define ENFY_WUPTSK 0x40U
#define ENFY_SIGSEM 0x50U
#define ENFY_SETFLG 0x60U
#define ENFY_SNDDTQ 0x70U
#define MAX_NFY_ELEMS 5

/* Bounds of pass 2 on sizes, from the EV3's 64 MB of RAM (LEGO MINDSTORMS
 * EV3 hardware developer kit: 64 MB DDR RAM): one stack may take an eighth of
 * it, all the configuration's task stacks together half. */
#define EV3CFG_MAX_STKSZ_TEXT "(8UL << 20)"
#define EV3CFG_MAX_STACKS_TEXT "(32UL << 20)"

/* Errors printed before the rest are only counted (random input gives thousands). */
#define MAX_PRINTED_ERRORS 50

#define MAX_ELEMS 8

struct obj {
	enum api api;
	char *id;                /* object ID name, or the string / value parameter */
	char *elem[MAX_ELEMS];   /* packet elements as C expression text */
	int nelem;
	const char *file;
	int line;
	int domain;              /* 0: kernel domain, else index into domains (1-based) */
	int number;              /* assigned object ID (or module index) */
	int task_number;         /* EV3_CRE_CYC: the ID of its handler task */
	const char *path;        /* ATT_MOD: the object it names (cfg_bind_modules) */
	bool nfy;                /* CRE_CYC/CRE_ALM in HRP3's form: elem[1] is the notification */
	unsigned nfymode;        /* its mode (TNFY_* | TENFY_*) */
	char *nfy_elem[MAX_NFY_ELEMS];   /* nfymode, par1[, par2[, par3[, par4]]] */
	int nnfy;
};

/* Where a configuration first showed which kernel it is written for. */
struct profile_mark {
	const char *file;        /* NULL: nowhere yet */
	int line;
	char what[160];          /* the static API, e.g. "CRE_CYC(CYC1)" */
};

struct cfg_ctx {
	FILE *err;
	int nerrors;
	cfg_include_fn include;
	void *include_arg;
	struct obj *objs;
	int nobjs, capobjs;
	char **domains;          /* DOMAIN names, 1-based IDs in order of appearance */
	const char **domain_file;   /* where each was first named */
	int *domain_line;
	int ndomains;
	char **c_includes;
	int nc_includes;
	const char *root;        /* the first file parsed: the configuration's name */
	char **names;            /* interned file names (tokens point here) */
	int nnames;
	/* parse state */
	struct tok *toks;
	int ntoks, captoks, pos;
	int dom_stack[16];
	int dom_depth;
	/* the kernel profile: CFG_PROFILE_AUTO until given (cfg_set_profile) */
	int profile;
	struct profile_mark hrp2_mark, hrp3_mark;
	/* a library's fragment: its IDs at the top of each kind's range (cfg_set_library) */
	bool library;
};

/* ---- small helpers ---- */

static void *xrealloc(void *p, size_t n)
{
	void *q = realloc(p, n ? n : 1);

	if (q == NULL) {
		fputs("ev3cfg: out of memory\n", stderr);
		exit(2);
	}
	return q;
}

static char *xstrndup(const char *s, size_t n)
{
	char *d = xrealloc(NULL, n + 1);

	memcpy(d, s, n);
	d[n] = '\0';
	return d;
}

static char *xstrdup(const char *s)
{
	return xstrndup(s, strlen(s));
}

/* A stable copy of a file name, shared by every token from that file. */
static const char *intern(struct cfg_ctx *ctx, const char *s, size_t n)
{
	for (int i = 0; i < ctx->nnames; i++)
		if (strlen(ctx->names[i]) == n && memcmp(ctx->names[i], s, n) == 0)
			return ctx->names[i];
	ctx->names = xrealloc(ctx->names, (size_t)(ctx->nnames + 1) * sizeof(*ctx->names));
	ctx->names[ctx->nnames] = xstrndup(s, n);
	return ctx->names[ctx->nnames++];
}

/* Prints "file:line[:col]: error: [what: ]message" and counts it (col 0: none). */
static void verror(struct cfg_ctx *ctx, const char *file, int line, int col, const char *what, const char *fmt,
		   va_list ap)
{
	if (ctx->nerrors++ >= MAX_PRINTED_ERRORS)
		return;
	fprintf(ctx->err, "%s:%d:", file, line);
	if (col > 0)
		fprintf(ctx->err, "%d:", col);
	fputs(" error: ", ctx->err);
	if (what != NULL)
		fprintf(ctx->err, "%s: ", what);
	vfprintf(ctx->err, fmt, ap);
	fputc('\n', ctx->err);
	if (ctx->nerrors == MAX_PRINTED_ERRORS)
		fprintf(ctx->err, "%s:%d: note: further errors are counted, not shown\n", file, line);
}

/* Reports "file:line: error: API(ID): message" and counts it. */
static void __attribute__((format(printf, 5, 6)))
report(struct cfg_ctx *ctx, const char *file, int line, const char *what, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	verror(ctx, file, line, 0, what, fmt, ap);
	va_end(ap);
}

/* Prints "file:line: warning: what: message"; a warning is not counted as an error. */
static void __attribute__((format(printf, 5, 6)))
warn(struct cfg_ctx *ctx, const char *file, int line, const char *what, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	fprintf(ctx->err, "%s:%d: warning: %s: ", file, line, what);
	vfprintf(ctx->err, fmt, ap);
	fputc('\n', ctx->err);
	va_end(ap);
}

/* Reports an error at a token's file, line and column. */
static void __attribute__((format(printf, 4, 5)))
report_at(struct cfg_ctx *ctx, const struct tok *t, const char *what, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	verror(ctx, t->file, t->line, t->col, what, fmt, ap);
	va_end(ap);
}

struct cfg_ctx *cfg_new(FILE *err, cfg_include_fn include, void *include_arg)
{
	struct cfg_ctx *ctx = xrealloc(NULL, sizeof(*ctx));

	memset(ctx, 0, sizeof(*ctx));
	ctx->err = err;
	ctx->include = include;
	ctx->include_arg = include_arg;
	return ctx;
}

void cfg_free(struct cfg_ctx *ctx)
{
	if (ctx == NULL)
		return;
	for (int i = 0; i < ctx->nobjs; i++) {
		free(ctx->objs[i].id);
		for (int e = 0; e < ctx->objs[i].nelem; e++)
			free(ctx->objs[i].elem[e]);
		for (int e = 0; e < ctx->objs[i].nnfy; e++)
			free(ctx->objs[i].nfy_elem[e]);
	}
	free(ctx->objs);
	for (int i = 0; i < ctx->ndomains; i++)
		free(ctx->domains[i]);
	free(ctx->domains);
	free(ctx->domain_file);
	free(ctx->domain_line);
	for (int i = 0; i < ctx->nc_includes; i++)
		free(ctx->c_includes[i]);
	free(ctx->c_includes);
	for (int i = 0; i < ctx->nnames; i++)
		free(ctx->names[i]);
	free(ctx->names);
	free(ctx);
}

void cfg_set_library(struct cfg_ctx *ctx, bool library)
{
	ctx->library = library;
}

void cfg_set_profile(struct cfg_ctx *ctx, int profile)
{
	ctx->profile = profile;
}

bool cfg_profile_from_source(struct cfg_ctx *ctx, const char *file, int line, const char *what)
{
	if (ctx->profile != CFG_PROFILE_AUTO || ctx->hrp2_mark.file != NULL || ctx->hrp3_mark.file != NULL)
		return false;
	ctx->hrp3_mark.file = intern(ctx, file, strlen(file));
	ctx->hrp3_mark.line = line;
	snprintf(ctx->hrp3_mark.what, sizeof(ctx->hrp3_mark.what), "%s", what);
	return true;
}

int cfg_profile(const struct cfg_ctx *ctx)
{
	if (ctx->profile != CFG_PROFILE_AUTO)
		return ctx->profile;
	return ctx->hrp3_mark.file != NULL ? CFG_PROFILE_HRP3 : CFG_PROFILE_HRP2;
}

void cfg_add_c_include(struct cfg_ctx *ctx, const char *directive)
{
	for (int i = 0; i < ctx->nc_includes; i++)
		if (strcmp(ctx->c_includes[i], directive) == 0)
			return;
	ctx->c_includes = xrealloc(ctx->c_includes, (size_t)(ctx->nc_includes + 1) * sizeof(char *));
	ctx->c_includes[ctx->nc_includes++] = xstrdup(directive);
}

/* ---- tokenizer over preprocessor output ---- */

/* True for a file whose text is configuration (static APIs only): the file
 * being parsed and every .cfg file; the others are headers it #includes. */
static bool is_cfg_file(const char *file, const char *root)
{
	size_t n = strlen(file);

	return strcmp(file, root) == 0 || (n > 4 && strcmp(file + n - 4, ".cfg") == 0);
}

static void push_tok(struct cfg_ctx *ctx, enum tok_kind kind, const char *s, size_t n, bool space,
		     const struct tok *where)
{
	struct tok *t;

	if (ctx->ntoks == ctx->captoks) {
		ctx->captoks = ctx->captoks ? 2 * ctx->captoks : 256;
		ctx->toks = xrealloc(ctx->toks, (size_t)ctx->captoks * sizeof(*ctx->toks));
	}
	t = &ctx->toks[ctx->ntoks++];
	*t = *where;
	t->kind = kind;
	t->text = s != NULL ? xstrndup(s, n) : NULL;
	t->space = space;
}

/* A character that may start or continue a C identifier (gcc accepts '$'). */
static bool is_ident_char(char c)
{
	return isalnum((unsigned char)c) || c == '_' || c == '$';
}

/* A byte that may appear in C text outside literals and comments: printable
 * ASCII except the three characters no C token uses, or whitespace. */
/* True if s is a C identifier (the linker defines __start_s and __stop_s only for those). */
static bool is_c_section_name(const char *s)
{
	if (!(isalpha((unsigned char)*s) || *s == '_'))
		return false;
	for (; *s; s++)
		if (!(isalnum((unsigned char)*s) || *s == '_'))
			return false;
	return true;
}

static bool is_c_text_byte(char c)
{
	unsigned char u = (unsigned char)c;

	if (u == ' ' || u == '\t' || u == '\n' || u == '\r' || u == '\v' || u == '\f')
		return true;
	return u > ' ' && u < 0x7f && u != '@' && u != '`' && u != '\\';
}

/* Splits text into tokens; "# N \"file\"" lines set the position, other
 * directives (#pragma, #ident) are dropped.  Bytes that are not C text,
 * unterminated literals and comments are reported (once per line). */
static void tokenize(struct cfg_ctx *ctx, const char *text, const char *name)
{
	const char *p = text, *line_start = text;
	const char *root = intern(ctx, name, strlen(name));
	struct tok at = { .file = root, .line = 1, .cfg_text = true };
	bool bol = true, space = false;

	while (*p != '\0') {
		at.col = (int)(p - line_start) + 1;
		if (*p == '\n') {
			at.line++;
			line_start = ++p;
			bol = true;
			space = true;
			continue;
		}
		if (isspace((unsigned char)*p)) {
			p++;
			space = true;
			continue;
		}
		if (bol && *p == '#') {
			const char *q = p + 1;
			char *end;
			long n;

			while (*q == ' ' || *q == '\t')
				q++;
			if (strncmp(q, "line", 4) == 0 && !isalnum((unsigned char)q[4]))
				q += 4;
			n = strtol(q, &end, 10);
			if (end != q && n > 0 && n < 100000000) {
				q = end;
				while (*q == ' ' || *q == '\t')
					q++;
				if (*q == '"') {
					const char *e = strpbrk(q + 1, "\"\n");

					if (e != NULL && *e == '"') {
						at.file = intern(ctx, q + 1, (size_t)(e - q - 1));
						at.cfg_text = is_cfg_file(at.file, root);
					}
				}
				at.line = (int)n - 1;   /* the newline ending this marker counts */
			}
			while (*p != '\0' && *p != '\n')
				p++;
			continue;
		}
		at.bol = bol;
		bol = false;
		if (p[0] == '/' && p[1] == '*') {
			const char *e = strstr(p + 2, "*/");

			if (e == NULL) {
				report_at(ctx, &at, NULL, "unterminated comment");
				break;
			}
			for (const char *c = p; c < e; c++)
				if (*c == '\n') {
					at.line++;
					line_start = c + 1;
				}
			p = e + 2;
			space = true;
			continue;
		}
		if (p[0] == '/' && p[1] == '/') {
			while (*p != '\0' && *p != '\n')
				p++;
			continue;
		}
		if (isalpha((unsigned char)*p) || *p == '_' || *p == '$') {
			const char *s = p;

			while (is_ident_char(*p))
				p++;
			push_tok(ctx, TK_ID, s, (size_t)(p - s), space, &at);
		} else if (isdigit((unsigned char)*p) || (*p == '.' && isdigit((unsigned char)p[1]))) {
			const char *s = p;

			while (isalnum((unsigned char)*p) || *p == '.' || *p == '_' ||
			       ((*p == '+' || *p == '-') && (p[-1] == 'e' || p[-1] == 'E' || p[-1] == 'p' || p[-1] == 'P')))
				p++;
			push_tok(ctx, TK_NUM, s, (size_t)(p - s), space, &at);
		} else if (*p == '"' || *p == '\'') {
			const char *s = p;
			char quote = *p++;

			while (*p != '\0' && *p != quote && *p != '\n') {
				if (*p == '\\' && p[1] != '\0' && p[1] != '\n')
					p++;
				p++;
			}
			if (*p != quote) {
				report_at(ctx, &at, NULL, "missing terminating %c character", quote);
				continue;
			}
			p++;
			push_tok(ctx, quote == '"' ? TK_STR : TK_NUM, s, (size_t)(p - s), space, &at);
		} else if (!is_c_text_byte(*p)) {
			if ((unsigned char)*p < 0x80 && isprint((unsigned char)*p))
				report_at(ctx, &at, NULL, "stray '%c': not C text", *p);
			else
				report_at(ctx, &at, NULL, "stray byte 0x%02x: not C text", (unsigned char)*p);
			while (*p != '\0' && *p != '\n')
				p++;
			continue;
		} else {
			static const char *const two[] = { "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "->", "++", "--" };
			size_t n = 1;

			for (size_t i = 0; i < sizeof(two) / sizeof(two[0]); i++)
				if (p[0] == two[i][0] && p[1] == two[i][1])
					n = 2;
			push_tok(ctx, TK_PUNCT, p, n, space, &at);
			p += n;
		}
		space = false;
	}
	at.col = (int)(p - line_start) + 1;
	push_tok(ctx, TK_EOF, NULL, 0, true, &at);
}

static void free_toks(struct cfg_ctx *ctx)
{
	for (int i = 0; i < ctx->ntoks; i++)
		free(ctx->toks[i].text);
	free(ctx->toks);
	ctx->toks = NULL;
	ctx->ntoks = 0;
	ctx->captoks = 0;
	ctx->pos = 0;
}

static struct tok *peek(struct cfg_ctx *ctx, int ahead)
{
	int i = ctx->pos + ahead;

	return &ctx->toks[i < ctx->ntoks ? i : ctx->ntoks - 1];
}

static bool is_punct(const struct tok *t, const char *s)
{
	return t->kind == TK_PUNCT && strcmp(t->text, s) == 0;
}

static struct tok *next(struct cfg_ctx *ctx)
{
	struct tok *t = peek(ctx, 0);

	if (t->kind != TK_EOF)
		ctx->pos++;
	return t;
}

/* ---- pass 1: static APIs ---- */

/* Skips one C declaration or definition from a header (the configuration is
 * preprocessed with TOPPERS_MACRO_ONLY, but not every header honours it). */
static void skip_c_declaration(struct cfg_ctx *ctx)
{
	int depth = 0;
	const struct tok *prev = NULL;

	for (;;) {
		struct tok *t = next(ctx);

		if (t->kind == TK_EOF)
			return;
		if (is_punct(t, "(") || is_punct(t, "[") || is_punct(t, "{")) {
			/* a function body: "... ) {" at file scope ends at its "}" */
			if (depth == 0 && is_punct(t, "{") && prev != NULL && is_punct(prev, ")")) {
				int d = 1;

				while (d > 0 && peek(ctx, 0)->kind != TK_EOF) {
					t = next(ctx);
					d += is_punct(t, "{") - is_punct(t, "}");
				}
				return;
			}
			depth++;
		} else if (is_punct(t, ")") || is_punct(t, "]") || is_punct(t, "}")) {
			if (depth > 0)
				depth--;
		} else if (depth == 0 && is_punct(t, ";")) {
			return;
		}
		prev = t;
	}
}

/* Skips what follows a syntax error: up to and including the next ';' outside
 * brackets, or a whole bracketed block ("NAME(...) { ... }"), or up to the
 * next line outside brackets, so one mistake gives one error. */
static void skip_statement(struct cfg_ctx *ctx)
{
	int depth = 0;

	for (bool first = true;; first = false) {
		struct tok *t = peek(ctx, 0);

		if (t->kind == TK_EOF || (depth == 0 && t->bol && !first))
			return;
		next(ctx);
		if (is_punct(t, "(") || is_punct(t, "[") || is_punct(t, "{")) {
			depth++;
		} else if (is_punct(t, ")") || is_punct(t, "]") || is_punct(t, "}")) {
			if (depth == 0)
				return;
			if (--depth == 0 && is_punct(t, "}")) {
				if (is_punct(peek(ctx, 0), ";"))
					next(ctx);
				return;
			}
		} else if (depth == 0 && is_punct(t, ";")) {
			return;
		}
	}
}

/* Joins tokens [from, to) into C expression text. */
static char *join_tokens(struct cfg_ctx *ctx, int from, int to)
{
	size_t len = 1;
	char *s, *d;

	for (int i = from; i < to; i++)
		len += strlen(ctx->toks[i].text) + 1;
	s = d = xrealloc(NULL, len);
	for (int i = from; i < to; i++) {
		if (i > from && ctx->toks[i].space)
			*d++ = ' ';
		strcpy(d, ctx->toks[i].text);
		d += strlen(d);
	}
	*d = '\0';
	return s;
}

/* Reads one expression up to a "," or the closing bracket at depth 0;
 * returns its text, or NULL (reported) if it is empty or runs off the end. */
static char *read_expr(struct cfg_ctx *ctx, const char *what, const char *close)
{
	int start = ctx->pos, depth = 0;
	const struct tok *first = peek(ctx, 0);

	for (;;) {
		const struct tok *t = peek(ctx, 0);

		if (t->kind == TK_EOF || (depth == 0 && (is_punct(t, ";")))) {
			report(ctx, first->file, first->line, what, "missing '%s'", close);
			return NULL;
		}
		if (depth == 0 && (is_punct(t, ",") || is_punct(t, close)))
			break;
		if (is_punct(t, "(") || is_punct(t, "[") || is_punct(t, "{"))
			depth++;
		else if (is_punct(t, ")") || is_punct(t, "]") || is_punct(t, "}"))
			depth--;
		ctx->pos++;
	}
	if (ctx->pos == start) {
		report(ctx, first->file, first->line, what, "empty parameter");
		return NULL;
	}
	return join_tokens(ctx, start, ctx->pos);
}

/* The string literal's contents (simple escapes); NULL if t is not a string. */
static char *unquote(const struct tok *t)
{
	size_t n;
	char *s, *d;

	if (t->kind != TK_STR)
		return NULL;
	n = strlen(t->text);
	s = d = xrealloc(NULL, n);
	for (size_t i = 1; i + 1 < n; i++) {
		if (t->text[i] == '\\' && i + 2 < n)
			i++;
		*d++ = t->text[i];
	}
	*d = '\0';
	return s;
}

static struct obj *new_obj(struct cfg_ctx *ctx)
{
	struct obj *o;

	if (ctx->nobjs == ctx->capobjs) {
		ctx->capobjs = ctx->capobjs ? ctx->capobjs * 2 : 32;
		ctx->objs = xrealloc(ctx->objs, (size_t)ctx->capobjs * sizeof(*ctx->objs));
	}
	o = &ctx->objs[ctx->nobjs++];
	memset(o, 0, sizeof(*o));
	return o;
}

/* The object kind an ID name belongs to: EV3_CRE_CYC numbers cyclic handlers too. */
static enum api id_kind(enum api a)
{
	return a == API_EV3_CRE_CYC ? API_CRE_CYC : a;
}

/* Drops the object new_obj made last (its parameters were refused). */
static void discard_last_obj(struct cfg_ctx *ctx)
{
	struct obj *o = &ctx->objs[--ctx->nobjs];

	free(o->id);
	for (int e = 0; e < o->nelem && e < MAX_ELEMS; e++)
		free(o->elem[e]);
}

#define EV3_CYC_TASK_PREFIX "EV3_CYC_TASK_"

/* Where name is already a C identifier of kernel_cfg.h (an object ID, an
 * EV3_CRE_CYC handler task, a domain), other than self's own: the static API
 * that defined it, its position and, for objects, the object; NULL if free.
 * TOPPERS object IDs of every kind share this one namespace. */
static const char *find_name(const struct cfg_ctx *ctx, const char *name, const struct obj *self,
			     const char **file, int *line, const struct obj **obj)
{
	size_t plen = strlen(EV3_CYC_TASK_PREFIX);

	*obj = NULL;
	for (int i = 0; i < ctx->nobjs; i++) {
		const struct obj *o = &ctx->objs[i];

		if (o == self || !apis[o->api].has_id || o->id == NULL)
			continue;
		*file = o->file;
		*line = o->line;
		if (strcmp(o->id, name) == 0) {
			*obj = o;
			return apis[o->api].name;
		}
		if (o->api == API_EV3_CRE_CYC && strncmp(name, EV3_CYC_TASK_PREFIX, plen) == 0 &&
		    strcmp(name + plen, o->id) == 0)
			return "EV3_CRE_CYC (its handler task)";
	}
	for (int i = 0; i < ctx->ndomains; i++)
		if (strcmp(ctx->domains[i], name) == 0) {
			*file = ctx->domain_file[i];
			*line = ctx->domain_line[i];
			return "DOMAIN";
		}
	return NULL;
}

/* Reports (and returns true) if object o's ID, or for EV3_CRE_CYC its handler
 * task's name, is already defined. */
static bool id_taken(struct cfg_ctx *ctx, const struct obj *o, const char *what)
{
	const struct obj *dup;
	const char *file = NULL, *by;
	int line = 0;

	by = find_name(ctx, o->id, o, &file, &line, &dup);
	if (by != NULL && dup != NULL && id_kind(dup->api) == id_kind(o->api)) {
		report(ctx, o->file, o->line, what, "%s is already defined at %s:%d (E_OBJ)", o->id, file, line);
		return true;
	}
	if (by != NULL) {
		report(ctx, o->file, o->line, what,
		       "%s is already defined at %s:%d by %s; the IDs of every kind share one namespace (E_OBJ)",
		       o->id, file, line, by);
		return true;
	}
	if (o->api == API_EV3_CRE_CYC) {
		char task[160];

		snprintf(task, sizeof(task), EV3_CYC_TASK_PREFIX "%s", o->id);
		if ((by = find_name(ctx, task, o, &file, &line, &dup)) != NULL) {
			report(ctx, o->file, o->line, what,
			       "its handler task %s is already defined at %s:%d by %s (E_OBJ)", task, file, line, by);
			return true;
		}
	}
	return false;
}

static bool is_null_expr(const char *e)
{
	return strcmp(e, "NULL") == 0 || strcmp(e, "0") == 0 || strcmp(e, "((void *)0)") == 0 ||
	       strcmp(e, "((void*)0)") == 0;
}

/* Notes that the static API what at file:line, in form form, is written for
 * HRP3 (hrp3) or HRP2; reports a configuration that mixes the two, or that
 * contradicts the profile it is built for (cfg_set_profile). */
static void mark_profile(struct cfg_ctx *ctx, bool hrp3, const char *file, int line, const char *what,
			 const char *form)
{
	struct profile_mark *mine = hrp3 ? &ctx->hrp3_mark : &ctx->hrp2_mark;
	const struct profile_mark *other = hrp3 ? &ctx->hrp2_mark : &ctx->hrp3_mark;
	const char *kernel = hrp3 ? "HRP3" : "HRP2", *other_kernel = hrp3 ? "HRP2" : "HRP3";

	if (ctx->profile == (hrp3 ? CFG_PROFILE_HRP2 : CFG_PROFILE_HRP3))
		report(ctx, file, line, what, "%s is TOPPERS/%s's, but the app is built for the %s profile "
		       "(--kernel %s) (E_PAR)", form, kernel, other_kernel, hrp3 ? "hrp2" : "hrp3");
	else if (other->file != NULL)
		report(ctx, file, line, what, "%s is TOPPERS/%s's, but %s at %s:%d is TOPPERS/%s's: a configuration "
		       "is written for one kernel profile (E_PAR)", form, kernel, other->what, other->file, other->line,
		       other_kernel);
	if (mine->file == NULL) {
		mine->file = file;
		mine->line = line;
		snprintf(mine->what, sizeof(mine->what), "%s", what);
	}
}

/* The value of a notification mode as written: TNFY_ and TENFY_ names, or
 * the integer constants a preprocessed header gives (0x03U), joined by | or
 * +, with parentheses; false for anything else. */
static bool eval_nfymode(const char *e, unsigned *value)
{
	unsigned v = 0;
	bool want_term = true;

	for (const char *p = e; *p != '\0';) {
		if (*p == ' ' || *p == '(' || *p == ')') {
			p++;
		} else if (!want_term && (*p == '|' || *p == '+')) {
			want_term = true;
			p++;
		} else if (want_term && (isalpha((unsigned char)*p) || *p == '_')) {
			const char *q = p;
			bool found = false;

			while (isalnum((unsigned char)*q) || *q == '_')
				q++;
			for (size_t i = 0; i < sizeof(nfy_names) / sizeof(nfy_names[0]); i++)
				if (strlen(nfy_names[i].name) == (size_t)(q - p) && strncmp(nfy_names[i].name, p, (size_t)(q - p)) == 0) {
					v |= nfy_names[i].value;
					found = true;
				}
			if (!found)
				return false;
			p = q;
			want_term = false;
		} else if (want_term && isdigit((unsigned char)*p)) {
			char *end;

			v |= (unsigned)strtoul(p, &end, 0);
			while (*end == 'u' || *end == 'U' || *end == 'l' || *end == 'L')
				end++;
			p = end;
			want_term = false;
		} else {
			return false;
		}
	}
	*value = v;
	return !want_term;
}

/* Splits HRP3's notification block "{ nfymode, par1, ... }" into o->nfy_elem
 * at its top-level commas; false if it has more than MAX_NFY_ELEMS. */
static bool split_nfy(struct obj *o, const char *block)
{
	const char *p = block + 1, *end = block + strlen(block) - 1, *start;
	int depth = 0;
	char quote = 0;

	while (end > p && *end == ' ')
		end--;
	for (start = p; p <= end; p++) {
		if (quote != 0) {
			if (*p == '\\' && p < end)
				p++;
			else if (*p == quote)
				quote = 0;
			continue;
		}
		if (*p == '"' || *p == '\'')
			quote = *p;
		else if (*p == '(' || *p == '[' || *p == '{')
			depth++;
		else if (*p == ')' || *p == ']' || (*p == '}' && p < end))
			depth--;
		if ((*p == ',' && depth == 0) || p == end) {
			const char *a = start, *b = p;

			while (a < b && *a == ' ')
				a++;
			while (b > a && b[-1] == ' ')
				b--;
			if (o->nnfy == MAX_NFY_ELEMS)
				return false;
			o->nfy_elem[o->nnfy++] = xstrndup(a, (size_t)(b - a));
			start = p + 1;
		}
	}
	return true;
}

/* CRE_CYC and CRE_ALM come in HRP2's form, a handler (cycatr, exinf, cychdr,
 * cyctim, cycphs; almatr, exinf, almhdr; times in ms), and HRP3's, a
 * notification (cycatr, { nfymode, par1[, par2[, par3[, par4]]] }, cyctim,
 * cycphs; almatr, { ... }; times in us), whose parameters are checked as
 * HRP3's configurator checks them (ev3rt-git/ev3rt-hrp3, kernel/kernel.trb,
 * generateNotifyHandler).  Marks the configuration's profile by the form. */
static void check_time_event(struct cfg_ctx *ctx, struct obj *o, const char *what)
{
	bool cyc = o->api == API_CRE_CYC;
	int hrp2_n = cyc ? 5 : 3, hrp3_n = cyc ? 4 : 2, braces = -1;
	unsigned m, mode1, mode2;
	int numpar, need;

	for (int i = 0; i < o->nelem; i++)
		if (o->elem[i][0] == '{' && braces < 0)
			braces = i;
	if (o->nelem == hrp2_n && braces < 0) {
		mark_profile(ctx, false, o->file, o->line, what, "the handler form (times in ms)");
		return;
	}
	if (o->nelem != hrp3_n || braces != 1) {
		if (braces >= 0 || o->nelem == hrp3_n)
			report(ctx, o->file, o->line, what, "malformed notification form: expected { %s, { nfymode, par1"
			       "[, par2...] }%s } as in TOPPERS/HRP3, the notification second (E_PAR)",
			       cyc ? "cycatr" : "almatr", cyc ? ", cyctim, cycphs" : "");
		else
			report(ctx, o->file, o->line, what, "%d parameters in { }, expected %d (HRP2: %s) or %d (HRP3: "
			       "%s, { nfymode, par1[, par2...] }%s) (E_PAR)", o->nelem, hrp2_n, apis[o->api].elems, hrp3_n,
			       cyc ? "cycatr" : "almatr", cyc ? ", cyctim, cycphs" : "");
		return;
	}
	o->nfy = true;
	mark_profile(ctx, true, o->file, o->line, what, "the notification form { nfymode, ... } (times in us)");
	if (!split_nfy(o, o->elem[1]) || o->nnfy < 2) {
		report(ctx, o->file, o->line, what, "the notification %s has %s parameters: expected nfymode and 1 to 4 "
		       "more (E_PAR)", o->elem[1], o->nnfy < 2 ? "too few" : "too many");
		return;
	}
	if (!eval_nfymode(o->nfy_elem[0], &m)) {
		report(ctx, o->file, o->line, what, "nfymode '%s' is not TNFY_* or TNFY_* | TENFY_* (E_PAR)",
		       o->nfy_elem[0]);
		return;
	}
	o->nfymode = m;
	mode1 = m & 0x0fU;
	mode2 = m & ~0x0fU;
	if (mode1 > NFY_SNDDTQ || (mode2 & 0x0fU) != 0 || mode2 > ENFY_SNDDTQ ||
	    (mode2 != 0 && (mode1 == NFY_HANDLER || mode1 == NFY_SETVAR || mode1 == NFY_INCVAR))) {
		report(ctx, o->file, o->line, what, "illegal nfymode %s (0x%x): the error notifications TENFY_* go "
		       "with TNFY_ACTTSK, TNFY_WUPTSK, TNFY_SIGSEM, TNFY_SETFLG and TNFY_SNDDTQ only (E_PAR)",
		       o->nfy_elem[0], m);
		return;
	}
	numpar = mode1 == NFY_HANDLER || mode1 == NFY_SETVAR || mode1 == NFY_SETFLG || mode1 == NFY_SNDDTQ ? 2 : 1;
	need = 1 + numpar + (mode2 == 0 ? 0 : mode2 == ENFY_SETFLG ? 2 : 1);
	if (o->nnfy != need) {
		report(ctx, o->file, o->line, what, "too %s parameters for nfymode %s: %d, expected %d (E_PAR)",
		       o->nnfy < need ? "few" : "many", o->nfy_elem[0], o->nnfy - 1, need - 1);
		return;
	}
	if (mode1 == NFY_HANDLER && o->domain != 0)
		report(ctx, o->file, o->line, what, "TNFY_HANDLER is not permitted in a user domain (DOMAIN(%s)): "
		       "HRP3 runs time-event handlers in the kernel domain; TNFY_ACTTSK or TNFY_WUPTSK hands the "
		       "work to a task (E_OACV)", ctx->domains[o->domain - 1]);
}

/* A static API only HRP2 (EV3RT 0.x) has marks the configuration HRP2's. */
static void mark_hrp2_api(struct cfg_ctx *ctx, const struct obj *o, const char *what)
{
	if (o->api == API_EV3_CRE_CYC)
		mark_profile(ctx, false, o->file, o->line, what, "EV3_CRE_CYC (EV3RT's HRP2 API, times in ms)");
}

/* Shape checks of pass 1 that need no values. */
static void check_obj(struct cfg_ctx *ctx, struct obj *o, const char *what)
{
	const struct api_desc *d = &apis[o->api];
	bool kernel_only = o->api == API_ATT_INI || o->api == API_ATT_TER || o->api == API_DEF_SVC ||
			   o->api == API_CFG_INT || o->api == API_ATT_ISR;

	if (o->api == API_CRE_CYC || o->api == API_CRE_ALM) {
		check_time_event(ctx, o, what);
		return;
	}
	mark_hrp2_api(ctx, o, what);
	if (d->max_elems > 0 && (o->nelem < d->min_elems || o->nelem > d->max_elems)) {
		if (d->min_elems == d->max_elems)
			report(ctx, o->file, o->line, what, "%d parameters in { } (%s), expected %d (E_PAR)",
			       o->nelem, d->elems, d->min_elems);
		else
			report(ctx, o->file, o->line, what, "%d parameters in { } (%s), expected %d to %d (E_PAR)",
			       o->nelem, d->elems, d->min_elems, d->max_elems);
		return;
	}
	if (kernel_only && o->domain != 0)
		report(ctx, o->file, o->line, what,
		       "belongs to the kernel domain, not inside DOMAIN(%s) (E_RSATR)", ctx->domains[o->domain - 1]);
	if (o->api == API_CRE_TSK && !is_null_expr(o->elem[5]))
		report(ctx, o->file, o->line, what, "stk must be NULL: the kernel allocates task stacks (E_NOSPT)");
	if (o->api == API_CRE_TSK && o->nelem == 8 && !is_null_expr(o->elem[7]))
		report(ctx, o->file, o->line, what, "sstk must be NULL: the kernel allocates system stacks (E_NOSPT)");
	if (o->api == API_CRE_DTQ && !is_null_expr(o->elem[2]))
		report(ctx, o->file, o->line, what, "dtqmb must be NULL: the kernel allocates the buffer (E_NOSPT)");
	if (o->api == API_CRE_PDQ && !is_null_expr(o->elem[3]))
		report(ctx, o->file, o->line, what, "pdqmb must be NULL: the kernel allocates the buffer (E_NOSPT)");
}

/* Reads "{ e, ... }" into o's elements from index first on; the count read, or -1 if malformed. */
static int read_packet(struct cfg_ctx *ctx, struct obj *o, const char *what, int first)
{
	int n = 0;

	if (!is_punct(next(ctx), "{"))
		return -1;
	for (;;) {
		char *e = read_expr(ctx, what, "}");

		if (e == NULL)
			return -1;
		if (first + n < MAX_ELEMS)
			o->elem[first + n] = e;
		else
			free(e);
		n++;
		if (!is_punct(peek(ctx, 0), ","))
			break;
		next(ctx);
	}
	return is_punct(next(ctx), "}") ? n : -1;
}

/*
 * ATA_SEC("section", { mematr, memreg }, { acptn1, acptn2, acptn3, acptn4 }):
 * a section of the kernel domain's memory with access permissions (HRP2's
 * memory-object API).  On the host the section's bounds are the linker's
 * __start_/__stop_ symbols, and every user domain gets the access that
 * acptn1 (write) and acptn2 (read) grant to all domains (TACP_SHARED).
 */
static void parse_ata_sec(struct cfg_ctx *ctx, const struct tok *name)
{
	const char *what = "ATA_SEC";
	struct tok *arg = next(ctx);
	char *sec = arg->kind == TK_STR ? unquote(arg) : NULL;
	struct obj *o;
	int n1 = -1, n2 = -1;

	o = new_obj(ctx);
	o->api = API_ATA_SEC;
	o->id = sec;
	o->file = name->file;
	o->line = name->line;
	o->domain = ctx->dom_depth > 0 ? ctx->dom_stack[ctx->dom_depth - 1] : 0;
	if (sec != NULL && is_punct(next(ctx), ","))
		n1 = read_packet(ctx, o, what, 0);
	if (n1 == 2 && is_punct(next(ctx), ","))
		n2 = read_packet(ctx, o, what, 2);
	o->nelem = 2 + (n2 > 0 ? n2 : 0);
	if (o->nelem > MAX_ELEMS)
		o->nelem = MAX_ELEMS;
	if (sec == NULL || n1 != 2 || n2 != 4 || !is_punct(next(ctx), ")") || !is_punct(peek(ctx, 0), ";")) {
		report(ctx, name->file, name->line, what,
		       "expected (\"section\", { mematr, memreg }, { acptn1, acptn2, acptn3, acptn4 }) (E_PAR)");
		discard_last_obj(ctx);
		while (!is_punct(peek(ctx, 0), ";") && peek(ctx, 0)->kind != TK_EOF)
			next(ctx);
		next(ctx);
		return;
	}
	next(ctx);
	if (!is_c_section_name(sec))
		report(ctx, name->file, name->line, what,
		       "section \"%s\": a C identifier is needed, the linker bounds it by __start_/__stop_ (E_PAR)", sec);
	if (o->domain != 0)
		report(ctx, name->file, name->line, what,
		       "belongs to the kernel domain, not inside DOMAIN(%s) (E_RSATR)", ctx->domains[o->domain - 1]);
}

/* Parses "API ( ... ) ;" after the name; records the object. */
static void parse_api(struct cfg_ctx *ctx, enum api a)
{
	const struct api_desc *d = &apis[a];
	struct tok *name = next(ctx);
	struct obj *o;
	char what[160];

	snprintf(what, sizeof(what), "%s", d->name);
	next(ctx);	/* "(" */
	if (a == API_ATA_SEC) {
		parse_ata_sec(ctx, name);
		return;
	}
	if (a == API_ATT_MOD || a == API_INCLUDE || a == API_INCLUDE_TABLE) {
		struct tok *arg = next(ctx);
		char *s = a == API_INCLUDE_TABLE ? (arg->kind == TK_ID ? xstrdup(arg->text) : NULL) : unquote(arg);

		if (s == NULL || !is_punct(peek(ctx, 0), ")")) {
			report(ctx, name->file, name->line, what, a == API_INCLUDE_TABLE ?
			       "expected one identifier, the name of a struct rtos_cfg (E_PAR)" :
			       "expected one string literal (E_PAR)");
			free(s);
			while (!is_punct(peek(ctx, 0), ";") && peek(ctx, 0)->kind != TK_EOF)
				next(ctx);
			next(ctx);
			return;
		}
		next(ctx);
		if (!is_punct(peek(ctx, 0), ";"))
			report(ctx, name->file, name->line, what, "missing ';' after the static API");
		else
			next(ctx);
		if (a == API_INCLUDE) {
			/* TECS's generated configuration: an app of TOPPERS's third-generation kernels */
			if (strcmp(s, "tecsgen.cfg") == 0)
				mark_profile(ctx, true, name->file, name->line, "INCLUDE(\"tecsgen.cfg\")",
					     "INCLUDE(\"tecsgen.cfg\") (TECS's components, of a third-generation kernel)");
			if (ctx->include == NULL)
				report(ctx, name->file, name->line, what, "INCLUDE is not available here");
			else
				ctx->nerrors += ctx->include(ctx, s, name->file, name->line, ctx->include_arg);
			free(s);
			return;
		}
		for (int i = 0; i < ctx->nobjs; i++)
			if (ctx->objs[i].api == a && strcmp(ctx->objs[i].id, s) == 0) {
				/* EV3RT's app build ignores the module names (its module.tf
				 * checks only their domain) and a linker script's second
				 * pattern for a file matches nothing: apps ship such lines. */
				if (a == API_ATT_MOD)
					warn(ctx, name->file, name->line, what,
					     "\"%s\" is already attached at %s:%d; this one is ignored",
					     s, ctx->objs[i].file, ctx->objs[i].line);
				else
					report(ctx, name->file, name->line, what,
					       "\"%s\" is already attached at %s:%d (E_OBJ)",
					       s, ctx->objs[i].file, ctx->objs[i].line);
				free(s);
				return;
			}
		o = new_obj(ctx);
		o->api = a;
		o->id = s;
		o->file = name->file;
		o->line = name->line;
		o->domain = ctx->dom_depth > 0 ? ctx->dom_stack[ctx->dom_depth - 1] : -1;
		return;
	}
	o = new_obj(ctx);
	o->api = a;
	o->file = name->file;
	o->line = name->line;
	o->domain = ctx->dom_depth > 0 ? ctx->dom_stack[ctx->dom_depth - 1] : 0;
	if (d->has_id) {
		struct tok *id = next(ctx);

		if (id->kind != TK_ID || !(is_punct(peek(ctx, 0), ","))) {
			report(ctx, name->file, name->line, what, "the first parameter must be the object's ID name (E_PAR)");
			discard_last_obj(ctx);
			while (!is_punct(peek(ctx, 0), ";") && peek(ctx, 0)->kind != TK_EOF)
				next(ctx);
			next(ctx);
			return;
		}
		o->id = xstrdup(id->text);
		snprintf(what, sizeof(what), "%s(%s)", d->name, id->text);
		next(ctx);	/* "," */
	} else if (d->has_value) {
		if ((o->id = read_expr(ctx, what, ")")) == NULL || !is_punct(next(ctx), ",")) {
			report(ctx, name->file, name->line, what, "expected a value and { %s } (E_PAR)", d->elems);
			discard_last_obj(ctx);
			while (!is_punct(peek(ctx, 0), ";") && peek(ctx, 0)->kind != TK_EOF)
				next(ctx);
			next(ctx);
			return;
		}
	}
	if (!is_punct(next(ctx), "{")) {
		report(ctx, name->file, name->line, what, "expected { %s } (E_PAR)", d->elems);
		discard_last_obj(ctx);
		while (!is_punct(peek(ctx, 0), ";") && peek(ctx, 0)->kind != TK_EOF)
			next(ctx);
		next(ctx);
		return;
	}
	for (;;) {
		char *e;

		if (is_punct(peek(ctx, 0), "}") && o->nelem == 0)
			break;
		if ((e = read_expr(ctx, what, "}")) == NULL)
			break;
		if (o->nelem < MAX_ELEMS)
			o->elem[o->nelem] = e;
		else
			free(e);
		o->nelem++;
		if (!is_punct(peek(ctx, 0), ","))
			break;
		next(ctx);
	}
	if (o->nelem > MAX_ELEMS)
		o->nelem = MAX_ELEMS + 1;
	if (!is_punct(next(ctx), "}") || !is_punct(next(ctx), ")") || !is_punct(peek(ctx, 0), ";")) {
		report(ctx, name->file, name->line, what, "malformed static API: expected \"{ %s });\"", d->elems);
		if (o->nelem > MAX_ELEMS)
			o->nelem = MAX_ELEMS;
		while (!is_punct(peek(ctx, 0), ";") && peek(ctx, 0)->kind != TK_EOF)
			next(ctx);
		next(ctx);
		return;
	}
	next(ctx);
	if (o->nelem > MAX_ELEMS) {
		o->nelem = MAX_ELEMS;
		report(ctx, o->file, o->line, what, "more than %d parameters in { } (E_PAR)", MAX_ELEMS);
		return;
	}
	if (o->id != NULL && d->has_id && id_taken(ctx, o, what))
		return;
	check_obj(ctx, o, what);
}

#define MAX_DOMAIN_DEPTH ((int)(sizeof(((struct cfg_ctx *)0)->dom_stack) / sizeof(int)))

/* Enters a domain block ("{" is next); blocks do not nest (E_RSATR).  A block
 * too deep to track is skipped whole. */
static void enter_domain(struct cfg_ctx *ctx, const struct tok *kw, int index, const char *name)
{
	if (ctx->dom_depth > 0)
		report_at(ctx, kw, "DOMAIN", "%s inside another domain block (E_RSATR)", name);
	if (ctx->dom_depth == MAX_DOMAIN_DEPTH) {
		skip_statement(ctx);
		return;
	}
	next(ctx);	/* "{" */
	ctx->dom_stack[ctx->dom_depth++] = index;
}

/* Parses "DOMAIN ( name ) {" and enters the domain. */
static void parse_domain(struct cfg_ctx *ctx)
{
	struct tok *kw = next(ctx);
	struct tok *id;
	int index = 0;
	char what[160];

	next(ctx);	/* "(" */
	id = next(ctx);
	if (id->kind != TK_ID || !is_punct(next(ctx), ")") || !is_punct(peek(ctx, 0), "{")) {
		report_at(ctx, kw, "DOMAIN", "expected DOMAIN(name) { ... } (E_PAR)");
		ctx->pos = (int)(kw - ctx->toks) + 1;
		skip_statement(ctx);
		return;
	}
	for (int i = 0; i < ctx->ndomains; i++)
		if (strcmp(ctx->domains[i], id->text) == 0)
			index = i + 1;
	if (index == 0) {
		const struct obj *dup;
		const char *file = NULL, *by;
		int line = 0;

		if ((by = find_name(ctx, id->text, NULL, &file, &line, &dup)) != NULL)
			report(ctx, kw->file, kw->line, "DOMAIN",
			       "%s is already defined at %s:%d by %s; the IDs of every kind share one namespace (E_OBJ)",
			       id->text, file, line, by);
		ctx->domains = xrealloc(ctx->domains, (size_t)(ctx->ndomains + 1) * sizeof(char *));
		ctx->domain_file = xrealloc(ctx->domain_file, (size_t)(ctx->ndomains + 1) * sizeof(char *));
		ctx->domain_line = xrealloc(ctx->domain_line, (size_t)(ctx->ndomains + 1) * sizeof(int));
		ctx->domain_file[ctx->ndomains] = kw->file;
		ctx->domain_line[ctx->ndomains] = kw->line;
		ctx->domains[ctx->ndomains++] = xstrdup(id->text);
		index = ctx->ndomains;
	}
	snprintf(what, sizeof(what), "DOMAIN(%s)", id->text);
	enter_domain(ctx, kw, index, what);
}

static int api_lookup(const char *name)
{
	for (int a = 0; a < API_COUNT; a++)
		if (strcmp(apis[a].name, name) == 0)
			return a;
	return -1;
}

/* What an HRP2 static API that ev3lx lacks configures; NULL for other names. */
static const char *unsupported_api(const char *name)
{
	for (size_t i = 0; i < sizeof(unsupported_apis) / sizeof(unsupported_apis[0]); i++)
		if (strcmp(unsupported_apis[i].name, name) == 0)
			return unsupported_apis[i].what;
	return NULL;
}

/* What an HRP3-only static API configures; NULL for other names. */
static const char *hrp3_only_api(const char *name)
{
	for (size_t i = 0; i < sizeof(hrp3_only_apis) / sizeof(hrp3_only_apis[0]); i++)
		if (strcmp(hrp3_only_apis[i].name, name) == 0)
			return hrp3_only_apis[i].what;
	return NULL;
}

/* Why a static API of another TOPPERS kernel is not HRP2's; NULL for other names. */
static const char *foreign_api(const char *name)
{
	for (size_t i = 0; i < sizeof(foreign_apis) / sizeof(foreign_apis[0]); i++)
		if (strcmp(foreign_apis[i].name, name) == 0)
			return foreign_apis[i].why;
	return NULL;
}

/* True for names shaped like a static API (ABC_DEF), which only appear in a
 * configuration's top level as static API calls. */
static bool looks_like_api(const char *s)
{
	const char *u = strchr(s, '_');

	if (u == NULL || u == s || strlen(s) > 16)
		return false;
	for (const char *c = s; *c; c++)
		if (!(isupper((unsigned char)*c) || isdigit((unsigned char)*c) || *c == '_'))
			return false;
	return u - s == 3 && isupper((unsigned char)u[1]);
}

/* Edit distance of a and b with adjacent transpositions (optimal string
 * alignment), up to 3: enough to tell a misspelt keyword. */
static int edit_distance(const char *a, const char *b)
{
	size_t na = strlen(a), nb = strlen(b);
	int d[24][24];

	if (na > 22 || nb > 22 || (na > nb ? na - nb : nb - na) > 3)
		return 4;
	for (size_t i = 0; i <= na; i++)
		for (size_t j = 0; j <= nb; j++) {
			int best;

			if (i == 0 || j == 0) {
				d[i][j] = (int)(i + j);
				continue;
			}
			best = d[i - 1][j - 1] + (toupper((unsigned char)a[i - 1]) != toupper((unsigned char)b[j - 1]));
			if (d[i - 1][j] + 1 < best)
				best = d[i - 1][j] + 1;
			if (d[i][j - 1] + 1 < best)
				best = d[i][j - 1] + 1;
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < best)
				best = d[i - 2][j - 2] + 1;
			d[i][j] = best;
		}
	return d[na][nb];
}

/* The keyword a misspelt name probably meant (ignoring case, one edit or transposition), or NULL. */
static const char *near_keyword(const char *name)
{
	static const char *const words[] = { "DOMAIN", "KERNEL_DOMAIN", "INCLUDE" };
	const char *best = NULL;
	int best_d = 2;

	if (strlen(name) < 4)
		return NULL;
	for (size_t i = 0; i < sizeof(words) / sizeof(words[0]) + API_COUNT; i++) {
		const char *w = i < sizeof(words) / sizeof(words[0]) ? words[i] : apis[i - sizeof(words) / sizeof(words[0])].name;
		int dist = edit_distance(name, w);

		if (dist < best_d) {
			best_d = dist;
			best = w;
		}
	}
	return best;
}

/* Reports what stands where a static API should: an unknown name (with the
 * keyword it resembles) or a token that cannot start one. */
static void report_not_api(struct cfg_ctx *ctx, const struct tok *t)
{
	const char *hint = t->kind == TK_ID ? near_keyword(t->text) : NULL;

	if (hint != NULL && strcmp(hint, t->text) == 0) {
		report_at(ctx, t, NULL, "syntax error: %s is not followed by '%s'", t->text,
			  strcmp(t->text, "KERNEL_DOMAIN") == 0 ? "{" : "(");
	} else if (t->kind == TK_ID && is_punct(peek(ctx, 1), "(")) {
		if (hint != NULL)
			report_at(ctx, t, t->text, "unknown static API (did you mean %s?)", hint);
		else
			report_at(ctx, t, t->text, "unknown static API");
	} else if (hint != NULL) {
		report_at(ctx, t, NULL, "syntax error: '%s' is not a static API (did you mean %s?)", t->text, hint);
	} else {
		report_at(ctx, t, NULL, "syntax error: expected a static API, found '%s'", t->text);
	}
}

int cfg_parse(struct cfg_ctx *ctx, const char *text, const char *name)
{
	int errors = ctx->nerrors;
	struct tok *saved_toks = ctx->toks;
	int saved_n = ctx->ntoks, saved_cap = ctx->captoks, saved_pos = ctx->pos, saved_depth = ctx->dom_depth;

	if (ctx->root == NULL)
		ctx->root = intern(ctx, name, strlen(name));
	ctx->toks = NULL;
	ctx->ntoks = 0;
	ctx->captoks = 0;
	ctx->pos = 0;
	ctx->dom_depth = 0;
	tokenize(ctx, text, name);
	for (;;) {
		struct tok *t = peek(ctx, 0);

		if (t->kind == TK_EOF)
			break;
		if (t->kind == TK_ID && is_punct(peek(ctx, 1), "(")) {
			int a = api_lookup(t->text);
			const char *what;

			if (a >= 0) {
				parse_api(ctx, (enum api)a);
				continue;
			}
			if (strcmp(t->text, "DOMAIN") == 0) {
				parse_domain(ctx);
				continue;
			}
			if ((what = unsupported_api(t->text)) != NULL) {
				report_at(ctx, t, t->text, "a static API of TOPPERS/HRP2 (%s) not supported by ev3lx", what);
				skip_statement(ctx);
				continue;
			}
			if ((what = hrp3_only_api(t->text)) != NULL) {
				report_at(ctx, t, t->text, "a static API of TOPPERS/HRP3 (%s) not supported by ev3lx", what);
				skip_statement(ctx);
				continue;
			}
			if ((what = foreign_api(t->text)) != NULL) {
				report_at(ctx, t, t->text, "unknown static API: %s", what);
				skip_statement(ctx);
				continue;
			}
			if (looks_like_api(t->text) && !t->cfg_text) {
				report_at(ctx, t, t->text, "unknown static API");
				skip_c_declaration(ctx);
				continue;
			}
		}
		if (t->kind == TK_ID && strcmp(t->text, "KERNEL_DOMAIN") == 0 && is_punct(peek(ctx, 1), "{")) {
			next(ctx);
			enter_domain(ctx, t, 0, "KERNEL_DOMAIN");
			continue;
		}
		if (is_punct(t, "}") && ctx->dom_depth > 0) {
			next(ctx);
			ctx->dom_depth--;
			if (is_punct(peek(ctx, 0), ";"))
				next(ctx);
			continue;
		}
		if (is_punct(t, ";")) {
			next(ctx);
			continue;
		}
		if (t->cfg_text) {
			/* configuration text is static APIs only, as for TOPPERS's configurator */
			report_not_api(ctx, t);
			skip_statement(ctx);
			continue;
		}
		skip_c_declaration(ctx);
	}
	if (ctx->dom_depth > 0)
		report(ctx, peek(ctx, 0)->file, peek(ctx, 0)->line, "DOMAIN", "missing '}' at the end of the file");
	free_toks(ctx);
	ctx->toks = saved_toks;
	ctx->ntoks = saved_n;
	ctx->captoks = saved_cap;
	ctx->pos = saved_pos;
	ctx->dom_depth = saved_depth;
	return ctx->nerrors - errors;
}

int cfg_errors(const struct cfg_ctx *ctx)
{
	return ctx->nerrors;
}

int cfg_finish(struct cfg_ctx *ctx)
{
	int errors = ctx->nerrors;
	int counters[API_COUNT] = { 0 };
	int modules = 0;

	for (int i = 0; i < ctx->nobjs; i++) {
		struct obj *o = &ctx->objs[i];

		if (o->api == API_ATT_MOD) {
			o->number = ++modules;
			if (o->domain >= 0)
				continue;
			/* Outside a DOMAIN block: the application's domain when there is one. */
			if (ctx->ndomains == 1)
				o->domain = 1;
			else if (ctx->ndomains == 0)
				o->domain = 0;
			else
				report(ctx, o->file, o->line, "ATT_MOD",
				       "\"%s\" outside DOMAIN() is ambiguous with %d user domains; put it inside one (E_RSATR)",
				       o->id, ctx->ndomains);
			continue;
		}
		if (!apis[o->api].has_id)
			continue;
		o->number = ++counters[id_kind(o->api)];
	}
	if (ctx->library)
		for (int i = 0; i < ctx->nobjs; i++) {
			struct obj *o = &ctx->objs[i];

			/* counted from the top: the kind's last object is TNUM_xxx */
			if (apis[o->api].has_id)
				o->number -= counters[id_kind(o->api)] + 1;
		}
	/* The handler tasks of EV3 cyclic handlers come after the application's tasks. */
	for (int i = 0; i < ctx->nobjs; i++)
		if (ctx->objs[i].api == API_EV3_CRE_CYC)
			ctx->objs[i].task_number = ++counters[API_CRE_TSK];
	return ctx->nerrors - errors;
}

/* ---- output ---- */

int cfg_module_count(const struct cfg_ctx *ctx)
{
	int n = 0;

	for (int i = 0; i < ctx->nobjs; i++)
		n += ctx->objs[i].api == API_ATT_MOD;
	return n;
}

static const struct obj *module_at(const struct cfg_ctx *ctx, int index)
{
	for (int i = 0; i < ctx->nobjs; i++)
		if (ctx->objs[i].api == API_ATT_MOD && ctx->objs[i].number == index)
			return &ctx->objs[i];
	return NULL;
}

const char *cfg_module_object(const struct cfg_ctx *ctx, int index)
{
	const struct obj *o = module_at(ctx, index);

	return o != NULL ? o->id : NULL;
}

int cfg_bind_modules(struct cfg_ctx *ctx, const char *const *objects, int nobjects)
{
	int errors = ctx->nerrors;
	int kept = 0, modules = 0;

	for (int i = 0; i < ctx->nobjs; i++) {
		struct obj *o = &ctx->objs[i];

		if (o->api == API_ATT_MOD) {
			for (int k = 0; k < nobjects && o->path == NULL; k++) {
				const char *slash = strrchr(objects[k], '/');

				if (strcmp(slash != NULL ? slash + 1 : objects[k], o->id) == 0)
					o->path = objects[k];
			}
			if (o->path == NULL) {
				/* As on EV3RT, where a stale ATT_MOD's linker pattern
				 * matches nothing: the module is dropped, the rest kept. */
				warn(ctx, o->file, o->line, "ATT_MOD",
				     "\"%s\" is not one of the app's objects; ignored", o->id);
				free(o->id);
				continue;
			}
			o->number = ++modules;
		}
		ctx->objs[kept++] = *o;
	}
	ctx->nobjs = kept;
	return ctx->nerrors - errors;
}

const char *cfg_module_path(const struct cfg_ctx *ctx, int index)
{
	const struct obj *o = module_at(ctx, index);

	return o != NULL ? o->path : NULL;
}

/* A relocatable link (ld -r -T script) gathers the module's code and
 * read-only data into ev3mod_N_text and its data and bss into ev3mod_N_data,
 * so that the final link provides __start_/__stop_ symbols bounding them.  A
 * word at the end of each keeps an empty part from vanishing.  The host's
 * position-independent code keeps its relocated constants (a C++ class's
 * vtable) in .data.rel.ro, which the loader writes: they go with the data,
 * or the text part would be writable and its segment writable and
 * executable (an ARM926 build without -fpic has no such section). */
void cfg_write_module_script(const struct cfg_ctx *ctx, FILE *out, int index)
{
	const struct obj *o = module_at(ctx, index);

	fprintf(out, "/* ATT_MOD(\"%s\") from %s:%d — generated by ev3cfg, do not edit. */\n",
		o ? o->id : "?", o ? o->file : "?", o ? o->line : 0);
	fprintf(out, "SECTIONS\n{\n");
	fprintf(out, "\tev3mod_%d_text : { *(.text .text.* .rodata .rodata.*) LONG(0) }\n", index);
	fprintf(out, "\tev3mod_%d_data : { *(.data.rel.ro .data.rel.ro.* .data .data.* .bss .bss.* COMMON) LONG(0) }\n", index);
	fprintf(out, "}\n");
}

static const char *domain_expr(const struct cfg_ctx *ctx, int domain)
{
	return domain > 0 ? ctx->domains[domain - 1] : "TDOM_KERNEL";
}

/* The name of the count of an object kind's IDs (TNUM_TSKID ...). */
static const char *tnum_of(enum api a)
{
	switch (id_kind(a)) {
	case API_CRE_SEM: return "TNUM_SEMID";
	case API_CRE_FLG: return "TNUM_FLGID";
	case API_CRE_DTQ: return "TNUM_DTQID";
	case API_CRE_PDQ: return "TNUM_PDQID";
	case API_CRE_MTX: return "TNUM_MTXID";
	case API_CRE_CYC: return "TNUM_CYCID";
	case API_CRE_ALM: return "TNUM_ALMID";
	default:          return "TNUM_TSKID";
	}
}

void cfg_write_header(const struct cfg_ctx *ctx, FILE *out, const char *symbol)
{
	/* a library's header has a guard of its own: a unit may see an app's too */
	const char *guard = ctx->library ? "EV3CFG_LIBRARY_KERNEL_CFG_H" : "TOPPERS_KERNEL_CFG_H";

	fprintf(out, "/* kernel_cfg.h — object IDs of the configuration; generated by ev3cfg, do not edit. */\n");
	fprintf(out, "#ifndef %s\n#define %s\n\n", guard, guard);
	for (int i = 0; i < ctx->ndomains; i++)
		if (ctx->library)	/* the application's name for its domain: it may define it too */
			fprintf(out, "#ifndef %s\n#define %s %d\n#endif\n", ctx->domains[i], ctx->domains[i], i + 1);
		else
			fprintf(out, "#define %s %d\n", ctx->domains[i], i + 1);
	if (ctx->library) {
		static const enum api kinds[] = { API_CRE_TSK, API_CRE_SEM, API_CRE_FLG, API_CRE_DTQ, API_CRE_PDQ,
						  API_CRE_MTX, API_CRE_CYC, API_CRE_ALM };

		/* how many IDs the library takes at the top of each range: what lies below is free */
		for (size_t k = 0; k < sizeof(kinds) / sizeof(kinds[0]); k++) {
			int n = 0;

			for (int i = 0; i < ctx->nobjs; i++)
				n += apis[ctx->objs[i].api].has_id && id_kind(ctx->objs[i].api) == kinds[k];
			fprintf(out, "#define EV3LX_LIB_NUM_%s %d\n", tnum_of(kinds[k]) + 5, n);
		}
	}
	for (int i = 0; i < ctx->nobjs; i++) {
		const struct obj *o = &ctx->objs[i];

		if (apis[o->api].has_id && o->number < 0)
			fprintf(out, "#define %s (%s - %d)\n", o->id, tnum_of(o->api), -o->number - 1);
		else if (apis[o->api].has_id)
			fprintf(out, "#define %s %d\n", o->id, o->number);
		if (o->api == API_EV3_CRE_CYC)
			fprintf(out, "#define EV3_CYC_TASK_%s %d\n", o->id, o->task_number);
	}
	fprintf(out, "\n#ifndef TOPPERS_MACRO_ONLY\nstruct rtos_cfg;\n");
	fprintf(out, "/* The configuration to boot (rtos_host_boot on the host). */\n");
	fprintf(out, "extern const struct rtos_cfg %s;\n#endif\n\n#endif\n", symbol);
}

/* Output with line counting, so generated code can be given its own #line. */
struct out {
	FILE *f;
	int line;
	const char *name;
};

static void __attribute__((format(printf, 2, 3))) emit(struct out *o, const char *fmt, ...)
{
	char buf[4096];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(buf, sizeof(buf), fmt, ap);
	va_end(ap);
	for (const char *c = buf; *c; c++)
		o->line += *c == '\n';
	fputs(buf, o->f);
}

/* Positions what follows at the static API's own line (compiler messages name it). */
static void at_api(struct out *o, const struct obj *ob)
{
	emit(o, "#line %d \"%s\"\n", ob->line, ob->file);
}

/* Back to the generated file's own numbering. */
static void at_self(struct out *o)
{
	emit(o, "#line %d \"%s\"\n", o->line + 1, o->name);
}

/* A pass-2 check: cond must hold, else the compiler reports msg at the API's line. */
static void __attribute__((format(printf, 4, 5)))
check(struct out *o, const struct obj *ob, const char *cond, const char *fmt, ...)
{
	char msg[512];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	at_api(o, ob);
	emit(o, "_Static_assert(%s, \"%s\");\n", cond, msg);
}

static void emit_checks(const struct cfg_ctx *ctx, struct out *o, const struct obj *ob)
{
	const char *id = ob->id;
	char c[1024];

	switch (ob->api) {
	case API_CRE_TSK:
		snprintf(c, sizeof(c), "((%s) & ~(ATR)TA_ACT) == 0", ob->elem[0]);
		check(o, ob, c, "CRE_TSK(%s): illegal tskatr, only TA_ACT is known (E_RSATR)", id);
		snprintf(c, sizeof(c), "(%s) >= TMIN_TPRI && (%s) <= TMAX_TPRI", ob->elem[3], ob->elem[3]);
		check(o, ob, c, "CRE_TSK(%s): itskpri out of range TMIN_TPRI..TMAX_TPRI (E_PAR)", id);
		if (ob->domain > 0 && !ctx->library) {	/* a library's platform tasks may run above apps */
			snprintf(c, sizeof(c), "(%s) >= TMIN_APP_TPRI", ob->elem[3]);
			check(o, ob, c, "CRE_TSK(%s): itskpri above TMIN_APP_TPRI for a task of DOMAIN(%s) (E_PAR)",
			      id, ctx->domains[ob->domain - 1]);
		}
		snprintf(c, sizeof(c), "(%s) > 0 && (%s) <= EV3CFG_MAX_STKSZ", ob->elem[4], ob->elem[4]);
		check(o, ob, c, "CRE_TSK(%s): stksz out of range 1..EV3CFG_MAX_STKSZ (8 MiB, an eighth of the "
		      "EV3 RAM of 64 MB) (E_PAR)", id);
		if (ob->nelem >= 7) {
			snprintf(c, sizeof(c), "(%s) >= 0 && (%s) <= EV3CFG_MAX_STKSZ", ob->elem[6], ob->elem[6]);
			check(o, ob, c, "CRE_TSK(%s): sstksz out of range 0..EV3CFG_MAX_STKSZ (8 MiB) (E_PAR)", id);
		}
		break;
	case API_CRE_SEM:
		snprintf(c, sizeof(c), "((%s) & ~(ATR)TA_TPRI) == 0", ob->elem[0]);
		check(o, ob, c, "CRE_SEM(%s): illegal sematr (E_RSATR)", id);
		snprintf(c, sizeof(c), "(%s) >= 1 && (%s) >= 0 && (%s) <= (%s)", ob->elem[2], ob->elem[1],
			 ob->elem[1], ob->elem[2]);
		check(o, ob, c, "CRE_SEM(%s): needs 1 <= maxsem and 0 <= isemcnt <= maxsem (E_PAR)", id);
		break;
	case API_CRE_FLG:
		snprintf(c, sizeof(c), "((%s) & ~(ATR)(TA_TPRI | TA_WMUL | TA_CLR)) == 0", ob->elem[0]);
		check(o, ob, c, "CRE_FLG(%s): illegal flgatr (E_RSATR)", id);
		break;
	case API_CRE_DTQ:
		snprintf(c, sizeof(c), "((%s) & ~(ATR)TA_TPRI) == 0", ob->elem[0]);
		check(o, ob, c, "CRE_DTQ(%s): illegal dtqatr (E_RSATR)", id);
		snprintf(c, sizeof(c), "(%s) >= 0 && (%s) <= 65536", ob->elem[1], ob->elem[1]);
		check(o, ob, c, "CRE_DTQ(%s): dtqcnt out of range 0..65536 (E_PAR)", id);
		break;
	case API_CRE_PDQ:
		snprintf(c, sizeof(c), "((%s) & ~(ATR)TA_TPRI) == 0", ob->elem[0]);
		check(o, ob, c, "CRE_PDQ(%s): illegal pdqatr (E_RSATR)", id);
		snprintf(c, sizeof(c), "(%s) >= 0 && (%s) <= 65536", ob->elem[1], ob->elem[1]);
		check(o, ob, c, "CRE_PDQ(%s): pdqcnt out of range 0..65536 (E_PAR)", id);
		snprintf(c, sizeof(c), "(%s) >= TMIN_DPRI && (%s) <= TMAX_DPRI", ob->elem[2], ob->elem[2]);
		check(o, ob, c, "CRE_PDQ(%s): maxdpri out of range TMIN_DPRI..TMAX_DPRI (E_PAR)", id);
		break;
	case API_CRE_MTX:
		snprintf(c, sizeof(c), "(%s) == TA_NULL || (%s) == TA_TPRI || (%s) == TA_CEILING || (%s) == TA_INHERIT",
			 ob->elem[0], ob->elem[0], ob->elem[0], ob->elem[0]);
		check(o, ob, c, "CRE_MTX(%s): illegal mtxatr (E_RSATR)", id);
		if (ob->nelem == 2) {
			snprintf(c, sizeof(c), "(%s) != TA_CEILING || ((%s) >= TMIN_TPRI && (%s) <= TMAX_TPRI)",
				 ob->elem[0], ob->elem[1], ob->elem[1]);
			check(o, ob, c, "CRE_MTX(%s): ceilpri out of range TMIN_TPRI..TMAX_TPRI (E_PAR)", id);
		} else {
			snprintf(c, sizeof(c), "(%s) != TA_CEILING", ob->elem[0]);
			check(o, ob, c, "CRE_MTX(%s): TA_CEILING needs a ceilpri (E_PAR)", id);
		}
		break;
	case API_CRE_CYC:
		if (ob->nfy) {
			/* HRP3: TA_STA only; times in us up to HRP3's TMAX_RELTIM (kernel/cyclic.trb) */
			snprintf(c, sizeof(c), "((%s) & ~(ATR)TA_STA) == 0", ob->elem[0]);
			check(o, ob, c, "CRE_CYC(%s): illegal cycatr: HRP3 has TA_STA only (E_RSATR)", id);
			snprintf(c, sizeof(c), "(%s) > 0 && (%s) <= TMAX_RELTIM", ob->elem[2], ob->elem[2]);
			check(o, ob, c, "CRE_CYC(%s): cyctim out of range 1..TMAX_RELTIM (E_PAR)", id);
			snprintf(c, sizeof(c), "(%s) >= 0 && (%s) <= TMAX_RELTIM", ob->elem[3], ob->elem[3]);
			check(o, ob, c, "CRE_CYC(%s): cycphs out of range 0..TMAX_RELTIM (E_PAR)", id);
			break;
		}
		/* fall through */
	case API_EV3_CRE_CYC:
		snprintf(c, sizeof(c), "((%s) & ~(ATR)(TA_STA | TA_PHS)) == 0", ob->elem[0]);
		check(o, ob, c, "%s(%s): illegal cycatr (E_RSATR)", apis[ob->api].name, id);
		snprintf(c, sizeof(c), "(%s) > 0 && (%s) <= TMAX_RELTIM", ob->elem[3], ob->elem[3]);
		check(o, ob, c, "%s(%s): cyctim out of range 1..TMAX_RELTIM (E_PAR)", apis[ob->api].name, id);
		snprintf(c, sizeof(c), "(%s) >= 0 && (%s) <= TMAX_RELTIM", ob->elem[4], ob->elem[4]);
		check(o, ob, c, "%s(%s): cycphs out of range 0..TMAX_RELTIM (E_PAR)", apis[ob->api].name, id);
		break;
	case API_CRE_ALM:
		snprintf(c, sizeof(c), "(%s) == TA_NULL", ob->elem[0]);
		check(o, ob, c, "CRE_ALM(%s): illegal almatr (E_RSATR)", id);
		break;
	case API_DEF_SVC:
		snprintf(c, sizeof(c), "(%s) >= 1 && (%s) <= TNUM_FNCD", ob->id, ob->id);
		check(o, ob, c, "DEF_SVC(%s): fncd out of range 1..TNUM_FNCD (E_PAR)", ob->id);
		snprintf(c, sizeof(c), "(%s) >= 0 && (%s) <= EV3CFG_MAX_STKSZ", ob->elem[2], ob->elem[2]);
		check(o, ob, c, "DEF_SVC(%s): stksz out of range 0..EV3CFG_MAX_STKSZ (8 MiB) (E_PAR)", ob->id);
		break;
	default:
		break;
	}
}

/* The sum of every task's stack (each counted once it is in range, so that
 * one bad size gives one error), at the last task's line: within
 * EV3CFG_MAX_STACKS, half the EV3's RAM. */
static void emit_stack_total(const struct cfg_ctx *ctx, struct out *o)
{
	const struct obj *last = NULL;

	for (int i = 0; i < ctx->nobjs; i++)
		if (ctx->objs[i].api == API_CRE_TSK || ctx->objs[i].api == API_EV3_CRE_CYC)
			last = &ctx->objs[i];
	if (last == NULL)
		return;
	at_api(o, last);
	emit(o, "_Static_assert(0ULL");
	for (int i = 0; i < ctx->nobjs; i++) {
		const struct obj *ob = &ctx->objs[i];

		if (ob->api == API_CRE_TSK)
			emit(o, " + ((%s) > 0 && (%s) <= EV3CFG_MAX_STKSZ ? (unsigned long long)(%s) : 0ULL)",
			     ob->elem[4], ob->elem[4], ob->elem[4]);
		else if (ob->api == API_EV3_CRE_CYC)
			emit(o, " + (unsigned long long)EV3CFG_CYC_STACK");
	}
	emit(o, " <= EV3CFG_MAX_STACKS, \"%s: the task stacks of the configuration total more than "
	     "EV3CFG_MAX_STACKS (32 MiB, half the EV3 RAM of 64 MB) (E_NOMEM)\");\n", last->id);
}

/* Writes one table: rows of every object of api kind(s), formatted by row(). */
static int count_api(const struct cfg_ctx *ctx, enum api a, enum api b)
{
	int n = 0;

	for (int i = 0; i < ctx->nobjs; i++)
		n += ctx->objs[i].api == a || ctx->objs[i].api == b;
	return n;
}

/* The handler a notification's row names: TNFY_HANDLER's own, else the one
 * emit_nfy_handler writes (a static buffer, used at once). */
static const char *nfy_handler(const struct obj *ob)
{
	static char name[200];

	if (ob->nfymode == NFY_HANDLER)
		snprintf(name, sizeof(name), "(%s)(%s)", ob->api == API_CRE_CYC ? "CYCHDR" : "ALMHDR", ob->nfy_elem[2]);
	else
		snprintf(name, sizeof(name), "ev3cfg_nfy_%s", ob->id);
	return name;
}

/* Writes the handler of an HRP3 notification other than TNFY_HANDLER, as
 * HRP3's configurator generates it (kernel/kernel.trb): it runs in non-task
 * context with par1 as exinf, does the notification and, when that fails and
 * a TENFY_* is given, the error notification. */
static void emit_nfy_handler(struct out *o, const struct obj *ob)
{
	unsigned mode1 = ob->nfymode & 0x0fU, mode2 = ob->nfymode & ~0x0fU;
	int epar = mode1 == NFY_SETFLG || mode1 == NFY_SNDDTQ ? 3 : 2;
	const char *call = NULL;
	char *const *p = ob->nfy_elem;

	at_api(o, ob);
	emit(o, "static void ev3cfg_nfy_%s(intptr_t exinf)\n{\n", ob->id);
	switch (mode1) {
	case NFY_SETVAR:
		emit(o, "\t*((intptr_t *)exinf) = (intptr_t)(%s);\n}\n", p[2]);
		return;
	case NFY_INCVAR:
		emit(o, "\t(void)iloc_cpu();\n\t*((intptr_t *)exinf) += 1;\n\t(void)iunl_cpu();\n}\n");
		return;
	case NFY_ACTTSK: call = "iact_tsk((ID)exinf)"; break;
	case NFY_WUPTSK: call = "iwup_tsk((ID)exinf)"; break;
	case NFY_SIGSEM: call = "isig_sem((ID)exinf)"; break;
	default: break;
	}
	if (mode2 == 0) {
		if (call != NULL)
			emit(o, "\t(void)%s;\n}\n", call);
		else if (mode1 == NFY_SETFLG)
			emit(o, "\t(void)iset_flg((ID)exinf, (FLGPTN)(%s));\n}\n", p[2]);
		else
			emit(o, "\t(void)ipsnd_dtq((ID)exinf, (intptr_t)(%s));\n}\n", p[2]);
		return;
	}
	if (call != NULL)
		emit(o, "\tER ercd = %s;\n", call);
	else if (mode1 == NFY_SETFLG)
		emit(o, "\tER ercd = iset_flg((ID)exinf, (FLGPTN)(%s));\n", p[2]);
	else
		emit(o, "\tER ercd = ipsnd_dtq((ID)exinf, (intptr_t)(%s));\n", p[2]);
	emit(o, "\n\tif (ercd != E_OK) {\n");
	switch (mode2) {
	case ENFY_SETVAR: emit(o, "\t\t*(intptr_t *)(%s) = (intptr_t)ercd;\n", p[epar]); break;
	case ENFY_INCVAR:
		emit(o, "\t\t(void)iloc_cpu();\n\t\t*(intptr_t *)(%s) += 1;\n\t\t(void)iunl_cpu();\n", p[epar]);
		break;
	case ENFY_ACTTSK: emit(o, "\t\t(void)iact_tsk(%s);\n", p[epar]); break;
	case ENFY_WUPTSK: emit(o, "\t\t(void)iwup_tsk(%s);\n", p[epar]); break;
	case ENFY_SIGSEM: emit(o, "\t\t(void)isig_sem(%s);\n", p[epar]); break;
	case ENFY_SETFLG: emit(o, "\t\t(void)iset_flg(%s, (FLGPTN)(%s));\n", p[epar], p[epar + 1]); break;
	default: emit(o, "\t\t(void)ipsnd_dtq(%s, (intptr_t)ercd);\n", p[epar]); break;
	}
	emit(o, "\t}\n}\n");
}

static void emit_row(const struct cfg_ctx *ctx, struct out *o, const struct obj *ob)
{
	const char *const *e = (const char *const *)ob->elem;

	at_api(o, ob);
	switch (ob->api) {
	case API_CRE_TSK:
		emit(o, "\t{ %s, %s, (intptr_t)(%s), %s, %s, %s, %s, \"%s\" },\n", ob->id, e[0], e[1], e[2], e[3],
		     e[4], domain_expr(ctx, ob->domain), ob->id);
		break;
	case API_EV3_CRE_CYC:	/* its handler task */
		emit(o, "\t{ EV3_CYC_TASK_%s, TA_ACT, (intptr_t)&ev3cfg_cyc_%s, ev3cfg_cyc_task, TMIN_APP_TPRI, "
		     "EV3CFG_CYC_STACK, %s, \"%s\" },\n", ob->id, ob->id, domain_expr(ctx, ob->domain), ob->id);
		break;
	case API_CRE_SEM:
		emit(o, "\t{ %s, %s, %s, %s, \"%s\" },\n", ob->id, e[0], e[1], e[2], ob->id);
		break;
	case API_CRE_FLG:
		emit(o, "\t{ %s, %s, %s, \"%s\" },\n", ob->id, e[0], e[1], ob->id);
		break;
	case API_CRE_DTQ:
		emit(o, "\t{ %s, %s, %s, \"%s\" },\n", ob->id, e[0], e[1], ob->id);
		break;
	case API_CRE_PDQ:
		emit(o, "\t{ %s, %s, %s, %s, \"%s\" },\n", ob->id, e[0], e[1], e[2], ob->id);
		break;
	case API_CRE_MTX:
		emit(o, "\t{ %s, %s, %s, \"%s\" },\n", ob->id, e[0], ob->nelem == 2 ? e[1] : "0", ob->id);
		break;
	case API_CRE_CYC:
		if (ob->nfy)
			emit(o, "\t{ %s, %s, (intptr_t)(%s), %s, %s, %s, \"%s\" },\n", ob->id, e[0], ob->nfy_elem[1],
			     nfy_handler(ob), e[2], e[3], ob->id);
		else
			emit(o, "\t{ %s, %s, (intptr_t)(%s), %s, %s, %s, \"%s\" },\n", ob->id, e[0], e[1], e[2], e[3],
			     e[4], ob->id);
		break;
	case API_CRE_ALM:
		if (ob->nfy)
			emit(o, "\t{ %s, %s, (intptr_t)(%s), %s, \"%s\" },\n", ob->id, e[0], ob->nfy_elem[1],
			     nfy_handler(ob), ob->id);
		else
			emit(o, "\t{ %s, %s, (intptr_t)(%s), %s, \"%s\" },\n", ob->id, e[0], e[1], e[2], ob->id);
		break;
	case API_ATT_INI:
	case API_ATT_TER:
		emit(o, "\t{ %s, (intptr_t)(%s) },\n", e[2], e[1]);
		break;
	case API_DEF_SVC:
		emit(o, "\t{ %s, (EXTSVC)(%s), %s },\n", ob->id, e[1], e[2]);
		break;
	case API_CFG_INT:
		emit(o, "\t{ %s, %s, %s },\n", ob->id, e[0], e[1]);
		break;
	case API_ATT_ISR:
		emit(o, "\t{ %s, (intptr_t)(%s), %s, %s, %s },\n", e[0], e[1], e[2], e[3], e[4]);
		break;
	default:
		break;
	}
}

/* Emits "static const struct type name[] = { rows };" for apis a and b; returns the row count. */
static int emit_table(const struct cfg_ctx *ctx, struct out *o, const char *type, const char *name,
		      enum api a, enum api b)
{
	int n = count_api(ctx, a, b);

	if (n == 0)
		return 0;
	emit(o, "\nstatic const struct %s %s[] = {\n", type, name);
	for (int i = 0; i < ctx->nobjs; i++)
		if (ctx->objs[i].api == a || ctx->objs[i].api == b)
			emit_row(ctx, o, &ctx->objs[i]);
	at_self(o);
	emit(o, "};\n");
	return n;
}

void cfg_write_source(const struct cfg_ctx *ctx, FILE *f, const char *symbol, const char *source_name)
{
	struct out o = { f, 1, source_name };
	static const struct { const char *type, *name, *field; enum api a, b; } tables[] = {
		{ "rtos_task_cfg", "ev3cfg_tasks", "tasks", API_CRE_TSK, API_EV3_CRE_CYC },
		{ "rtos_sem_cfg", "ev3cfg_sems", "sems", API_CRE_SEM, API_COUNT },
		{ "rtos_flg_cfg", "ev3cfg_flgs", "flgs", API_CRE_FLG, API_COUNT },
		{ "rtos_dtq_cfg", "ev3cfg_dtqs", "dtqs", API_CRE_DTQ, API_COUNT },
		{ "rtos_pdq_cfg", "ev3cfg_pdqs", "pdqs", API_CRE_PDQ, API_COUNT },
		{ "rtos_mtx_cfg", "ev3cfg_mtxs", "mtxs", API_CRE_MTX, API_COUNT },
		{ "rtos_cyc_cfg", "ev3cfg_cycs", "cycs", API_CRE_CYC, API_COUNT },
		{ "rtos_alm_cfg", "ev3cfg_alms", "alms", API_CRE_ALM, API_COUNT },
		{ "rtos_int_cfg", "ev3cfg_ints", "ints", API_CFG_INT, API_COUNT },
		{ "rtos_isr_cfg", "ev3cfg_isrs", "isrs", API_ATT_ISR, API_COUNT },
		{ "rtos_ini_cfg", "ev3cfg_inis", "inis", API_ATT_INI, API_COUNT },
		{ "rtos_ter_cfg", "ev3cfg_ters", "ters", API_ATT_TER, API_COUNT },
		{ "rtos_svc_cfg", "ev3cfg_svcs", "svcs", API_DEF_SVC, API_COUNT },
	};
	int rows[sizeof(tables) / sizeof(tables[0])];
	int nmods = 0, nsecs = 0, nev3cyc = count_api(ctx, API_EV3_CRE_CYC, API_COUNT), ntables = 0;

	emit(&o, "/* %s — the configuration's tables; generated by ev3cfg, do not edit. */\n", source_name);
	if (cfg_profile(ctx) == CFG_PROFILE_HRP3)
		emit(&o, "#ifndef EV3LX_KERNEL_HRP3\n#define EV3LX_KERNEL_HRP3 1\n#endif\n");
	emit(&o, "#include \"kernel.h\"\n#include \"rtos_cfg.h\"\n#include \"kernel_cfg.h\"\n");
	for (int i = 0; i < ctx->nc_includes; i++)
		emit(&o, "%s\n", ctx->c_includes[i]);
	at_self(&o);
	emit(&o, "\n/* Bounds of sizes (ev3cfg, docs/ev3rt-apps.md): the EV3 has 64 MB of RAM. */\n");
	emit(&o, "#define EV3CFG_MAX_STKSZ %s\n#define EV3CFG_MAX_STACKS %s\n", EV3CFG_MAX_STKSZ_TEXT,
	     EV3CFG_MAX_STACKS_TEXT);
	for (int i = 0; i < ctx->nobjs; i++)
		if (ctx->objs[i].api == API_INCLUDE_TABLE)
			emit(&o, "extern const struct rtos_cfg %s;\n", ctx->objs[i].id);
	if (nev3cyc > 0) {
		emit(&o, "\n#ifndef EV3CFG_CYC_STACK\n#define EV3CFG_CYC_STACK 4096\n#endif\n");
		emit(&o, "\n/* EV3_CRE_CYC: the handler runs in its own task, woken by a kernel cyclic handler. */\n");
		emit(&o, "struct ev3cfg_cyc {\n\tvoid (*handler)(intptr_t exinf);\n\tintptr_t exinf;\n};\n\n");
		emit(&o, "static void ev3cfg_cyc_task(intptr_t arg)\n{\n"
			 "\tconst struct ev3cfg_cyc *c = (const struct ev3cfg_cyc *)arg;\n\n"
			 "\tfor (;;)\n\t\tif (slp_tsk() == E_OK)\n\t\t\tc->handler(c->exinf);\n}\n\n");
		emit(&o, "static void ev3cfg_cyc_wake(intptr_t tskid)\n{\n\t(void)iwup_tsk((ID)tskid);\n}\n");
		for (int i = 0; i < ctx->nobjs; i++) {
			const struct obj *ob = &ctx->objs[i];

			if (ob->api != API_EV3_CRE_CYC)
				continue;
			at_api(&o, ob);
			emit(&o, "static const struct ev3cfg_cyc ev3cfg_cyc_%s = { %s, (intptr_t)(%s) };\n", ob->id,
			     ob->elem[2], ob->elem[1]);
		}
		at_self(&o);
	}
	for (int i = 0; i < ctx->nobjs; i++)
		if (ctx->objs[i].nfy && ctx->objs[i].nfymode != NFY_HANDLER) {
			if (i == 0 || !ctx->objs[i - 1].nfy)
				emit(&o, "\n/* HRP3's notifications, as its configurator writes them. */\n");
			emit_nfy_handler(&o, &ctx->objs[i]);
		}
	at_self(&o);
	for (size_t t = 0; t < sizeof(tables) / sizeof(tables[0]); t++) {
		if (tables[t].a == API_CRE_CYC) {
			/* kernel cyclic handlers: CRE_CYC rows, then one per EV3_CRE_CYC */
			int n = count_api(ctx, API_CRE_CYC, API_EV3_CRE_CYC);

			rows[t] = n;
			if (n == 0)
				continue;
			emit(&o, "\nstatic const struct rtos_cyc_cfg ev3cfg_cycs[] = {\n");
			for (int i = 0; i < ctx->nobjs; i++) {
				const struct obj *ob = &ctx->objs[i];

				if (ob->api == API_CRE_CYC) {
					emit_row(ctx, &o, ob);
				} else if (ob->api == API_EV3_CRE_CYC) {
					at_api(&o, ob);
					emit(&o, "\t{ %s, %s, EV3_CYC_TASK_%s, ev3cfg_cyc_wake, %s, %s, \"%s\" },\n", ob->id,
					     ob->elem[0], ob->id, ob->elem[3], ob->elem[4], ob->id);
				}
			}
			at_self(&o);
			emit(&o, "};\n");
			continue;
		}
		rows[t] = emit_table(ctx, &o, tables[t].type, tables[t].name, tables[t].a, tables[t].b);
	}
	nmods = 0;
	for (int i = 0; i < ctx->nobjs; i++) {
		nmods += ctx->objs[i].api == API_ATT_MOD && ctx->objs[i].domain > 0;
		nsecs += ctx->objs[i].api == API_ATA_SEC;
	}
	if (nmods > 0 || nsecs > 0) {
		emit(&o, "\n/* ATT_MOD: each module's code and data; ATA_SEC: a section's user-domain access;\n"
			 " * bounded by the linker. */\n");
		for (int i = 0; i < ctx->nobjs; i++)
			if (ctx->objs[i].api == API_ATA_SEC)	/* weak: a target may leave the section out */
				emit(&o, "extern char __start_%s[] __attribute__((weak)), __stop_%s[] __attribute__((weak));\n",
				     ctx->objs[i].id, ctx->objs[i].id);
		for (int i = 0; i < ctx->nobjs; i++) {
			const struct obj *ob = &ctx->objs[i];

			if (ob->api == API_ATT_MOD && ob->domain > 0)
				emit(&o, "extern char __start_ev3mod_%d_text[], __stop_ev3mod_%d_text[];\n"
					 "extern char __start_ev3mod_%d_data[], __stop_ev3mod_%d_data[];\n",
				     ob->number, ob->number, ob->number, ob->number);
		}
		emit(&o, "static struct rtos_mem_cfg ev3cfg_mems[%d + %d * TNUM_DOMID];\n\n", 2 * nmods, nsecs);
		emit(&o, "/* The bounds are link-time addresses: filled in before main(), before any boot. */\n");
		emit(&o, "__attribute__((constructor)) static void ev3cfg_modules(void)\n{\n");
		for (int i = 0, row = 0; i < ctx->nobjs; i++) {
			const struct obj *ob = &ctx->objs[i];

			if (ob->api != API_ATT_MOD || ob->domain <= 0)
				continue;
			emit(&o, "\tev3cfg_mems[%d] = (struct rtos_mem_cfg){ %s, __start_ev3mod_%d_text,\n"
				 "\t\t(SIZE)(__stop_ev3mod_%d_text - __start_ev3mod_%d_text), TPM_READ | TPM_EXEC, "
				 "\"%s code\" };\n", row++, domain_expr(ctx, ob->domain), ob->number, ob->number,
			     ob->number, ob->id);
			emit(&o, "\tev3cfg_mems[%d] = (struct rtos_mem_cfg){ %s, __start_ev3mod_%d_data,\n"
				 "\t\t(SIZE)(__stop_ev3mod_%d_data - __start_ev3mod_%d_data), TPM_READ | TPM_WRITE, "
				 "\"%s data\" };\n", row++, domain_expr(ctx, ob->domain), ob->number, ob->number,
			     ob->number, ob->id);
		}
		if (nsecs > 0)
			emit(&o, "\tint row = %d;\n\n", 2 * nmods);
		for (int i = 0; i < ctx->nobjs; i++) {
			const struct obj *ob = &ctx->objs[i];

			if (ob->api != API_ATA_SEC)
				continue;
			at_api(&o, ob);
			emit(&o, "\tfor (ID dom = 1; dom <= TNUM_DOMID && __start_%s != __stop_%s; dom++)\n"
				 "\t\tev3cfg_mems[row++] = (struct rtos_mem_cfg){ dom, __start_%s,\n"
				 "\t\t\t(SIZE)(__stop_%s - __start_%s),\n"
				 "\t\t\t((%s) == TACP_SHARED ? TPM_READ : 0U) | ((%s) == TACP_SHARED ? TPM_WRITE : 0U),"
				 " \"%s\" };\n", ob->id, ob->id, ob->id, ob->id, ob->id, ob->elem[3], ob->elem[2], ob->id);
			at_self(&o);
		}
		emit(&o, "}\n");
	}
	/* Pass-2 checks of the values, at each static API's line. */
	for (int i = 0; i < ctx->ndomains; i++) {
		emit(&o, "_Static_assert(%s <= TNUM_DOMID, \"DOMAIN(%s): more than TNUM_DOMID user domains (E_NOID)\");\n",
		     ctx->domains[i], ctx->domains[i]);
	}
	for (int i = 0; i < ctx->nobjs; i++)
		emit_checks(ctx, &o, &ctx->objs[i]);
	emit_stack_total(ctx, &o);
	at_self(&o);
	for (int i = 0; i < ctx->nobjs; i++)
		ntables += ctx->objs[i].api == API_INCLUDE_TABLE;
	if (ntables > 0) {
		emit(&o, "\nstatic const struct rtos_cfg *const ev3cfg_includes[] = {");
		for (int i = 0; i < ctx->nobjs; i++)
			if (ctx->objs[i].api == API_INCLUDE_TABLE)
				emit(&o, " &%s,", ctx->objs[i].id);
		emit(&o, " NULL };\n");
	}
	emit(&o, "\nconst struct rtos_cfg %s = {\n\t.name = \"%s\",\n", symbol,
	     ctx->root != NULL ? ctx->root : "configuration");
	for (size_t t = 0; t < sizeof(tables) / sizeof(tables[0]); t++)
		if (rows[t] > 0)
			emit(&o, "\t.%s = RTOS_TABLE(%s),\n", tables[t].field, tables[t].name);
	if (nmods > 0 || nsecs > 0)
		emit(&o, "\t.mems = RTOS_TABLE(ev3cfg_mems),\n");
	if (ntables > 0)
		emit(&o, "\t.includes = ev3cfg_includes,\n");
	if (cfg_profile(ctx) == CFG_PROFILE_HRP3)
		emit(&o, "\t.profile = RTOS_PROFILE_HRP3,\n");
	emit(&o, "};\n");
}

void cfg_write_profile(const struct cfg_ctx *ctx, FILE *f)
{
	fputs("/* The kernel profile the app is built for; generated by ev3cfg, do not edit. */\n", f);
	if (cfg_profile(ctx) == CFG_PROFILE_HRP3)
		fputs("/* TOPPERS/HRP3 (EV3RT 1.x): time in us, HRP3's calls (kernel_hrp3.h). */\n"
		      "#define EV3LX_KERNEL_HRP3 1\n", f);
	else
		fputs("/* TOPPERS/HRP2 (EV3RT 0.x): time in ms. */\n", f);
}

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
	const char *file;
	int line;
};

enum api {
	API_CRE_TSK, API_CRE_SEM, API_CRE_FLG, API_CRE_DTQ, API_CRE_PDQ, API_CRE_MTX,
	API_CRE_CYC, API_CRE_ALM, API_EV3_CRE_CYC, API_ATT_MOD, API_ATT_INI, API_ATT_TER,
	API_DEF_SVC, API_CFG_INT, API_ATT_ISR, API_INCLUDE, API_INCLUDE_TABLE, API_COUNT
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
	[API_CRE_CYC] = { "CRE_CYC", true, false, 5, 5, "cycatr, exinf, cychdr, cyctim, cycphs" },
	[API_CRE_ALM] = { "CRE_ALM", true, false, 3, 3, "almatr, exinf, almhdr" },
	[API_EV3_CRE_CYC] = { "EV3_CRE_CYC", true, false, 5, 5, "cycatr, exinf, cychdr, cyctim, cycphs" },
	[API_ATT_MOD] = { "ATT_MOD", false, false, 0, 0, NULL },
	[API_ATT_INI] = { "ATT_INI", false, false, 3, 3, "iniatr, exinf, inirtn" },
	[API_ATT_TER] = { "ATT_TER", false, false, 3, 3, "teratr, exinf, terrtn" },
	[API_DEF_SVC] = { "DEF_SVC", false, true, 3, 3, "svcatr, svcrtn, stksz" },
	[API_CFG_INT] = { "CFG_INT", false, true, 2, 2, "intatr, intpri" },
	[API_ATT_ISR] = { "ATT_ISR", false, false, 5, 5, "isratr, exinf, intno, isr, isrpri" },
	[API_INCLUDE] = { "INCLUDE", false, false, 0, 0, NULL },
	[API_INCLUDE_TABLE] = { "EV3LX_INCLUDE_TABLE", false, false, 0, 0, NULL },
};

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
};

struct cfg_ctx {
	FILE *err;
	int nerrors;
	cfg_include_fn include;
	void *include_arg;
	struct obj *objs;
	int nobjs, capobjs;
	char **domains;          /* DOMAIN names, 1-based IDs in order of appearance */
	int ndomains;
	char **c_includes;
	int nc_includes;
	const char *root;        /* the first file parsed: the configuration's name */
	char **names;            /* interned file names (tokens point here) */
	int nnames;
	/* parse state */
	struct tok *toks;
	int ntoks, pos;
	int dom_stack[16];
	int dom_depth;
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

/* Reports "file:line: error: API(ID): message" and counts it. */
static void __attribute__((format(printf, 5, 6)))
report(struct cfg_ctx *ctx, const char *file, int line, const char *what, const char *fmt, ...)
{
	va_list ap;

	fprintf(ctx->err, "%s:%d: error: ", file, line);
	if (what != NULL)
		fprintf(ctx->err, "%s: ", what);
	va_start(ap, fmt);
	vfprintf(ctx->err, fmt, ap);
	va_end(ap);
	fputc('\n', ctx->err);
	ctx->nerrors++;
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
	}
	free(ctx->objs);
	for (int i = 0; i < ctx->ndomains; i++)
		free(ctx->domains[i]);
	free(ctx->domains);
	for (int i = 0; i < ctx->nc_includes; i++)
		free(ctx->c_includes[i]);
	free(ctx->c_includes);
	for (int i = 0; i < ctx->nnames; i++)
		free(ctx->names[i]);
	free(ctx->names);
	free(ctx);
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

static void push_tok(struct cfg_ctx *ctx, enum tok_kind kind, const char *s, size_t n, bool space,
		     const char *file, int line)
{
	struct tok *t;

	ctx->toks = xrealloc(ctx->toks, (size_t)(ctx->ntoks + 1) * sizeof(*ctx->toks));
	t = &ctx->toks[ctx->ntoks++];
	t->kind = kind;
	t->text = s != NULL ? xstrndup(s, n) : NULL;
	t->space = space;
	t->file = file;
	t->line = line;
}

/* Splits text into tokens; "# N \"file\"" lines set the position, other
 * directives (#pragma, #ident) are dropped. */
static void tokenize(struct cfg_ctx *ctx, const char *text, const char *name)
{
	const char *p = text;
	const char *file = intern(ctx, name, strlen(name));
	int line = 1;
	bool bol = true, space = false;

	while (*p != '\0') {
		if (*p == '\n') {
			line++;
			p++;
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
			if (end != q && n > 0) {
				q = end;
				while (*q == ' ' || *q == '\t')
					q++;
				if (*q == '"') {
					const char *e = strchr(q + 1, '"');

					if (e != NULL)
						file = intern(ctx, q + 1, (size_t)(e - q - 1));
				}
				line = (int)n - 1;   /* the newline ending this marker counts */
			}
			while (*p != '\0' && *p != '\n')
				p++;
			continue;
		}
		bol = false;
		if (p[0] == '/' && p[1] == '*') {
			const char *e = strstr(p + 2, "*/");

			for (const char *c = p; c < (e ? e : p + strlen(p)); c++)
				if (*c == '\n')
					line++;
			p = e ? e + 2 : p + strlen(p);
			space = true;
			continue;
		}
		if (p[0] == '/' && p[1] == '/') {
			while (*p != '\0' && *p != '\n')
				p++;
			continue;
		}
		if (isalpha((unsigned char)*p) || *p == '_') {
			const char *s = p;

			while (isalnum((unsigned char)*p) || *p == '_')
				p++;
			push_tok(ctx, TK_ID, s, (size_t)(p - s), space, file, line);
		} else if (isdigit((unsigned char)*p) || (*p == '.' && isdigit((unsigned char)p[1]))) {
			const char *s = p;

			while (isalnum((unsigned char)*p) || *p == '.' || *p == '_' ||
			       ((*p == '+' || *p == '-') && (p[-1] == 'e' || p[-1] == 'E' || p[-1] == 'p' || p[-1] == 'P')))
				p++;
			push_tok(ctx, TK_NUM, s, (size_t)(p - s), space, file, line);
		} else if (*p == '"' || *p == '\'') {
			const char *s = p;
			char quote = *p++;

			while (*p != '\0' && *p != quote && *p != '\n') {
				if (*p == '\\' && p[1] != '\0')
					p++;
				p++;
			}
			if (*p == quote)
				p++;
			push_tok(ctx, quote == '"' ? TK_STR : TK_NUM, s, (size_t)(p - s), space, file, line);
		} else {
			static const char *const two[] = { "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "->", "++", "--" };
			size_t n = 1;

			for (size_t i = 0; i < sizeof(two) / sizeof(two[0]); i++)
				if (p[0] == two[i][0] && p[1] == two[i][1])
					n = 2;
			push_tok(ctx, TK_PUNCT, p, n, space, file, line);
			p += n;
		}
		space = false;
	}
	push_tok(ctx, TK_EOF, NULL, 0, true, file, line);
}

static void free_toks(struct cfg_ctx *ctx)
{
	for (int i = 0; i < ctx->ntoks; i++)
		free(ctx->toks[i].text);
	free(ctx->toks);
	ctx->toks = NULL;
	ctx->ntoks = 0;
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

static const struct obj *find_obj(const struct cfg_ctx *ctx, enum api kind, const char *id)
{
	for (int i = 0; i < ctx->nobjs; i++)
		if (id_kind(ctx->objs[i].api) == kind && ctx->objs[i].id != NULL &&
		    strcmp(ctx->objs[i].id, id) == 0)
			return &ctx->objs[i];
	return NULL;
}

static bool is_null_expr(const char *e)
{
	return strcmp(e, "NULL") == 0 || strcmp(e, "0") == 0 || strcmp(e, "((void *)0)") == 0 ||
	       strcmp(e, "((void*)0)") == 0;
}

/* Shape checks of pass 1 that need no values. */
static void check_obj(struct cfg_ctx *ctx, struct obj *o, const char *what)
{
	const struct api_desc *d = &apis[o->api];
	bool kernel_only = o->api == API_ATT_INI || o->api == API_ATT_TER || o->api == API_DEF_SVC ||
			   o->api == API_CFG_INT || o->api == API_ATT_ISR;

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

/* Parses "API ( ... ) ;" after the name; records the object. */
static void parse_api(struct cfg_ctx *ctx, enum api a)
{
	const struct api_desc *d = &apis[a];
	struct tok *name = next(ctx);
	struct obj *o;
	char what[160];

	snprintf(what, sizeof(what), "%s", d->name);
	next(ctx);	/* "(" */
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
			if (ctx->include == NULL)
				report(ctx, name->file, name->line, what, "INCLUDE is not available here");
			else
				ctx->nerrors += ctx->include(ctx, s, name->file, name->line, ctx->include_arg);
			free(s);
			return;
		}
		for (int i = 0; i < ctx->nobjs; i++)
			if (ctx->objs[i].api == a && strcmp(ctx->objs[i].id, s) == 0) {
				report(ctx, name->file, name->line, what, "\"%s\" is already attached at %s:%d (E_OBJ)",
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
			ctx->nobjs--;
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
			ctx->nobjs--;
			while (!is_punct(peek(ctx, 0), ";") && peek(ctx, 0)->kind != TK_EOF)
				next(ctx);
			next(ctx);
			return;
		}
	}
	if (!is_punct(next(ctx), "{")) {
		report(ctx, name->file, name->line, what, "expected { %s } (E_PAR)", d->elems);
		ctx->nobjs--;
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
	if (o->id != NULL && d->has_id) {
		const struct obj *dup = find_obj(ctx, id_kind(a), o->id);

		if (dup != NULL && dup != o) {
			report(ctx, o->file, o->line, what, "%s is already defined at %s:%d (E_OBJ)", o->id,
			       dup->file, dup->line);
			return;
		}
	}
	check_obj(ctx, o, what);
}

/* Parses "DOMAIN ( name ) {" and enters the domain. */
static void parse_domain(struct cfg_ctx *ctx)
{
	struct tok *kw = next(ctx);
	struct tok *id;
	int index = 0;

	next(ctx);	/* "(" */
	id = next(ctx);
	if (id->kind != TK_ID || !is_punct(next(ctx), ")") || !is_punct(peek(ctx, 0), "{")) {
		report(ctx, kw->file, kw->line, "DOMAIN", "expected DOMAIN(name) { ... } (E_PAR)");
		return;
	}
	next(ctx);
	for (int i = 0; i < ctx->ndomains; i++)
		if (strcmp(ctx->domains[i], id->text) == 0)
			index = i + 1;
	if (index == 0) {
		ctx->domains = xrealloc(ctx->domains, (size_t)(ctx->ndomains + 1) * sizeof(char *));
		ctx->domains[ctx->ndomains++] = xstrdup(id->text);
		index = ctx->ndomains;
	}
	if (ctx->dom_depth > 0) {
		report(ctx, kw->file, kw->line, "DOMAIN", "DOMAIN(%s) inside another domain block (E_RSATR)", id->text);
		return;
	}
	ctx->dom_stack[ctx->dom_depth++] = index;
}

static int api_lookup(const char *name)
{
	for (int a = 0; a < API_COUNT; a++)
		if (strcmp(apis[a].name, name) == 0)
			return a;
	return -1;
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

int cfg_parse(struct cfg_ctx *ctx, const char *text, const char *name)
{
	int errors = ctx->nerrors;
	struct tok *saved_toks = ctx->toks;
	int saved_n = ctx->ntoks, saved_pos = ctx->pos, saved_depth = ctx->dom_depth;

	if (ctx->root == NULL)
		ctx->root = intern(ctx, name, strlen(name));
	ctx->toks = NULL;
	ctx->ntoks = 0;
	ctx->pos = 0;
	ctx->dom_depth = 0;
	tokenize(ctx, text, name);
	for (;;) {
		struct tok *t = peek(ctx, 0);

		if (t->kind == TK_EOF)
			break;
		if (t->kind == TK_ID && is_punct(peek(ctx, 1), "(")) {
			int a = api_lookup(t->text);

			if (a >= 0) {
				parse_api(ctx, (enum api)a);
				continue;
			}
			if (strcmp(t->text, "DOMAIN") == 0) {
				parse_domain(ctx);
				continue;
			}
			if (looks_like_api(t->text)) {
				report(ctx, t->file, t->line, t->text, "unknown static API");
				skip_c_declaration(ctx);
				continue;
			}
		}
		if (t->kind == TK_ID && strcmp(t->text, "KERNEL_DOMAIN") == 0 && is_punct(peek(ctx, 1), "{")) {
			next(ctx);
			next(ctx);
			ctx->dom_stack[ctx->dom_depth++] = 0;
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
		skip_c_declaration(ctx);
	}
	if (ctx->dom_depth > 0)
		report(ctx, peek(ctx, 0)->file, peek(ctx, 0)->line, "DOMAIN", "missing '}' at the end of the file");
	free_toks(ctx);
	ctx->toks = saved_toks;
	ctx->ntoks = saved_n;
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

	for (int i = 0; i < ctx->nobjs; i++) {
		struct obj *o = &ctx->objs[i];

		if (o->api != API_ATT_MOD)
			continue;
		for (int k = 0; k < nobjects && o->path == NULL; k++) {
			const char *slash = strrchr(objects[k], '/');

			if (strcmp(slash != NULL ? slash + 1 : objects[k], o->id) == 0)
				o->path = objects[k];
		}
		if (o->path == NULL)
			report(ctx, o->file, o->line, "ATT_MOD", "\"%s\" is not one of the app's objects (E_NOEXS)", o->id);
	}
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
 * word at the end of each keeps an empty part from vanishing. */
void cfg_write_module_script(const struct cfg_ctx *ctx, FILE *out, int index)
{
	const struct obj *o = module_at(ctx, index);

	fprintf(out, "/* ATT_MOD(\"%s\") from %s:%d — generated by ev3cfg, do not edit. */\n",
		o ? o->id : "?", o ? o->file : "?", o ? o->line : 0);
	fprintf(out, "SECTIONS\n{\n");
	fprintf(out, "\tev3mod_%d_text : { *(.text .text.* .rodata .rodata.* .data.rel.ro .data.rel.ro.*) LONG(0) }\n", index);
	fprintf(out, "\tev3mod_%d_data : { *(.data .data.* .bss .bss.* COMMON) LONG(0) }\n", index);
	fprintf(out, "}\n");
}

static const char *domain_expr(const struct cfg_ctx *ctx, int domain)
{
	return domain > 0 ? ctx->domains[domain - 1] : "TDOM_KERNEL";
}

void cfg_write_header(const struct cfg_ctx *ctx, FILE *out, const char *symbol)
{
	fprintf(out, "/* kernel_cfg.h — object IDs of the configuration; generated by ev3cfg, do not edit. */\n");
	fprintf(out, "#ifndef TOPPERS_KERNEL_CFG_H\n#define TOPPERS_KERNEL_CFG_H\n\n");
	for (int i = 0; i < ctx->ndomains; i++)
		fprintf(out, "#define %s %d\n", ctx->domains[i], i + 1);
	for (int i = 0; i < ctx->nobjs; i++) {
		const struct obj *o = &ctx->objs[i];

		if (apis[o->api].has_id)
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
		if (ob->domain > 0) {
			snprintf(c, sizeof(c), "(%s) >= TMIN_APP_TPRI", ob->elem[3]);
			check(o, ob, c, "CRE_TSK(%s): itskpri above TMIN_APP_TPRI for a task of DOMAIN(%s) (E_PAR)",
			      id, ctx->domains[ob->domain - 1]);
		}
		snprintf(c, sizeof(c), "(%s) > 0", ob->elem[4]);
		check(o, ob, c, "CRE_TSK(%s): stksz must be positive (E_PAR)", id);
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
		break;
	default:
		break;
	}
}

/* Writes one table: rows of every object of api kind(s), formatted by row(). */
static int count_api(const struct cfg_ctx *ctx, enum api a, enum api b)
{
	int n = 0;

	for (int i = 0; i < ctx->nobjs; i++)
		n += ctx->objs[i].api == a || ctx->objs[i].api == b;
	return n;
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
		emit(o, "\t{ %s, %s, (intptr_t)(%s), %s, %s, %s, \"%s\" },\n", ob->id, e[0], e[1], e[2], e[3], e[4],
		     ob->id);
		break;
	case API_CRE_ALM:
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
	int nmods = 0, nev3cyc = count_api(ctx, API_EV3_CRE_CYC, API_COUNT), ntables = 0;

	emit(&o, "/* %s — the configuration's tables; generated by ev3cfg, do not edit. */\n", source_name);
	emit(&o, "#include \"kernel.h\"\n#include \"rtos_cfg.h\"\n#include \"kernel_cfg.h\"\n");
	for (int i = 0; i < ctx->nc_includes; i++)
		emit(&o, "%s\n", ctx->c_includes[i]);
	at_self(&o);
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
	for (int i = 0; i < ctx->nobjs; i++)
		nmods += ctx->objs[i].api == API_ATT_MOD && ctx->objs[i].domain > 0;
	if (nmods > 0) {
		emit(&o, "\n/* ATT_MOD: each module's code and data, bounded by the linker. */\n");
		for (int i = 0; i < ctx->nobjs; i++) {
			const struct obj *ob = &ctx->objs[i];

			if (ob->api == API_ATT_MOD && ob->domain > 0)
				emit(&o, "extern char __start_ev3mod_%d_text[], __stop_ev3mod_%d_text[];\n"
					 "extern char __start_ev3mod_%d_data[], __stop_ev3mod_%d_data[];\n",
				     ob->number, ob->number, ob->number, ob->number);
		}
		emit(&o, "static struct rtos_mem_cfg ev3cfg_mems[%d];\n\n", 2 * nmods);
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
		emit(&o, "}\n");
	}
	/* Pass-2 checks of the values, at each static API's line. */
	for (int i = 0; i < ctx->ndomains; i++) {
		emit(&o, "_Static_assert(%s <= TNUM_DOMID, \"DOMAIN(%s): more than TNUM_DOMID user domains (E_NOID)\");\n",
		     ctx->domains[i], ctx->domains[i]);
	}
	for (int i = 0; i < ctx->nobjs; i++)
		emit_checks(ctx, &o, &ctx->objs[i]);
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
	if (nmods > 0)
		emit(&o, "\t.mems = RTOS_TABLE(ev3cfg_mems),\n");
	if (ntables > 0)
		emit(&o, "\t.includes = ev3cfg_includes,\n");
	emit(&o, "};\n");
}

/*
 * test_cfg_errors.c — the configurator's pass 1 on preprocessed text: every
 * static API's shape, C declarations from headers skipped, positions from
 * line markers, and error messages that name the file, line and static API
 * (and the TOPPERS error code), as the TOPPERS configurator's do.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tap.h"
#include "cfg_gen.h"

static char *errbuf;
static size_t errlen;

/* Parses text as app.cfg (with objects app.o); returns the error count, messages in errbuf. */
static int run(const char *text, struct cfg_ctx **out)
{
	static const char *const objects[] = { "build/obj/app.o", "build/obj/util.o" };
	FILE *err;
	struct cfg_ctx *ctx;
	int n;

	free(errbuf);
	errbuf = NULL;
	err = open_memstream(&errbuf, &errlen);
	ctx = cfg_new(err, NULL, NULL);
	n = cfg_parse(ctx, text, "app.cfg");
	n += cfg_finish(ctx);
	n += cfg_bind_modules(ctx, objects, 2);
	fclose(err);
	if (out != NULL)
		*out = ctx;
	else
		cfg_free(ctx);
	return n;
}

/* The generated header or source as a string. */
static char *generate(struct cfg_ctx *ctx, bool source)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);

	if (source)
		cfg_write_source(ctx, f, "app_cfg", "kernel_cfg.c");
	else
		cfg_write_header(ctx, f, "app_cfg");
	fclose(f);
	return buf;
}

static void expect_error(const char *text, const char *message, const char *name)
{
	int n = run(text, NULL);

	ok(n == 1 && errbuf != NULL && strstr(errbuf, message) != NULL, "%s", name);
	if (n != 1 || strstr(errbuf, message) == NULL)
		tap_diag("got %d error(s): %s", n, errbuf);
}

int main(void)
{
	struct cfg_ctx *ctx;
	char *h, *c;

	tap_plan(22);

	/* A configuration as the preprocessor leaves it: line markers, header declarations. */
	is_int(run("# 1 \"app.cfg\"\n"
		   "# 1 \"app.h\" 1\n"
		   "typedef struct { int a; int b[2]; } pair_t;\n"
		   "static inline int twice(int x) { return 2 * x; }\n"
		   "extern void main_task(intptr_t exinf) __attribute__((unused));\n"
		   "# 3 \"app.cfg\" 2\n"
		   "DOMAIN(TDOM_APP) {\n"
		   "CRE_TSK(MAIN_TASK, { 0x02U, 0, main_task, (6 + 1), 4096, NULL });\n"
		   "CRE_TSK(SUB_TASK, { 0U, 0, sub_task, 8, 4096, NULL });\n"
		   "EV3_CRE_CYC(MY_CYC, { 0x02U, 7, my_cyc, 100, 0 });\n"
		   "CRE_CYC(KCYC, { 0U, 0, k_cyc, 10, 0 });\n"
		   "CRE_DTQ(DTQ, { 0U, 8, NULL });\n"
		   "}\n"
		   "ATT_MOD(\"app.o\");\n"
		   "ATT_INI({ 0U, 0, app_init });\n", &ctx), 0,
	       "a preprocessed configuration with header declarations parses cleanly");
	h = generate(ctx, false);
	c = generate(ctx, true);
	ok(strstr(h, "#define TDOM_APP 1\n") && strstr(h, "#define MAIN_TASK 1\n") && strstr(h, "#define SUB_TASK 2\n"),
	   "kernel_cfg.h numbers domains and tasks from 1 in order");
	ok(strstr(h, "#define KCYC 2\n") && strstr(h, "#define MY_CYC 1\n") && strstr(h, "#define EV3_CYC_TASK_MY_CYC 3\n"),
	   "EV3_CRE_CYC gets a cyclic ID and a handler task after the app's tasks");
	ok(strstr(c, "#line 4 \"app.cfg\"\n\t{ MAIN_TASK, 0x02U, (intptr_t)(0), main_task, (6 + 1), 4096, TDOM_APP, \"MAIN_TASK\" },") != NULL,
	   "a CRE_TSK row carries its parameters, its domain and its line");
	ok(strstr(c, "#line 4 \"app.cfg\"\n_Static_assert(((6 + 1)) >= TMIN_APP_TPRI, \"CRE_TSK(MAIN_TASK): itskpri above TMIN_APP_TPRI") != NULL,
	   "value checks are static assertions placed at the static API's line");
	ok(strstr(c, "{ MY_CYC, 0x02U, EV3_CYC_TASK_MY_CYC, ev3cfg_cyc_wake, 100, 0, \"MY_CYC\" }") &&
	   strstr(c, "ev3cfg_cyc_task, TMIN_APP_TPRI") && strstr(c, "{ my_cyc, (intptr_t)(7) }"),
	   "EV3_CRE_CYC: a kernel cyclic handler wakes the handler's task");
	ok(strstr(c, "__start_ev3mod_1_data") && strstr(c, "TPM_READ | TPM_WRITE, \"app.o data\""),
	   "ATT_MOD outside DOMAIN with one user domain gives that domain the module's data");
	ok(strcmp(cfg_module_path(ctx, 1), "build/obj/app.o") == 0, "ATT_MOD(\"app.o\") is bound to the object of that name");
	free(h);
	free(c);
	cfg_free(ctx);

	expect_error("\n\nCRE_FOO(X, { 1 });\n", "app.cfg:3: error: CRE_FOO: unknown static API",
		     "an unknown static API is named with its line");
	expect_error("CRE_SEM(S, { 0U, 1 });\n",
		     "app.cfg:1: error: CRE_SEM(S): 2 parameters in { } (sematr, isemcnt, maxsem), expected 3 (E_PAR)",
		     "a wrong parameter count names the API, the object and the expected packet");
	expect_error("CRE_SEM(S, { 0U, 0, 1 });\nCRE_SEM(S, { 0U, 0, 1 });\n",
		     "app.cfg:2: error: CRE_SEM(S): S is already defined at app.cfg:1 (E_OBJ)",
		     "a duplicate ID names both places");
	expect_error("CRE_TSK(T, { 0U, 0, t, 8, 1024, stack_area });\n",
		     "app.cfg:1: error: CRE_TSK(T): stk must be NULL", "a caller-supplied stack is refused");
	expect_error("CRE_DTQ(Q, { 0U, 4, buf });\n", "app.cfg:1: error: CRE_DTQ(Q): dtqmb must be NULL",
		     "a caller-supplied data queue buffer is refused");
	expect_error("DOMAIN(TDOM_APP) {\nATT_INI({ 0U, 0, init });\n}\n",
		     "app.cfg:2: error: ATT_INI: belongs to the kernel domain, not inside DOMAIN(TDOM_APP) (E_RSATR)",
		     "ATT_INI inside a user domain is refused");
	expect_error("CRE_SEM(S, { 0U, 0, 1 })\nCRE_FLG(F, { 0U, 0 });\n", "app.cfg:1: error: CRE_SEM(S): malformed static API",
		     "a missing ';' is reported at the static API");
	expect_error("# 7 \"inc/app.h\"\nCRE_TSK(42, { 0U, 0, t, 8, 1024, NULL });\n",
		     "inc/app.h:7: error: CRE_TSK: the first parameter must be the object's ID name (E_PAR)",
		     "line markers move the reported position into the included file");
	expect_error("DOMAIN(A) {\n}\nDOMAIN(B) {\n}\nATT_MOD(\"app.o\");\n",
		     "app.cfg:5: error: ATT_MOD: \"app.o\" outside DOMAIN() is ambiguous with 2 user domains",
		     "ATT_MOD outside DOMAIN with two user domains is ambiguous");
	expect_error("DOMAIN(A) {\nATT_MOD(\"main.o\");\n}\n",
		     "app.cfg:2: error: ATT_MOD: \"main.o\" is not one of the app's objects (E_NOEXS)",
		     "ATT_MOD naming an object the app does not have");
	expect_error("ATT_MOD(\"app.o\");\nATT_MOD(\"app.o\");\n",
		     "app.cfg:2: error: ATT_MOD: \"app.o\" is already attached at app.cfg:1 (E_OBJ)",
		     "a module attached twice");
	expect_error("INCLUDE(\"app_common.cfg\");\n", "app.cfg:1: error: INCLUDE: INCLUDE is not available here",
		     "INCLUDE without a file reader is reported");
	expect_error("DOMAIN(A) {\nCRE_SEM(S, { 0U, 0, 1 });\n", "error: DOMAIN: missing '}' at the end of the file",
		     "an unclosed DOMAIN block");
	is_int(run("CRE_MTX(M, { TA_CEILING, 3 });\nCRE_MTX(N, { 0U });\nCRE_PDQ(P, { 0U, 4, 8, NULL });\n"
		   "CRE_ALM(A, { 0U, 0, alm });\nDEF_SVC(5, { 0U, svc, 1024 });\nEV3LX_INCLUDE_TABLE(ev3api_cfg);\n",
		   NULL), 0, "mutexes with and without a ceiling, PDQ, alarm, DEF_SVC and a platform table parse");
	free(errbuf);
	return tap_done();
}

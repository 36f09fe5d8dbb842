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

/* text configures with no error but warns message, as EV3RT accepts such ATT_MODs,
 * and keeps exactly one module, the object named kept. */
static void expect_ignored_module(const char *text, const char *message, const char *kept, const char *name)
{
	struct cfg_ctx *ctx;
	int n = run(text, &ctx);

	is_int(n, 0, "%s: no error", name);
	ok(errbuf != NULL && strstr(errbuf, message) != NULL, "%s: warns", name);
	if (errbuf == NULL || strstr(errbuf, message) == NULL)
		tap_diag("got: %s", errbuf != NULL ? errbuf : "(nothing)");
	is_int(cfg_module_count(ctx), 1, "%s: one module is kept", name);
	ok(cfg_module_object(ctx, 1) != NULL && strcmp(cfg_module_object(ctx, 1), kept) == 0,
	   "%s: module 1 is %s", name, kept);
	cfg_free(ctx);
}

/* text gives at least one error, the first of them message (a lexical error may leave more behind). */
static void expect_first_error(const char *text, const char *message, const char *name)
{
	int n = run(text, NULL);

	ok(n >= 1 && errbuf != NULL && strncmp(errbuf, message, strlen(message)) == 0, "%s", name);
	if (n < 1 || strncmp(errbuf, message, strlen(message)) != 0)
		tap_diag("got %d error(s): %s", n, errbuf);
}

static void expect_error(const char *text, const char *message, const char *name)
{
	int n = run(text, NULL);

	ok(n == 1 && errbuf != NULL && strstr(errbuf, message) != NULL, "%s", name);
	if (n != 1 || strstr(errbuf, message) == NULL)
		tap_diag("got %d error(s): %s", n, errbuf);
}

/* An INCLUDE that reads nothing: the configuration's own text is what is tested. */
static int include_nothing(struct cfg_ctx *ctx, const char *file, const char *from_file, int from_line, void *arg)
{
	(void)ctx; (void)file; (void)from_file; (void)from_line; (void)arg;
	return 0;
}

/* The profile text (with INCLUDE available) is configured for, or -1 on errors. */
static int profile_of(const char *text)
{
	struct cfg_ctx *ctx = cfg_new(stderr, include_nothing, NULL);
	int profile = cfg_parse(ctx, text, "app.cfg") == 0 ? cfg_profile(ctx) : -1;

	cfg_free(ctx);
	return profile;
}

/* The profile of text built with profile, given the source's hint of a wait in microseconds. */
static int profile_with_source_hint(const char *text, int profile)
{
	struct cfg_ctx *ctx = cfg_new(stderr, include_nothing, NULL);
	int result = -1;

	cfg_set_profile(ctx, profile);
	if (cfg_parse(ctx, text, "app.cfg") == 0) {
		bool took = cfg_profile_from_source(ctx, "app.c", 12, "tslp_tsk with 1000000");

		ok(took == (profile == CFG_PROFILE_AUTO && strstr(text, "CRE_CYC") == NULL),
		   "the hint is taken only where nothing else decides (%s)", took ? "taken" : "not taken");
		result = cfg_profile(ctx);
	}
	cfg_free(ctx);
	return result;
}

int main(void)
{
	struct cfg_ctx *ctx;
	char *h, *c;

	tap_plan(85);

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

	expect_error("\n\nCRE_FOO(X, { 1 });\n", "app.cfg:3:1: error: CRE_FOO: unknown static API",
		     "an unknown static API is named with its line and column");
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
	expect_ignored_module("DOMAIN(A) {\nATT_MOD(\"main.o\");\nATT_MOD(\"util.o\");\n}\n",
			      "app.cfg:2: warning: ATT_MOD: \"main.o\" is not one of the app's objects; ignored",
			      "util.o", "ATT_MOD naming an object the app does not have");
	expect_ignored_module("ATT_MOD(\"app.o\");\nATT_MOD(\"app.o\");\n",
			      "app.cfg:2: warning: ATT_MOD: \"app.o\" is already attached at app.cfg:1; this one is ignored",
			      "app.o", "a module attached twice");
	expect_error("INCLUDE(\"app_common.cfg\");\n", "app.cfg:1: error: INCLUDE: INCLUDE is not available here",
		     "INCLUDE without a file reader is reported");
	expect_error("DOMAIN(A) {\nCRE_SEM(S, { 0U, 0, 1 });\n", "error: DOMAIN: missing '}' at the end of the file",
		     "an unclosed DOMAIN block");
	is_int(run("CRE_MTX(M, { TA_CEILING, 3 });\nCRE_MTX(N, { 0U });\nCRE_PDQ(P, { 0U, 4, 8, NULL });\n"
		   "CRE_ALM(A, { 0U, 0, alm });\nDEF_SVC(5, { 0U, svc, 1024 });\nEV3LX_INCLUDE_TABLE(ev3api_cfg);\n",
		   NULL), 0, "mutexes with and without a ceiling, PDQ, alarm, DEF_SVC and a platform table parse");

	/* Configuration text is static APIs only; what TOPPERS's configurator refuses, so does ev3cfg. */
	expect_error("DOMIAN(TDOM_APP) {\nCRE_SEM(S, { 0U, 0, 1 });\n}\n",
		     "app.cfg:1:1: error: DOMIAN: unknown static API (did you mean DOMAIN?)",
		     "a misspelt DOMAIN block is one error, with the keyword it resembles");
	expect_error("  Domain(TDOM_APP) {\n}\n", "app.cfg:1:3: error: Domain: unknown static API (did you mean DOMAIN?)",
		     "DOMAIN in the wrong case is refused");
	expect_error("CRE_SEM(S, { 0U, 0, 1 });\nthis is junk\nCRE_FLG(F, { 0U, 0 });\n",
		     "app.cfg:2:1: error: syntax error: expected a static API, found 'this'", "a junk line is a syntax error");
	expect_error("int helper(void) { return 1; }\n", "app.cfg:1:1: error: syntax error: expected a static API, found 'int'",
		     "a C definition in the configuration file itself is refused");
	expect_error("CRE_SEM(S, { 0U, 0, 1 });\n}\n", "app.cfg:2:1: error: syntax error: expected a static API, found '}'",
		     "an unmatched '}'");
	expect_error("DOMAIN TDOM_APP {\n}\n", "app.cfg:1:1: error: syntax error: DOMAIN is not followed by '('",
		     "DOMAIN without its parentheses");
	expect_first_error("CRE_SEM(S, { 0U, 0, 1 });\nCRE_\x01SEM(T, { 0U, 0, 1 });\n",
		     "app.cfg:2:5: error: stray byte 0x01: not C text", "a control byte is not C text");
	expect_error("CRE_SEM(S, { 0U, 0, 1 }); @\n", "app.cfg:1:27: error: stray '@': not C text",
		     "a character no C token uses");
	expect_first_error("CRE_SEM(S, { 0U, 0, 1 });\nATT_MOD(\"app.o);\n", "app.cfg:2:9: error: missing terminating \" character",
		     "an unterminated string");
	expect_error("CRE_SEM(S, { 0U, 0, 1 });\n/* never closed\n", "app.cfg:2:1: error: unterminated comment",
		     "an unterminated comment");
	expect_error("DEF_TEX(T, { 0U, tex });\n",
		     "app.cfg:1:1: error: DEF_TEX: a static API of TOPPERS/HRP2 (task exception routines) not supported by ev3lx",
		     "an HRP2 static API ev3lx lacks is refused by name");
	expect_error("SAC_SEM(S, { 1, 1, 1, 1 });\n", "SAC_SEM: a static API of TOPPERS/HRP2 (access control vectors) not supported",
		     "access control vectors are refused, not ignored");
	expect_error("CRE_MBX(M, { 0U, 1, NULL });\n", "app.cfg:1:1: error: CRE_MBX: unknown static API: TOPPERS/HRP2 has no mailboxes",
		     "a mailbox (ASP's) is named as not HRP2's");
	expect_error("ACV_DOM({ 1, 1, 1, 1 });\n",
		     "app.cfg:1:1: error: ACV_DOM: a static API of TOPPERS/HRP3 (a domain's access vector) not supported by ev3lx",
		     "HRP3's ACV_DOM is named as HRP3's");
	expect_error("CRE_ISR(I, { 0U, 0, 5, isr, 1 });\n", "CRE_ISR: a static API of TOPPERS/HRP3 (interrupt service routines",
		     "HRP3's CRE_ISR is named as HRP3's");

	/* The two kernel profiles: HRP2's CRE_CYC/CRE_ALM (a handler, ms), HRP3's (a notification, us). */
	is_int(run("# 1 \"app.cfg\"\n"
		   "CRE_TSK(T, { 0U, 0, t, 8, 4096, NULL });\n"
		   "DOMAIN(TDOM_APP) {\n"
		   "CRE_CYC(C1, { TA_STA, { TNFY_ACTTSK, T }, 1000U * 1000U, 0U });\n"
		   "CRE_CYC(C2, { 0U, { 0x06U, F, 0x01U }, (500 * 1000), 10 });\n"
		   "CRE_CYC(C3, { 0U, { TNFY_SNDDTQ | TENFY_SETVAR, Q, 7, &err }, 100, 0 });\n"
		   "CRE_CYC(C4, { 0U, { TNFY_WUPTSK | TENFY_SETFLG, T, F, 0x2 }, 100, 0 });\n"
		   "CRE_ALM(A1, { 0U, { TNFY_SIGSEM | TENFY_INCVAR, S, &misses } });\n"
		   "CRE_ALM(A2, { 0U, { TNFY_SETVAR, &flag, 1 } });\n"
		   "}\n"
		   "CRE_ALM(A3, { 0U, { TNFY_HANDLER, 5, handler } });\n", &ctx), 0,
	       "HRP3's notification forms of CRE_CYC and CRE_ALM parse, every mode and error mode");
	is_int(cfg_profile(ctx), CFG_PROFILE_HRP3, "a notification form makes the configuration HRP3's");
	c = generate(ctx, true);
	ok(strstr(c, "#define EV3LX_KERNEL_HRP3 1") && strstr(c, ".profile = RTOS_PROFILE_HRP3,"),
	   "its kernel_cfg.c is compiled in the HRP3 profile and tells the kernel so");
	ok(strstr(c, "{ C1, TA_STA, (intptr_t)(T), ev3cfg_nfy_C1, 1000U * 1000U, 0U, \"C1\" }") &&
	   strstr(c, "static void ev3cfg_nfy_C1(intptr_t exinf)\n{\n\t(void)iact_tsk((ID)exinf);\n}"),
	   "TNFY_ACTTSK: the row passes the task as exinf to a handler that activates it");
	ok(strstr(c, "\t(void)iset_flg((ID)exinf, (FLGPTN)(0x01U));") && strstr(c, "(500 * 1000), 10, \"C2\""),
	   "a numeric nfymode (as a preprocessed header gives it) is read: TNFY_SETFLG");
	ok(strstr(c, "ER ercd = ipsnd_dtq((ID)exinf, (intptr_t)(7));\n\n\tif (ercd != E_OK) {\n"
		     "\t\t*(intptr_t *)(&err) = (intptr_t)ercd;"), "TNFY_SNDDTQ | TENFY_SETVAR: the error code is stored");
	ok(strstr(c, "\t\t(void)iset_flg(F, (FLGPTN)(0x2));"), "TENFY_SETFLG takes a flag and a pattern");
	ok(strstr(c, "ER ercd = isig_sem((ID)exinf);") && strstr(c, "\t\t*(intptr_t *)(&misses) += 1;"),
	   "CRE_ALM: TNFY_SIGSEM | TENFY_INCVAR");
	ok(strstr(c, "\t*((intptr_t *)exinf) = (intptr_t)(1);"), "TNFY_SETVAR sets the variable par1 points to");
	ok(strstr(c, "{ A3, 0U, (intptr_t)(5), (ALMHDR)(handler), \"A3\" }"),
	   "TNFY_HANDLER (kernel domain): the handler itself, with its exinf");
	ok(strstr(c, "((0U) & ~(ATR)TA_STA) == 0") && strstr(c, "(100) > 0 && (100) <= TMAX_RELTIM"),
	   "HRP3's value rules: TA_STA only, cyctim within HRP3's TMAX_RELTIM");
	free(c);
	cfg_free(ctx);
	is_int(run("CRE_CYC(C, { TA_STA, 0, h, 10, 0 });\n", &ctx), 0, "HRP2's form parses");
	is_int(cfg_profile(ctx), CFG_PROFILE_HRP2, "and makes the configuration HRP2's");
	c = generate(ctx, true);
	ok(strstr(c, "EV3LX_KERNEL_HRP3") == NULL && strstr(c, ".profile") == NULL, "whose kernel_cfg.c stays HRP2's");
	free(c);
	cfg_free(ctx);
	expect_error("CRE_CYC(A, { TA_STA, 0, h, 10, 0 });\nCRE_CYC(B, { TA_STA, { TNFY_ACTTSK, T }, 10, 0 });\n",
		     "app.cfg:2: error: CRE_CYC(B): the notification form { nfymode, ... } (times in us) is TOPPERS/HRP3's, "
		     "but CRE_CYC(A) at app.cfg:1 is TOPPERS/HRP2's: a configuration is written for one kernel profile (E_PAR)",
		     "mixing HRP2's and HRP3's forms is refused, naming both");
	expect_error("CRE_ALM(B, { 0U, { TNFY_ACTTSK, T } });\nEV3_CRE_CYC(C, { 0U, 0, h, 10, 0 });\n",
		     "app.cfg:2: error: EV3_CRE_CYC(C): EV3_CRE_CYC (EV3RT's HRP2 API, times in ms) is TOPPERS/HRP2's, "
		     "but CRE_ALM(B) at app.cfg:1 is TOPPERS/HRP3's", "EV3_CRE_CYC in an HRP3 configuration");
	expect_error("CRE_CYC(C, { TA_STA, 0, h });\n",
		     "app.cfg:1: error: CRE_CYC(C): 3 parameters in { }, expected 5 (HRP2: cycatr, exinf, cychdr, cyctim, "
		     "cycphs) or 4 (HRP3: cycatr, { nfymode, par1[, par2...] }, cyctim, cycphs) (E_PAR)",
		     "a wrong count names both forms");
	expect_error("CRE_CYC(C, { TA_STA, 0, h, 10 });\n",
		     "app.cfg:1: error: CRE_CYC(C): malformed notification form: expected { cycatr, { nfymode, par1[, par2...] }, "
		     "cyctim, cycphs } as in TOPPERS/HRP3", "four parameters without a notification");
	expect_error("CRE_CYC(C, { TA_STA, { TNFY_ACTTSK, T }, h, 10, 0 });\n", "CRE_CYC(C): malformed notification form",
		     "a notification in HRP2's five");
	expect_error("CRE_CYC(C, { TA_STA, { TNFY_SETFLG, F }, 10, 0 });\n",
		     "app.cfg:1: error: CRE_CYC(C): too few parameters for nfymode TNFY_SETFLG: 1, expected 2 (E_PAR)",
		     "TNFY_SETFLG needs a pattern");
	expect_error("CRE_CYC(C, { TA_STA, { TNFY_ACTTSK, T, U }, 10, 0 });\n",
		     "too many parameters for nfymode TNFY_ACTTSK: 2, expected 1 (E_PAR)", "TNFY_ACTTSK takes one");
	expect_error("CRE_ALM(A, { 0U, { TNFY_SETVAR | TENFY_SETVAR, &x, 1, &e } });\n",
		     "illegal nfymode TNFY_SETVAR | TENFY_SETVAR (0x11): the error notifications TENFY_* go with",
		     "an error notification of a notification that cannot fail");
	expect_error("CRE_ALM(A, { 0U, { TNFY_FOO, T } });\n", "nfymode 'TNFY_FOO' is not TNFY_* or TNFY_* | TENFY_* (E_PAR)",
		     "an unknown nfymode");
	is_int(profile_of("INCLUDE(\"app_common.cfg\");\nINCLUDE(\"tecsgen.cfg\");\nCRE_TSK(T, { 0U, 0, t, 8, 4096, NULL });\n"),
	       CFG_PROFILE_HRP3, "INCLUDE(\"tecsgen.cfg\") (TECS, of the third-generation kernels) makes it HRP3's");
	is_int(profile_of("INCLUDE(\"app_common.cfg\");\nCRE_TSK(T, { 0U, 0, t, 8, 4096, NULL });\n"), CFG_PROFILE_HRP2,
	       "tasks alone say nothing: HRP2's, unless the build says otherwise");
	is_int(profile_with_source_hint("CRE_TSK(T, { 0U, 0, t, 8, 4096, NULL });\n", CFG_PROFILE_AUTO), CFG_PROFILE_HRP3,
	       "a wait in microseconds in the source makes a configuration without time events HRP3's");
	is_int(profile_with_source_hint("CRE_CYC(C, { TA_STA, 0, h, 10, 0 });\n", CFG_PROFILE_AUTO), CFG_PROFILE_HRP2,
	       "the source's hint loses to an HRP2 handler form in app.cfg");
	is_int(profile_with_source_hint("CRE_TSK(T, { 0U, 0, t, 8, 4096, NULL });\n", CFG_PROFILE_HRP2), CFG_PROFILE_HRP2,
	       "and to --kernel hrp2");
	expect_error("DOMAIN(TDOM_APP) {\nCRE_CYC(C, { TA_STA, { TNFY_HANDLER, 0, h }, 10, 0 });\n}\n",
		     "app.cfg:2: error: CRE_CYC(C): TNFY_HANDLER is not permitted in a user domain (DOMAIN(TDOM_APP))",
		     "TNFY_HANDLER in a user domain is HRP3's E_OACV");
	expect_error("# 1 \"app.h\" 1\nextern int x;\nFOO_BAR(1);\n# 3 \"app.cfg\" 2\n",
		     "app.h:2:1: error: FOO_BAR: unknown static API", "a static-API-shaped call in a header is still refused");

	/* One namespace: kernel_cfg.h defines every ID, domain and EV3 handler task as a C macro. */
	expect_error("CRE_SEM(X, { 0U, 0, 1 });\nCRE_FLG(X, { 0U, 0 });\n",
		     "app.cfg:2: error: CRE_FLG(X): X is already defined at app.cfg:1 by CRE_SEM; the IDs of every kind share one namespace (E_OBJ)",
		     "a semaphore and a flag of one name");
	expect_error("DOMAIN(MAIN) {\n}\nCRE_SEM(MAIN, { 0U, 0, 1 });\n",
		     "app.cfg:3: error: CRE_SEM(MAIN): MAIN is already defined at app.cfg:1 by DOMAIN",
		     "an object named as a domain");
	expect_error("CRE_TSK(T, { 0U, 0, t, 8, 1024, NULL });\nDOMAIN(T) {\n}\n",
		     "app.cfg:2: error: DOMAIN: T is already defined at app.cfg:1 by CRE_TSK", "a domain named as an object");
	expect_error("EV3_CRE_CYC(C, { 0U, 0, h, 10, 0 });\nCRE_TSK(EV3_CYC_TASK_C, { 0U, 0, t, 8, 1024, NULL });\n",
		     "app.cfg:2: error: CRE_TSK(EV3_CYC_TASK_C): EV3_CYC_TASK_C is already defined at app.cfg:1 by EV3_CRE_CYC (its handler task)",
		     "a task named as an EV3 cyclic handler's task");

	/* Nested domain blocks, however deep, are errors, not overflows. */
	{
		char text[40 * 20 + 1] = "";

		for (int i = 0; i < 20; i++)
			strcat(text, "KERNEL_DOMAIN {\n");
		for (int i = 0; i < 20; i++)
			strcat(text, "}\n");
		ok(run(text, NULL) > 0 && strstr(errbuf, "app.cfg:2:1: error: DOMAIN: KERNEL_DOMAIN inside another domain block (E_RSATR)"),
		   "nested KERNEL_DOMAIN blocks: one error each, no overflow of the block stack");
	}
	/* Random input gives many errors; the first ones are printed, all are counted. */
	{
		char *text = malloc(200 * 6 + 1);

		text[0] = '\0';
		for (int i = 0; i < 200; i++)
			strcat(text, "junk\n");
		ok(run(text, NULL) == 200 && strstr(errbuf, "further errors are counted, not shown") &&
		   strstr(errbuf, "app.cfg:51:1:") == NULL, "200 errors: 50 printed, the rest counted");
		free(text);
	}

	/* Sizes: each stack within 8 MiB, all of them within 32 MiB (pass 2). */
	is_int(run("CRE_TSK(T, { 0U, 0, t, 8, 1 << 30, NULL, 4096, NULL });\nEV3_CRE_CYC(C, { 0U, 0, h, 10, 0 });\n"
		   "DEF_SVC(1, { 0U, svc, 1024 });\n", &ctx), 0, "a 1 GiB stack passes pass 1 (a value: pass 2 checks it)");
	c = generate(ctx, true);
	ok(strstr(c, "#define EV3CFG_MAX_STKSZ (8UL << 20)\n#define EV3CFG_MAX_STACKS (32UL << 20)\n") &&
	   strstr(c, "_Static_assert((1 << 30) > 0 && (1 << 30) <= EV3CFG_MAX_STKSZ, \"CRE_TSK(T): stksz out of range") &&
	   strstr(c, "_Static_assert((4096) >= 0 && (4096) <= EV3CFG_MAX_STKSZ, \"CRE_TSK(T): sstksz out of range") &&
	   strstr(c, "_Static_assert((1024) >= 0 && (1024) <= EV3CFG_MAX_STKSZ, \"DEF_SVC(1): stksz out of range"),
	   "pass 2 bounds every stack size");
	ok(strstr(c, "#line 2 \"app.cfg\"\n_Static_assert(0ULL + ((1 << 30) > 0 && (1 << 30) <= EV3CFG_MAX_STKSZ ? "
		     "(unsigned long long)(1 << 30) : 0ULL) + (unsigned long long)EV3CFG_CYC_STACK <= EV3CFG_MAX_STACKS") != NULL,
	   "and their total, at the last task's line, counting EV3_CRE_CYC's handler tasks");
	free(c);
	cfg_free(ctx);

	free(errbuf);
	return tap_done();
}

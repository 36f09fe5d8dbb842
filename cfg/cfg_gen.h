/*
 * cfg_gen.h — the app.cfg configurator's core: parses C-preprocessed
 * configuration text (static API calls, line markers) and writes the
 * generated kernel_cfg.h, kernel_cfg.c and the ATT_MOD module list.
 * The program around it (ev3cfg.c) runs the preprocessor and opens files.
 */
#ifndef EV3CFG_CFG_GEN_H
#define EV3CFG_CFG_GEN_H

#include <stdbool.h>
#include <stdio.h>

struct cfg_ctx;

/* Called for INCLUDE("file") found in from_file at from_line: parse that
 * file (cfg_parse) and return the number of errors it printed itself (those
 * cfg_parse reports are counted already). */
typedef int (*cfg_include_fn)(struct cfg_ctx *ctx, const char *file, const char *from_file,
			      int from_line, void *arg);

/* A new, empty configuration; errors are printed to err. */
struct cfg_ctx *cfg_new(FILE *err, cfg_include_fn include, void *include_arg);
void cfg_free(struct cfg_ctx *ctx);

/* Parses the preprocessed text of file name (line markers "# N \"file\"" move
 * the position).  The text of name and of every .cfg file is static APIs
 * only; C declarations from the headers they #include are skipped.  Returns
 * the number of errors reported ("file:line: error: API(ID): message", with
 * ":col" for what is not a static API). */
int cfg_parse(struct cfg_ctx *ctx, const char *text, const char *name);

/* Errors reported so far. */
int cfg_errors(const struct cfg_ctx *ctx);

/* The kernel profile a configuration is written for: TOPPERS/HRP2 (EV3RT
 * 0.x; times in ms, CRE_CYC with a handler) or TOPPERS/HRP3 (EV3RT 1.x;
 * times in us, CRE_CYC with a notification); AUTO: told by its static APIs. */
#define CFG_PROFILE_AUTO 0
#define CFG_PROFILE_HRP2 2
#define CFG_PROFILE_HRP3 3

/* Builds the configuration for profile (CFG_PROFILE_*), before cfg_parse: a
 * static API of the other kernel's form is then an error. */
/* A library's fragment (ev3cfg --library): every kind's IDs are counted from
 * the top of its range, the kind's last object being TNUM_xxx, so that an
 * application's IDs, counted from 1, never meet them; kernel_cfg.h gives
 * them as (TNUM_xxx - n). */
void cfg_set_library(struct cfg_ctx *ctx, bool library);
void cfg_set_profile(struct cfg_ctx *ctx, int profile);

/* The profile given, or told by the static APIs parsed (HRP3 if any is in
 * HRP3's form, else HRP2). */
int cfg_profile(const struct cfg_ctx *ctx);

/* With --kernel auto and no static API telling the profile, takes the
 * app's source as evidence of HRP3: a wait of what (at file:line) written in
 * microseconds.  True if that decided the profile. */
bool cfg_profile_from_source(struct cfg_ctx *ctx, const char *file, int line, const char *what);

/* Writes the header every source of the app is compiled with first (the
 * build's -include): it defines EV3LX_KERNEL_HRP3 for the HRP3 profile, so
 * that kernel.h gives HRP3's names, types and calls. */
void cfg_write_profile(const struct cfg_ctx *ctx, FILE *out);

/* Records an #include directive of a .cfg file, copied into kernel_cfg.c. */
void cfg_add_c_include(struct cfg_ctx *ctx, const char *directive);

/* Checks what needs the whole configuration (ATT_MOD's domain); returns errors. */
int cfg_finish(struct cfg_ctx *ctx);

/* Matches every ATT_MOD("x.o") with the object path whose file name is x.o;
 * reports (and counts) the modules that name none of them. */
int cfg_bind_modules(struct cfg_ctx *ctx, const char *const *objects, int nobjects);

/* The generated files: ID macros; tables and the root struct rtos_cfg named
 * symbol (source_name is the file name used in #line directives); the
 * module list ("object-basename linker-script" per ATT_MOD); one linker
 * script per ATT_MOD module (index 1..cfg_module_count). */
void cfg_write_header(const struct cfg_ctx *ctx, FILE *out, const char *symbol);
void cfg_write_source(const struct cfg_ctx *ctx, FILE *out, const char *symbol, const char *source_name);
int  cfg_module_count(const struct cfg_ctx *ctx);
const char *cfg_module_object(const struct cfg_ctx *ctx, int index);
const char *cfg_module_path(const struct cfg_ctx *ctx, int index);   /* after cfg_bind_modules */
void cfg_write_module_script(const struct cfg_ctx *ctx, FILE *out, int index);

#endif /* EV3CFG_CFG_GEN_H */

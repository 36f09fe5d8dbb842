/*
 * module.c — the module table: init order, exit, references, parameters.
 *
 * Initcalls and parameters are found through the linker sections
 * "lx_initcalls" and "lx_module_params" (linux/module.h): GNU ld defines
 * __start_<section> / __stop_<section> for them.  They are declared weak so
 * that an image without any module links too.
 */
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux/errno.h>
#include <linux_compat/platform.h>
#include <linux_compat/report.h>
#include <sil.h>
#include <linux_compat/modparam.h>

extern const struct lx_initcall *const __start_lx_initcalls[] __attribute__((__weak__));
extern const struct lx_initcall *const __stop_lx_initcalls[] __attribute__((__weak__));
extern const struct lx_module_param *const __start_lx_module_params[] __attribute__((__weak__));
extern const struct lx_module_param *const __stop_lx_module_params[] __attribute__((__weak__));

/* Live modules, most recently initialised first (the exit order). */
static struct module *live_modules;

/* The number of initcall entries linked. */
static size_t initcall_count(void)
{
	if (__start_lx_initcalls == NULL || __stop_lx_initcalls == NULL)
		return 0;
	return (size_t)(__stop_lx_initcalls - __start_lx_initcalls);
}

/* The number of parameter entries linked. */
static size_t param_count(void)
{
	if (__start_lx_module_params == NULL || __stop_lx_module_params == NULL)
		return 0;
	return (size_t)(__stop_lx_module_params - __start_lx_module_params);
}

/* True if a runs before b: lower level, then module name, then init before exit entries. */
static bool init_order_before(const struct lx_initcall *a, const struct lx_initcall *b)
{
	int cmp;

	if (a->level != b->level)
		return a->level < b->level;
	cmp = strcmp(module_name(a->module), module_name(b->module));
	if (cmp != 0)
		return cmp < 0;
	return (uintptr_t)a < (uintptr_t)b;
}

/* The module_exit function linked for mod, or NULL. */
static void (*exit_of(const struct module *mod))(void)
{
	size_t i, n = initcall_count();

	for (i = 0; i < n; i++)
		if (__start_lx_initcalls[i]->module == mod && __start_lx_initcalls[i]->exit != NULL)
			return __start_lx_initcalls[i]->exit;
	return NULL;
}

/* The next init entry to run after `prev` in the documented order (NULL = first). */
static const struct lx_initcall *next_init(const struct lx_initcall *prev)
{
	const struct lx_initcall *best = NULL, *c;
	size_t i, n = initcall_count();

	for (i = 0; i < n; i++) {
		c = __start_lx_initcalls[i];
		if (c->init == NULL)
			continue;
		if (prev != NULL && !init_order_before(prev, c))
			continue;
		if (best == NULL || init_order_before(c, best))
			best = c;
	}
	return best;
}

/* Makes mod live: at the head of the live list. */
static void make_live(struct module *mod)
{
	mod->state = MODULE_STATE_LIVE;
	mod->next_live = live_modules;
	live_modules = mod;
}

/* Longest boot command line (Linux's COMMAND_LINE_SIZE on ARM). */
#define BOOT_ARGS_MAX	1024

/* The boot command line, split in place; charp parameters point into it, as
 * into Linux's static_command_line, so it lives until the next boot. */
static char boot_args[BOOT_ARGS_MAX];

/* Sets the parameters the boot command line names ("module.param=value"
 * words, blank-separated), as Linux does for built-in modules; other words
 * are not for modules and are skipped. */
static void apply_boot_args(const char *args)
{
	char *word, *dot, *eq, *next;

	if (strlen(args) >= sizeof(boot_args)) {
		pr_err("boot command line longer than %d bytes; ignored\n", BOOT_ARGS_MAX - 1);
		return;
	}
	strcpy(boot_args, args);
	for (word = boot_args; *word != '\0'; word = next) {
		word += strspn(word, " \t");
		next = word + strcspn(word, " \t");
		if (*next != '\0')
			*next++ = '\0';
		dot = strchr(word, '.');
		eq = strchr(word, '=');
		if (dot == NULL || eq == NULL || dot > eq)
			continue;
		*dot = '\0';
		*eq = '\0';
		if (lx_module_param_set(word, dot + 1, eq + 1) == E_NOEXS)
			pr_warn("%s: unknown parameter '%s' ignored\n", word, dot + 1);
	}
}

/* True if a module other than mod with mod's name is loaded (its init ran or
 * runs, and did not fail): Linux refuses a second module of one name. */
static bool name_loaded(const struct module *mod)
{
	size_t i, n = initcall_count();

	for (i = 0; i < n; i++) {
		const struct module *other = __start_lx_initcalls[i]->module;

		if (other != NULL && other != mod && strcmp(other->name, mod->name) == 0 &&
		    (other->state == MODULE_STATE_COMING || other->state == MODULE_STATE_LIVE ||
		     other->state == MODULE_STATE_GOING))
			return true;
	}
	return false;
}

/* Runs each module_init once in order; the number that failed. */
int lx_modules_init(void)
{
	const struct lx_initcall *c = NULL;
	size_t i, n = initcall_count();
	struct module *mod;
	int failed = 0, ret;

	apply_boot_args(lx_platform_boot_args());

	while ((c = next_init(c)) != NULL) {
		mod = c->module;
		if (mod == NULL || mod->state != MODULE_STATE_UNFORMED)
			continue;
		if (name_loaded(mod)) {
			/* as insmod of a second module with one KBUILD_MODNAME
			 * (load_module: "module is already loaded"); its
			 * parameters stay the first one's */
			mod->state = MODULE_STATE_FAILED;
			mod->init_result = -EEXIST;
			pr_err("module %s: a module of that name is already loaded; this one is refused (-EEXIST), "
			       "its init and exit are not called\n", mod->name);
			failed++;
			continue;
		}
		mod->state = MODULE_STATE_COMING;
		ret = c->init();
		mod->init_result = ret;
		if (ret != 0) {
			mod->state = MODULE_STATE_FAILED;
			pr_err("module %s: init failed (%d); its exit will not be called\n",
			       mod->name, ret);
			failed++;
			continue;
		}
		make_live(mod);
	}
	/* Modules with only a module_exit are live from the start, as in Linux. */
	for (i = 0; i < n; i++) {
		mod = __start_lx_initcalls[i]->module;
		if (mod != NULL && mod->state == MODULE_STATE_UNFORMED) {
			if (name_loaded(mod)) {
				mod->state = MODULE_STATE_FAILED;
				mod->init_result = -EEXIST;
				pr_err("module %s: a module of that name is already loaded; this one is refused (-EEXIST)\n",
				       mod->name);
				failed++;
				continue;
			}
			make_live(mod);
		}
	}
	return failed;
}

/* Runs module_exit of the live modules, newest first; all become uninitialised. */
void lx_modules_exit(void)
{
	struct module *mod;
	void (*exit_fn)(void);
	size_t i, n = initcall_count();

	while ((mod = live_modules) != NULL) {
		live_modules = mod->next_live;
		mod->next_live = NULL;
		if (mod->refcnt != 0)
			pr_warn("module %s: unloaded with %d references held\n", mod->name, mod->refcnt);
		mod->state = MODULE_STATE_GOING;
		exit_fn = exit_of(mod);
		if (exit_fn != NULL)
			exit_fn();
		mod->state = MODULE_STATE_UNFORMED;
	}
	/* Failed modules may be tried again at the next lx_modules_init. */
	for (i = 0; i < n; i++) {
		mod = __start_lx_initcalls[i]->module;
		if (mod != NULL) {
			mod->state = MODULE_STATE_UNFORMED;
			mod->init_result = 0;
			mod->refcnt = 0;
		}
	}
}

/* Forgets every module's state (boot): each is uninitialised again, as after a power cycle. */
void lx_modules_reset(void)
{
	struct module *mod;
	size_t i, n = initcall_count();

	live_modules = NULL;
	for (i = 0; i < n; i++) {
		mod = __start_lx_initcalls[i]->module;
		if (mod != NULL) {
			mod->state = MODULE_STATE_UNFORMED;
			mod->init_result = 0;
			mod->refcnt = 0;
			mod->next_live = NULL;
		}
	}
}

/* The linked module called name (the loaded one where several share it), or NULL. */
struct module *lx_module_find(const char *name)
{
	size_t i, n = initcall_count();
	struct module *found = NULL;

	if (name == NULL)
		return NULL;
	for (i = 0; i < n; i++) {
		struct module *mod = __start_lx_initcalls[i]->module;

		if (mod == NULL || strcmp(mod->name, name) != 0)
			continue;
		if (mod->state == MODULE_STATE_LIVE || mod->state == MODULE_STATE_COMING)
			return mod;
		if (found == NULL)
			found = mod;
	}
	return found;
}

/* The module's name; "kernel" for built-in code. */
const char *module_name(const struct module *mod)
{
	return mod != NULL ? mod->name : "kernel";
}

/* A reference unless the module is going or failed. */
bool try_module_get(struct module *mod)
{
	bool ok;
	SIL_PRE_LOC;

	if (mod == NULL)
		return true;
	SIL_LOC_INT();
	ok = mod->state == MODULE_STATE_LIVE || mod->state == MODULE_STATE_COMING;
	if (ok)
		mod->refcnt++;
	SIL_UNL_INT();
	return ok;
}

/* A reference, unconditionally. */
void __module_get(struct module *mod)
{
	SIL_PRE_LOC;

	if (mod == NULL)
		return;
	SIL_LOC_INT();
	mod->refcnt++;
	SIL_UNL_INT();
}

/* Drops a reference; reports an unbalanced put. */
void module_put(struct module *mod)
{
	bool underflow;
	SIL_PRE_LOC;

	if (mod == NULL)
		return;
	SIL_LOC_INT();
	underflow = mod->refcnt <= 0;
	if (!underflow)
		mod->refcnt--;
	SIL_UNL_INT();
	if (underflow)
		lx_report("module_put without a reference", NULL, 0, "module %s", mod->name);
}

/* References held. */
int module_refcount(struct module *mod)
{
	return mod != NULL ? mod->refcnt : 0;
}

/* The parameter entry for module/param, or NULL. */
static const struct lx_module_param *find_param(const char *module, const char *param)
{
	size_t i, n = param_count();

	for (i = 0; i < n; i++) {
		const struct lx_module_param *p = __start_lx_module_params[i];

		if (strcmp(p->module, module) == 0 && strcmp(p->name, param) == 0)
			return p;
	}
	return NULL;
}

/* Parses value for p and stores it: 0 or -EINVAL / -ERANGE (the kstrto* rules). */
static int store_param(const struct lx_module_param *p, const char *value)
{
	bool bv;
	int ret = 0;

	switch (p->type) {
	case LX_PARAM_charp:
		*(const char **)p->arg = value;
		return 0;
	case LX_PARAM_bool:
	case LX_PARAM_invbool:
		/* Linux also accepts an empty value (a bare flag) as true. */
		if (value[0] == '\0')
			bv = true;
		else
			ret = kstrtobool(value, &bv);
		if (ret == 0)
			*(bool *)p->arg = p->type == LX_PARAM_bool ? bv : !bv;
		return ret;
	case LX_PARAM_int:
		return kstrtoint(value, 0, (int *)p->arg);
	case LX_PARAM_short:
		return kstrtos16(value, 0, (s16 *)p->arg);
	case LX_PARAM_long:
		return kstrtol(value, 0, (long *)p->arg);
	case LX_PARAM_uint:
		return kstrtouint(value, 0, (unsigned int *)p->arg);
	case LX_PARAM_ushort:
		return kstrtou16(value, 0, (u16 *)p->arg);
	case LX_PARAM_ulong:
		return kstrtoul(value, 0, (unsigned long *)p->arg);
	case LX_PARAM_byte:
		return kstrtou8(value, 0, (u8 *)p->arg);
	}
	return -EINVAL;
}

/* Sets a module parameter from text before the module is initialised. */
/* Sets the same parameter of every other module of p's name, as insmod's
 * arguments reach whichever of them loads (the others are refused,
 * -EEXIST): which one that is is only known at boot.  The value was valid
 * for p, whose type they share when built from one driver. */
static void store_in_namesakes(const struct lx_module_param *p, const char *value)
{
	size_t i, n = param_count();

	for (i = 0; i < n; i++) {
		const struct lx_module_param *q = __start_lx_module_params[i];

		if (q != p && strcmp(q->module, p->module) == 0 && strcmp(q->name, p->name) == 0 &&
		    store_param(q, value) != 0)
			pr_err("module %s: bad value \"%s\" for parameter %s of a module of the same name\n",
			       q->module, value, q->name);
	}
}

ER lx_module_param_set(const char *module, const char *param, const char *value)
{
	const struct lx_module_param *p;
	struct module *mod;

	if (module == NULL || param == NULL || value == NULL)
		return E_PAR;
	p = find_param(module, param);
	if (p == NULL)
		return E_NOEXS;
	mod = lx_module_find(module);
	if (mod != NULL && mod->state != MODULE_STATE_UNFORMED)
		return E_OBJ;
	if (store_param(p, value) != 0) {
		pr_err("module %s: bad value \"%s\" for parameter %s\n", module, value, param);
		return E_PAR;
	}
	store_in_namesakes(p, value);
	return E_OK;
}

/* Formats a module parameter's value into buf. */
ER lx_module_param_get(const char *module, const char *param, char *buf, SIZE len)
{
	const struct lx_module_param *p;

	if (module == NULL || param == NULL || buf == NULL || len == 0)
		return E_PAR;
	p = find_param(module, param);
	if (p == NULL)
		return E_NOEXS;
	switch (p->type) {
	case LX_PARAM_charp: {
		const char *s = *(const char **)p->arg;

		snprintf(buf, len, "%s", s != NULL ? s : "(null)");
		break;
	}
	case LX_PARAM_bool:
		snprintf(buf, len, "%c", *(bool *)p->arg ? 'Y' : 'N');
		break;
	case LX_PARAM_invbool:
		snprintf(buf, len, "%c", *(bool *)p->arg ? 'N' : 'Y');
		break;
	case LX_PARAM_int:
		snprintf(buf, len, "%d", *(int *)p->arg);
		break;
	case LX_PARAM_short:
		snprintf(buf, len, "%hd", *(short *)p->arg);
		break;
	case LX_PARAM_long:
		snprintf(buf, len, "%ld", *(long *)p->arg);
		break;
	case LX_PARAM_uint:
		snprintf(buf, len, "%u", *(unsigned int *)p->arg);
		break;
	case LX_PARAM_ushort:
		snprintf(buf, len, "%hu", *(unsigned short *)p->arg);
		break;
	case LX_PARAM_ulong:
		snprintf(buf, len, "%lu", *(unsigned long *)p->arg);
		break;
	case LX_PARAM_byte:
		snprintf(buf, len, "%hhu", *(unsigned char *)p->arg);
		break;
	}
	return E_OK;
}

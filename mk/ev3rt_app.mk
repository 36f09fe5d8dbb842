# EV3RT-style apps: app.cfg through the configurator (cfg/ev3cfg.c), then
# compile and link.  Call once per app and build configuration:
#
#   $(eval $(call ev3rt_app,NAME,CONFIG,CFG,SRCS[,RUNNER]))
#
#   NAME    the app's name; it builds in $(BUILD)/CONFIG/ev3rt/NAME/
#   CONFIG  host, host-san, host32 or arm926-test
#   CFG     the app's configuration file (app.cfg); its directory is on the
#           include path of everything below, then cfg/ (app_common.cfg)
#           and the platform's headers
#   SRCS    the app's sources: C (.c) and C++ (.cpp, compiled with g++;
#           the program is then linked with g++, so libstdc++ is linked;
#           the app's global constructors run in the platform's app-init
#           task at boot, before the app's tasks, as on EV3RT: see the
#           object's rule below)
#   RUNNER  optional: objects with main() (booting ev3rt_app_cfg); the app is
#           then also linked as the program $(BUILD)/CONFIG/ev3rt/NAME/NAME
#
# EV3RT_SYMBOL_NAME (optional, set before the call) names the configuration
# symbol instead of ev3rt_app_cfg.  EV3RT_KERNEL_NAME (optional): the kernel
# profile, hrp2 or hrp3 (ev3cfg --kernel); by default ev3cfg tells it from
# the configuration (docs/ev3rt-apps.md, "Two kernel profiles") and writes
# gen/kernel_profile.h, which every source of the app includes first.  EV3RT_PLATFORM_NAME_CONFIG (optional):
# what the program links the app against instead of libev3lx.a.  EV3RT_LIBS_NAME_CONFIG (optional): static
# libraries the program links after the app (an EV3RT SDK library's archive,
# Makefile.inc's APPL_LIBS).
#
# An app's `main` is an ordinary function on EV3RT (the platform boots the
# kernel, the app's tasks call main() if they like): NAME.o renames it
# ev3rt_app_main, so it never meets the runner's main(); its file calls go to
# the simulated SD card (EV3RT_APP_FS_SYMS).
#
# It produces gen/kernel_cfg.h and gen/kernel_cfg.c (the ID macros, and the
# tables as `const struct rtos_cfg ev3rt_app_cfg`), and NAME.o: one
# relocatable object holding the app's objects, every ATT_MOD object relinked
# into its domain's sections, and kernel_cfg.o — link it with a runner and
# libev3lx.a.  App sources get EV3RT_APP_WARN (no -Werror: apps build
# unchanged; none under the app's OMIT_WARNING_ALL, EV3RT_OMIT_WALL_NAME_CONFIG)
# and, last, the app's own flags (EV3RT_APPFLAGS_NAME_CONFIG: its COPTS, CDEFS,
# APPL_CFLAGS); the program is linked with its EV3RT_LDFLAGS_NAME_CONFIG;
# configuration errors stop the build with "app.cfg:LINE: ...".
EV3RT_APP_WARN ?= -Wall -Wno-unused-parameter

# The app's C library file calls (fopen, open, mkdir, rename, remove, stat,
# opendir...), its libraries' too, are renamed in its object to ev3sim's,
# which work on the simulated SD card as newlib over FatFs does on the brick
# (ev3sim/src/app_fs.c): the app itself is unchanged.
EV3RT_APP_FS_SYMS := mk/ev3rt_app_fs.syms
# The app's malloc family and C++ operators new and delete are renamed the
# same way to the apps' heap in its domain (api/src/app_malloc.c), as an
# EV3RT app's newlib allocates from the heap EV3RT gives its domain.
EV3RT_APP_HEAP_SYMS := mk/ev3rt_app_heap.syms
# The languages EV3RT's app build compiles in (public source:
# ev3rt-git/ev3rt-hrp2-sdk, common/Makefile.img: gcc -std=gnu99, g++
# -std=gnu++11).  A plain `inline` function gets an external definition
# too (GNU89's rule): EV3RT's older gcc inlined every call of such a
# function in its sample apps (hwbrickbench), where today's may not and the
# call would have no definition to link against.
EV3RT_APP_CSTD   ?= -std=gnu99 -fgnu89-inline
EV3RT_APP_CXXSTD ?= -std=gnu++11
# An inline function's static (a singleton's getInstance()) and its guard are
# weak symbols, as on EV3RT's bare-metal toolchain, not GNU unique ones: the
# relink of each ATT_MOD object below drops section groups, and two modules
# with the same unique symbol would then clash instead of sharing one.
EV3RT_APP_CXXSYMS ?= -fno-gnu-unique
# The app's own computation costs virtual CPU time: every basic block calls
# the host kernel's __sanitizer_cov_trace_pc (rtos_host.h, CPU time).
EV3RT_APP_CPU    ?= -fsanitize-coverage=trace-pc

# The app compile flags above are a key of each configuration's
# ($(BUILD)/CONFIG/ev3rt/app.key) that every app object depends on, made once.
ev3rt_app_key = $(if $(EV3RT_APP_KEY_$(1)),,$(eval EV3RT_APP_KEY_$(1) := $(BUILD)/$(1)/ev3rt/app.key)$(eval \
	$(call key_file_rule,$(BUILD)/$(1)/ev3rt/app.key,$$(EV3RT_APP_CSTD) $$(EV3RT_APP_CXXSTD) $$(EV3RT_APP_CXXSYMS) $$(EV3RT_APP_CPU) $$(EV3RT_APP_WARN))))

# An app built with --kernel auto whose app.cfg names no time event (EV3RT
# 1.x's samples and tutorials often have none) is told by its source: a
# wait written in microseconds — a literal of 100000 or more in a call that
# takes a timeout (100 s as HRP2's milliseconds, 0.1 s as HRP3's
# microseconds) — is the hint ev3cfg takes (--time-hint), once per app.
EV3RT_TIMED_CALLS := dly_tsk|tslp_tsk|twai_sem|twai_flg|tsnd_dtq|trcv_dtq|tsnd_pdq|trcv_pdq|tloc_mtx
EV3RT_TIME_GREP := grep -HnoE '\b($(EV3RT_TIMED_CALLS))[[:space:]]*[(]([^;]*[^0-9_A-Za-z])?[1-9][0-9]{5,}'
EV3RT_TIME_SED := sed -E 's/^([^:]*:[0-9]+:)([a-z_]+).*[^0-9]([1-9][0-9]{5,})$$/\1\2 with \3/'
ev3rt_time_hint = $(if $(filter auto,$(or $(EV3RT_KERNEL_$(1)),auto)),$(if $(filter undefined,$(origin \
	EV3RT_TIME_HINT_$(1))),$(eval EV3RT_TIME_HINT_$(1) := $$(shell $$(EV3RT_TIME_GREP) $(2) /dev/null 2>/dev/null \
	| head -n 1 | $$(EV3RT_TIME_SED))))$(EV3RT_TIME_HINT_$(1)))

define ev3rt_app
$(call ev3rt_app_key,$(2))
EV3RT_DIR_$(1)_$(2)  := $(BUILD)/$(2)/ev3rt/$(1)
EV3RT_OBJS_$(1)_$(2) := $$(patsubst %,$(BUILD)/$(2)/ev3rt/$(1)/obj/%.o,$$(basename $(4)))
EV3RT_LINK_$(1)_$(2) := $$(if $$(filter %.cpp,$(4)),$$(CXX_$(2)),$$(CC_$(2)))
EV3RT_INC_$(1)_$(2)  := -I$(BUILD)/$(2)/ev3rt/$(1)/gen -I$(patsubst %/,%,$(dir $(3))) -Icfg $(call layer_inc,api)
EV3RT_PROFILE_$(1)_$(2) := -include $(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_profile.h
EV3RT_HINT_$(1)_$(2) := $$(call ev3rt_time_hint,$(1),$$(filter %.c %.cpp,$(4)))
$(eval $(call key_file_rule,$(BUILD)/$(2)/ev3rt/$(1)/kernel.key,$(or $(EV3RT_KERNEL_$(1)),auto) $$(EV3RT_HINT_$(1)_$(2))))

$(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_cfg.c: $(3) $$(EV3CFG) cfg/app_common.cfg cfg/tecsgen.cfg \
		$$(wildcard $(dir $(3))*.h $(dir $(3))*.cfg) $(BUILD)/$(2)/ev3rt/$(1)/kernel.key
	@mkdir -p $$(@D)
	$$(quiet) CFG $(2) $(3)
	$(Q)$$(EV3CFG) -o $$(@D) --cpp '$$(CC_$(2)) -E' $$(EV3RT_INC_$(1)_$(2)) $(KERNEL_DEFS) \
		$(if $(EV3RT_SYMBOL_$(1)),--symbol $(EV3RT_SYMBOL_$(1))) --kernel $(or $(EV3RT_KERNEL_$(1)),auto) \
		$$(if $$(EV3RT_HINT_$(1)_$(2)),--time-hint '$$(EV3RT_HINT_$(1)_$(2))') \
		$$(addprefix --object ,$$(EV3RT_OBJS_$(1)_$(2))) $(3)

$(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_cfg.h $(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_profile.h: \
	$(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_cfg.c ;

$(BUILD)/$(2)/ev3rt/$(1)/obj/%.o: %.c $(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_cfg.h $(BUILD)/$(2)/compile.key \
		$(BUILD)/$(2)/ev3rt/app.key
	@mkdir -p $$(@D)
	$$(quiet) CC $(2) $$<
	$(Q)$$(CC_$(2)) $$(EV3RT_APP_CSTD) $$(EV3RT_APP_CPU) $$(EV3RT_PROFILE_$(1)_$(2)) $$(EV3RT_INC_$(1)_$(2)) \
		$$(if $$(EV3RT_OMIT_WALL_$(1)_$(2)),,$$(EV3RT_APP_WARN)) $$(CFLAGS_$(2)) $(KERNEL_DEFS) $$(EV3RT_APPFLAGS_$(1)_$(2)) \
		-MMD -MP -c $$< -o $$@

$(BUILD)/$(2)/ev3rt/$(1)/obj/%.o: %.cpp $(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_cfg.h $(BUILD)/$(2)/compile.key \
		$(BUILD)/$(2)/ev3rt/app.key
	@mkdir -p $$(@D)
	$$(quiet) CXX $(2) $$<
	$(Q)$$(CXX_$(2)) $$(EV3RT_APP_CXXSTD) $$(EV3RT_APP_CXXSYMS) $$(EV3RT_APP_CPU) $$(EV3RT_PROFILE_$(1)_$(2)) $$(EV3RT_INC_$(1)_$(2)) \
		$$(if $$(EV3RT_OMIT_WALL_$(1)_$(2)),,$$(EV3RT_APP_WARN)) $$(CFLAGS_$(2)) $(KERNEL_DEFS) $$(EV3RT_APPFLAGS_$(1)_$(2)) \
		-MMD -MP -c $$< -o $$@

$(BUILD)/$(2)/ev3rt/$(1)/kernel_cfg.o: $(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_cfg.c $(BUILD)/$(2)/compile.key
	$$(quiet) CC $(2) $$<
	$(Q)$$(CC_$(2)) -std=gnu11 $$(EV3RT_INC_$(1)_$(2)) $$(EV3RT_APP_WARN) $$(CFLAGS_$(2)) $(KERNEL_DEFS) \
		-MMD -MP -c $$< -o $$@

# Each ATT_MOD object is relinked into its domain's sections; C++'s section
# groups (an inline function's static, a template's code) are placed like
# any section (--force-group-allocation), or they would stay outside the
# domain.  The app's SDK libraries (EV3RT_DOMLIBS_NAME_CONFIG) are linked
# into the domain of the app's first module, as EV3RT links them into the
# app's module: a library's buffers are the app's.  The app's C++ global
# constructors (its objects' and libraries' .init_array; not the
# configuration's, nor a sanitizer's, whose sections have a priority in
# their names) go to ev3rt_app_init_array, which the platform's app-init task
# runs at boot as EV3RT's does (api/src/app_init.c), and its __cxa_atexit is
# the platform's, which registers no destructor, as EV3RT runs none.  An
# app's own __dso_handle (ET Robocon's C++ apps define `void *__dso_handle`
# for EV3RT's toolchain, which had none) stays the app's: it would clash with
# the host C library's start-up file.  (The recipe is a prerequisite: an object linked by an older one would construct
# its globals before boot.)
$(BUILD)/$(2)/ev3rt/$(1)/$(1).o: $$(EV3RT_OBJS_$(1)_$(2)) $(BUILD)/$(2)/ev3rt/$(1)/kernel_cfg.o \
		$$(EV3RT_DOMLIBS_$(1)_$(2)) $(EV3RT_APP_FS_SYMS) $(EV3RT_APP_HEAP_SYMS) mk/ev3rt_app.mk
	$$(quiet) LD $(2) $$@
	$(Q)set -e; objs=; \
	for o in $$(EV3RT_OBJS_$(1)_$(2)); do \
		script=$$$$(awk -v o="$$$$o" '$$$$1 == o { print $$$$2 }' $(BUILD)/$(2)/ev3rt/$(1)/gen/modules.txt); \
		if [ -n "$$$$script" ]; then \
			$$(CC_$(2)) -r -nostdlib -Wl,--force-group-allocation -o "$$$$o.dom.o" -Wl,-T,"$$$$script" "$$$$o"; \
			objs="$$$$objs $$$$o.dom.o"; \
		else \
			objs="$$$$objs $$$$o"; \
		fi; \
	done; \
	if [ -n "$$(strip $$(EV3RT_DOMLIBS_$(1)_$(2)))" ]; then \
		script=$$$$(awk 'NR == 1 { print $$$$2 }' $(BUILD)/$(2)/ev3rt/$(1)/gen/modules.txt); \
		$$(CC_$(2)) -r -nostdlib -Wl,--force-group-allocation -o $$@.libs.o \
			$$$${script:+-Wl,-T,"$$$$script"} -Wl,--whole-archive $$(EV3RT_DOMLIBS_$(1)_$(2)) -Wl,--no-whole-archive; \
		objs="$$$$objs $$@.libs.o"; \
	fi; \
	$$(CC_$(2)) -r -nostdlib -o $$@.app.o $$$$objs; \
	$$(OBJCOPY_$(2)) --rename-section .init_array=ev3rt_app_init_array $$@.app.o; \
	$$(CC_$(2)) -r -nostdlib -o $$@ $$@.app.o $(BUILD)/$(2)/ev3rt/$(1)/kernel_cfg.o; \
	$$(OBJCOPY_$(2)) --redefine-sym main=ev3rt_app_main --redefine-sym __cxa_atexit=ev3rt_app_cxa_atexit \
		--localize-symbol=__dso_handle --redefine-syms=$(EV3RT_APP_FS_SYMS) \
		--redefine-syms=$(EV3RT_APP_HEAP_SYMS) $$@

ifneq ($(strip $(5)),)
EV3RT_PLATFORM_$(1)_$(2) ?= $(BUILD)/$(2)/libev3lx.a
$(BUILD)/$(2)/ev3rt/$(1)/$(1): $(BUILD)/$(2)/ev3rt/$(1)/$(1).o $(5) $$(EV3RT_PLATFORM_$(1)_$(2)) $$(EV3RT_LIBS_$(1)_$(2))
	$$(quiet) LD $(2) $$@
	$(Q)$$(EV3RT_LINK_$(1)_$(2)) $$(CFLAGS_$(2)) $$(LDFLAGS_$(2)) $$(EV3RT_LDFLAGS_$(1)_$(2)) -o $$@ $$< $(5) \
		-Wl,--start-group $$(EV3RT_LIBS_$(1)_$(2)) $$(EV3RT_PLATFORM_$(1)_$(2)) -Wl,--end-group -lm \
		$$(EV3RT_LDLIBS_$(1)_$(2))
endif

-include $$(EV3RT_OBJS_$(1)_$(2):.o=.d) $(BUILD)/$(2)/ev3rt/$(1)/kernel_cfg.d
endef

# The configurator's own test app, linked into tests/cfg/test_app_cfg in every
# host configuration: the test's object is the test code plus the whole app.
define ev3rt_cfg_test
$(call ev3rt_app,cfg_test_app,$(1),tests/cfg/app_kernel/app.cfg,tests/cfg/app_kernel/app.c)

$(BUILD)/$(1)/obj/tests/cfg/test_app_cfg.o: tests/cfg/test_app_cfg.c $(BUILD)/$(1)/ev3rt/cfg_test_app/cfg_test_app.o
	@mkdir -p $$(@D)
	$$(quiet) CC $(1) $$<
	$(Q)$$(CC_$(1)) $$(call src_flags,$$<) -Itests/cfg/app_kernel -I$(BUILD)/$(1)/ev3rt/cfg_test_app/gen \
		$$(WARN) $$(CFLAGS_$(1)) $(KERNEL_DEFS) -MMD -MP -c $$< -o $$@.main.o
	$(Q)$$(CC_$(1)) -r -nostdlib -o $$@ $$@.main.o $(BUILD)/$(1)/ev3rt/cfg_test_app/cfg_test_app.o
endef
$(foreach c,$(HOST_CONFIGS),$(eval $(call ev3rt_cfg_test,$(c))))

# The configurator's pass 1 tested in-process: the test object of $(2)
# (tests/cfg/test_cfg_errors, the fuzz harness tests/cfg/test_fuzz_cfg) in
# configuration $(1) includes cfg_gen.
define ev3rt_cfg_unit_test
$(BUILD)/$(1)/obj/$(2).o: $(2).c cfg/cfg_gen.c cfg/cfg_gen.h $(BUILD)/$(1)/compile.key
	@mkdir -p $$(@D)
	$$(quiet) CC $(1) $$<
	$(Q)$$(CC_$(1)) $$(call src_flags,$$<) -Icfg $$(WARN) $$(CFLAGS_$(1)) -MMD -MP -c $$< -o $$@.main.o
	$(Q)$$(CC_$(1)) -std=c11 $$(WARN) $$(CFLAGS_$(1)) -c cfg/cfg_gen.c -o $$@.gen.o
	$(Q)$$(CC_$(1)) -r -nostdlib -o $$@ $$@.main.o $$@.gen.o
endef
EV3CFG_UNIT_TESTS := tests/cfg/test_cfg_errors tests/cfg/test_fuzz_cfg
$(foreach c,$(HOST_CONFIGS),$(foreach t,$(EV3CFG_UNIT_TESTS),$(eval $(call ev3rt_cfg_unit_test,$(c),$(t)))))

# `make cfg-error-check` (in `make test`): every configuration in tests/cfg/bad
# fails — in ev3cfg or when kernel_cfg.c is compiled — with the messages its
# "/* expect: ... */" lines give (file, line, static API); and ev3cfg built
# with ASan, UBSan and LeakSanitizer says the same of it, with no report of
# its own (every error path frees what it took).
CFG_BAD_INC := -Itests/cfg/bad -Icfg $(call layer_inc,api)

.PHONY: cfg-error-check
cfg-error-check: $(EV3CFG) $(EV3CFG_SAN)
	@set -e; export LC_ALL=C; n=0; \
	for f in tests/cfg/bad/*.cfg; do \
		out=$(BUILD)/cfg-error-check/$$(basename $$f .cfg); rm -rf $$out; mkdir -p $$out/san; \
		if $(EV3CFG) -o $$out --cpp 'gcc -E' $(CFG_BAD_INC) --object $$out/main.o $$f 2> $$out/errors.txt; then \
			if gcc -std=gnu11 -I$$out $(CFG_BAD_INC) -c $$out/kernel_cfg.c -o $$out/kernel_cfg.o \
				2>> $$out/errors.txt; then \
				echo "cfg-error-check: $$f: accepted"; exit 1; \
			fi; \
		fi; \
		grep -a '^/\* expect: ' $$f | sed 's|^/\* expect: \(.*\) \*/$$|\1|' | while IFS= read -r e; do \
			grep -qF -- "$$e" $$out/errors.txt || \
				{ echo "cfg-error-check: $$f: no \"$$e\" in:"; cat $$out/errors.txt; exit 1; }; \
		done; \
		ASAN_OPTIONS=detect_leaks=1 $(EV3CFG_SAN) -o $$out/san --cpp 'gcc -E' $(CFG_BAD_INC) \
			--object $$out/main.o $$f > $$out/san.txt 2>&1 || true; \
		$(EV3CFG) -o $$out/san --cpp 'gcc -E' $(CFG_BAD_INC) --object $$out/main.o $$f > $$out/plain.txt 2>&1 || true; \
		cmp -s $$out/san.txt $$out/plain.txt || \
			{ echo "cfg-error-check: $$f: the sanitized ev3cfg says otherwise:"; \
			  diff $$out/plain.txt $$out/san.txt || true; exit 1; }; \
		n=$$((n + 1)); \
	done; \
	echo "cfg-error-check: $$n bad configurations, each reported at its file, line and static API, without a leak"
TEST_SUITE_EXTRA += cfg-error-check

# EV3RT-style apps beyond the configurator's rule (mk/ev3rt_app.mk):
#
#   examples/NAME/   each example app is built in every host configuration and
#                    linked into its test, tests/examples/test_NAME.c, which
#                    runs it in ev3sim's robots (ev3sim/run.h) and asserts what
#                    it does.
#   tests/ev3sim/apps/NAME/  ev3sim's own test apps, each linked into
#                    tests/ev3sim/test_app_NAME.c the same way.
#   ev3rt-app        `make ev3rt-app APP=/abs/dir [EV3RT_LIB_DIR=/abs/dir]`
#                    builds the runner of any app directory,
#                    $(BUILD)/host/ev3rt/KEY/KEY (KEY: run_NAME, or
#                    EV3RT_RUN_KEY), the app named NAME (EV3RT_APP_NAME, else
#                    the directory's name): what `ev3sim run APP_DIR
#                    [--lib-dir DIR]` does before executing it.  ev3sim calls
#                    it with APP and EV3RT_LIB_DIR links to the directories
#                    inside KEY, a key made of the name and a hash of the real
#                    path, and a lock on the build (ev3sim/src/app_build.c):
#                    make expands '$' in APP and splits it at spaces, so a
#                    path given here directly must have neither.  The
#                    app's Makefile.inc is read as EV3RT's app build reads it
#                    (public source: ev3rt-git/ev3rt-hrp2-sdk, common/Makefile.app
#                    and Makefile.prj.common): SRCLANG (c, or c++: the app is
#                    app.cpp), APPL_COBJS (C), APPL_CXXOBJS (C++), APPL_DIRS,
#                    INCLUDES, APPL_LIBS and LIBS (linked), mkfile_path; every
#                    `include` directory under the app is on the include path
#                    and every `src` directory is searched for sources; under
#                    CONFIG_EV3RT_APPLICATION it may include an SDK library's
#                    Makefile from $(EV3RT_SDK_LIB_DIR)/<lib>/Makefile (see
#                    mk/ev3rt/Makefile.slib).

# Reads the Makefile.inc of app directory $(1) (mk/ev3rt/appinfo.mk) into
# the variables $(2)_*, its SDK libraries from directory $(3), through the
# build directory $(4).
# It is written beside and renamed into place, so a make reading the same
# app at the same time never includes half of it.
ev3rt_read_app = $(if $(shell env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL $(MAKE) -s --no-print-directory \
	-f mk/ev3rt/appinfo.mk APP='$(1)' PREFIX='$(2)' EV3RT_LIB_DIR='$(3)' SDKDIR='$(4)' \
	OUT='$(4)/appinfo.mk.'$$$$ info >&2 && mv -f '$(4)/appinfo.mk.'$$$$ '$(4)/appinfo.mk' && echo ok),\
	$(eval include $(4)/appinfo.mk),$(error $(1)/Makefile.inc: the app could not be read))

# SDK library $(1) of app $(2) in configuration $(3), its sources in
# $(4)_SLIB_SRCS_$(1): compiled as the app's are (the app's include path, its
# pattern rules), in one archive.
define ev3rt_slib_rules
EV3RT_SLIB_OBJS_$(2)_$(1)_$(3) := $$(patsubst %,$(BUILD)/$(3)/ev3rt/$(2)/obj/%.o,$$(basename $$($(4)_SLIB_SRCS_$(1))))
$(BUILD)/$(3)/ev3rt/$(2)/lib/$(1).a: $$(EV3RT_SLIB_OBJS_$(2)_$(1)_$(3))
	@mkdir -p $$(@D)
	$$(quiet) AR $(3) $$@
	$(Q)rm -f $$@ && ar rcs $$@ $$^
-include $$(EV3RT_SLIB_OBJS_$(2)_$(1)_$(3):.o=.d)
endef

# App $(1) in configuration $(2) from app directory $(3), as read into $(4)_*
# (ev3rt_read_app): its sources, SDK libraries (linked into its domain),
# other libraries and include path; $(5): a runner's objects (ev3rt_app).
define ev3rt_dir_app
EV3RT_LIBS_$(1)_$(2) := $$(filter-out -l%,$$($(4)_LDLIBS))
EV3RT_LDLIBS_$(1)_$(2) := $$(filter -l%,$$($(4)_LDLIBS))
EV3RT_DOMLIBS_$(1)_$(2) := $$(patsubst %,$(BUILD)/$(2)/ev3rt/$(1)/lib/%.a,$$($(4)_SLIBS))
EV3RT_APPFLAGS_$(1)_$(2) := $$($(4)_CFLAGS)
EV3RT_OMIT_WALL_$(1)_$(2) := $$($(4)_OMIT_WALL)
EV3RT_LDFLAGS_$(1)_$(2) := $$($(4)_LDFLAGS)
$(call ev3rt_app,$(1),$(2),$(3)/app.cfg,$$($(4)_SRCS),$(5))
EV3RT_INC_$(1)_$(2) += $$($(4)_INCLUDES)
$$(foreach l,$$($(4)_SLIBS),$$(eval $$(call ev3rt_slib_rules,$$(l),$(1),$(2),$(4))))
# the objects ATT_MOD names come from Makefile.inc too
$(BUILD)/$(2)/ev3rt/$(1)/gen/kernel_cfg.c: $$(wildcard $(3)/Makefile.inc)
endef

EXAMPLES := $(patsubst examples/%/app.cfg,%,$(wildcard examples/*/app.cfg))

# Each example's Makefile.inc, read once; its SDK libraries are in examples/library.
$(foreach e,$(EXAMPLES),$(call ev3rt_read_app,examples/$(e),EXAMPLE_$(e),$(CURDIR)/examples/library,$(BUILD)/ev3rt-info/$(e)))

# $(1) = example, $(2) = config
define ev3rt_example_rules
$(call ev3rt_dir_app,$(1),$(2),examples/$(1),EXAMPLE_$(1))
# a C++ example's test links libstdc++, as the app's program would
TEST_LDLIBS_examples/test_$(1) := $$(if $$(filter %.cpp,$$(EXAMPLE_$(1)_SRCS)),-lstdc++) \
	$$(EXAMPLE_$(1)_LDFLAGS) $$(EXAMPLE_$(1)_LDLIBS)

$(BUILD)/$(2)/obj/tests/examples/test_$(1).o: tests/examples/test_$(1).c $(BUILD)/$(2)/ev3rt/$(1)/$(1).o
	@mkdir -p $$(@D)
	$$(quiet) CC $(2) $$<
	$(Q)$$(CC_$(2)) $$(call src_flags,$$<) $$(WARN) $$(CFLAGS_$(2)) $(KERNEL_DEFS) \
		-MMD -MP -MF $$(@:.o=.d) -MT $$@ -c $$< -o $$@.main.o
	$(Q)$$(CC_$(2)) -r -nostdlib -o $$@ $$@.main.o $(BUILD)/$(2)/ev3rt/$(1)/$(1).o
endef
$(foreach c,$(HOST_CONFIGS),$(foreach e,$(EXAMPLES),$(eval $(call ev3rt_example_rules,$(e),$(c)))))

# The platform `ev3sim run` links an app against: the library and the
# runner's image writers as one object in which the only global names are
# those the app's headers declare and the runner's entry (ev3sim_run_main),
# so an app's own global names (a tick_handler, a jiffies) never meet
# ev3lx's, as on EV3RT, whose kernel and app are separate images.  The app's
# file calls and its heap calls, renamed (mk/ev3rt_app.mk), are the platform's: those names stay too.
EV3RT_APP_FS_CALLS := $(sort $(shell awk '{ print $$2 }' $(EV3RT_APP_FS_SYMS) $(EV3RT_APP_HEAP_SYMS)))
# The configurations whose ev3sim runs apps: host, and host32 (the target's
# 32-bit types; its ev3sim has no image writers and no live view's server:
# no 32-bit libpng, giflib or libmicrohttpd comes with gcc-multilib).
EV3SIM_CONFIGS := host host32
EV3SIM_WRITERS_host := ev3sim/lcd_png.c ev3sim/lcd_gif.c ev3sim/world_file.c ev3sim/live_http.c
EV3SIM_WRITERS_host32 :=
EV3SIM_LDLIBS_host := -lpng -lgif -ljson-c
EV3SIM_LDLIBS_host32 :=
EV3RT_PLATFORM = $(BUILD)/$(1)/ev3rt/platform.o
EV3RT_PLATFORM_OBJS = $(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$(EV3SIM_WRITERS_$(1)))
# $(1) = config
define ev3rt_platform_rules
$(call EV3RT_PLATFORM,$(1)): $(LIB_$(1)) $(call EV3RT_PLATFORM_OBJS,$(1)) mk/ev3rt/platform_syms.sh $(EV3RT_APP_FS_SYMS) $(EV3RT_APP_HEAP_SYMS) \
		$(wildcard api/*.h api/syssvc/*.h rtos_stub/include/*.h rtos_stub/include/syssvc/*.h)
	@mkdir -p $$(@D)
	$$(quiet) LD $(1) $$@
	$(Q)set -e; tmp=$$@.$$$$$$$$; \
	$(LD_$(1)) -r -o $$$$tmp.r.o --whole-archive $(LIB_$(1)) --no-whole-archive $(call EV3RT_PLATFORM_OBJS,$(1)); \
	PLATFORM_KEEP='ev3sim_run_main __sanitizer_cov_trace_pc ev3rt_app_cxa_atexit $(EV3RT_APP_FS_CALLS)' bash mk/ev3rt/platform_syms.sh $$$$tmp.r.o \
		$(CC_$(1)) $(call layer_inc,api) $(CFLAGS_$(1)) $(KERNEL_DEFS) > $$$$tmp.syms; \
	$(OBJCOPY_$(1)) --keep-global-symbols=$$$$tmp.syms $$$$tmp.r.o $$$$tmp; \
	mv $$$$tmp.syms $$@.syms; rm -f $$$$tmp.r.o; mv $$$$tmp $$@
# Made with ev3sim, so that `ev3sim run` finds it made: apps' builds in
# parallel (each under its own lock) would each make it; each makes it in
# files of its own and renames them into place, so even then none sees
# another's half-written object.
$(BUILD)/$(1)/ev3sim: | $(call EV3RT_PLATFORM,$(1))
endef
$(foreach c,$(EV3SIM_CONFIGS),$(eval $(call ev3rt_platform_rules,$(c))))

# The tests of ev3lx's SDK libraries (api/library/LIB): an app that takes
# the library from its Makefile.inc, tests/api/library/LIB/app/, linked into
# tests/api/library/LIB/test_*.c (each runs it as an example's test does).
EV3RT_LIB_TESTS := $(patsubst tests/api/library/%/app/app.cfg,%,$(wildcard tests/api/library/*/app/app.cfg))
$(foreach l,$(EV3RT_LIB_TESTS),$(call ev3rt_read_app,tests/api/library/$(l)/app,LIBTEST_$(l),,$(BUILD)/ev3rt-info/libtest_$(l)))

# $(1) = library, $(2) = config, $(3) = a test (its path without .c)
define ev3rt_lib_test_rules
TEST_LDLIBS_$(patsubst tests/%,%,$(3)) := -lstdc++
$(BUILD)/$(2)/obj/$(3).o: $(3).c $(BUILD)/$(2)/ev3rt/libtest_$(1)/libtest_$(1).o
	@mkdir -p $$(@D)
	$$(quiet) CC $(2) $$<
	$(Q)$$(CC_$(2)) $$(call src_flags,$$<) $$(WARN) $$(CFLAGS_$(2)) $(KERNEL_DEFS) \
		-MMD -MP -MF $$(@:.o=.d) -MT $$@ -c $$< -o $$@.main.o
	$(Q)$$(CC_$(2)) -r -nostdlib -o $$@ $$@.main.o $(BUILD)/$(2)/ev3rt/libtest_$(1)/libtest_$(1).o
endef
$(foreach c,$(HOST_CONFIGS),$(foreach l,$(EV3RT_LIB_TESTS),\
	$(eval $(call ev3rt_dir_app,libtest_$(l),$(c),tests/api/library/$(l)/app,LIBTEST_$(l)))\
	$(foreach t,$(patsubst %.c,%,$(wildcard tests/api/library/$(l)/test_*.c)),\
		$(eval $(call ev3rt_lib_test_rules,$(l),$(c),$(t))))))

# ev3sim's own test apps, tests/ev3sim/apps/NAME (app.c alone): each linked
# into tests/ev3sim/test_app_NAME.c as an example is into its test, as
# ev3sim_test_NAME (no example's name).
# (only those with an app: test_app_build.c tests ev3sim/src/app_build.c)
EV3SIM_TEST_APPS := $(filter $(patsubst tests/ev3sim/apps/%/app.cfg,%,$(wildcard tests/ev3sim/apps/*/app.cfg)),\
	$(patsubst tests/ev3sim/test_app_%.c,%,$(wildcard tests/ev3sim/test_app_*.c)))

# $(1) = test app, $(2) = config
define ev3sim_test_app_rules
$(call ev3rt_app,ev3sim_test_$(1),$(2),tests/ev3sim/apps/$(1)/app.cfg,tests/ev3sim/apps/$(1)/app.c)

$(BUILD)/$(2)/obj/tests/ev3sim/test_app_$(1).o: tests/ev3sim/test_app_$(1).c \
		$(BUILD)/$(2)/ev3rt/ev3sim_test_$(1)/ev3sim_test_$(1).o
	@mkdir -p $$(@D)
	$$(quiet) CC $(2) $$<
	$(Q)$$(CC_$(2)) $$(call src_flags,$$<) $$(WARN) $$(CFLAGS_$(2)) $(KERNEL_DEFS) \
		-MMD -MP -MF $$(@:.o=.d) -MT $$@ -c $$< -o $$@.main.o
	$(Q)$$(CC_$(2)) -r -nostdlib -o $$@ $$@.main.o $(BUILD)/$(2)/ev3rt/ev3sim_test_$(1)/ev3sim_test_$(1).o
endef
$(foreach c,$(HOST_CONFIGS),$(foreach a,$(EV3SIM_TEST_APPS),$(eval $(call ev3sim_test_app_rules,$(a),$(c)))))

ifneq ($(findstring $$,$(value APP)),)
$(error APP=$(value APP): make would expand its '$$'; ev3sim run APP_DIR builds any path)
endif
ifneq ($(APP),)
ifneq ($(words $(APP)),1)
$(error APP="$(APP)": make splits a path at spaces; ev3sim run APP_DIR builds any path)
endif
ifneq ($(findstring $$,$(value EV3RT_LIB_DIR))$(word 2,$(EV3RT_LIB_DIR)),)
$(error EV3RT_LIB_DIR=$(value EV3RT_LIB_DIR): make would expand or split it; ev3sim run --lib-dir takes any path)
endif
# ccache rewrites the paths of dependency files relative to CCACHE_BASEDIR
# through their real paths, which would bring the app directory's own path
# (its spaces, its ';') back into them: not for an app
export CCACHE_BASEDIR :=
EV3RT_APP_NAME ?= $(notdir $(APP))
EV3RT_RUN_KEY  ?= run_$(EV3RT_APP_NAME)
EV3RT_RUN_NAME := $(EV3RT_RUN_KEY)
# the configuration of the ev3sim that builds the app (build/CONFIG/ev3sim)
EV3RT_RUN_CONFIG ?= host
ifeq ($(filter $(EV3RT_RUN_CONFIG),$(EV3SIM_CONFIGS)),)
$(error EV3RT_RUN_CONFIG=$(EV3RT_RUN_CONFIG): ev3sim runs apps in $(EV3SIM_CONFIGS))
endif
EV3RT_RUN_DIR  := $(BUILD)/$(EV3RT_RUN_CONFIG)/ev3rt/$(EV3RT_RUN_NAME)
EV3RT_LIB_DIR ?=
# the kernel profile (ev3sim run --kernel): auto, hrp2 or hrp3
EV3RT_KERNEL ?= auto
ifeq ($(filter auto hrp2 hrp3,$(EV3RT_KERNEL)),)
$(error EV3RT_KERNEL=$(EV3RT_KERNEL): expected auto, hrp2 or hrp3)
endif
EV3RT_KERNEL_$(EV3RT_RUN_NAME) := $(EV3RT_KERNEL)
$(call ev3rt_read_app,$(APP),EV3RT_RUN,$(EV3RT_LIB_DIR),$(EV3RT_RUN_DIR)/sdk)

$(EV3RT_RUN_DIR)/runner.o: ev3sim/app_runner.c
	@mkdir -p $(@D)
	$(quiet) CC $(EV3RT_RUN_CONFIG) $<
	$(Q)$(CC_$(EV3RT_RUN_CONFIG)) $(call src_flags,$<) $(WARN) $(CFLAGS_$(EV3RT_RUN_CONFIG)) $(KERNEL_DEFS) \
		-DEV3SIM_APP_NAME='"$(EV3RT_APP_NAME)"' -c $< -o $@

# the runner is ev3sim's command line: it writes --lcd's PNG with libpng and --lcd-video's GIF
# with giflib where the ev3sim program does
EV3RT_PLATFORM_$(EV3RT_RUN_NAME)_$(EV3RT_RUN_CONFIG) := $(call EV3RT_PLATFORM,$(EV3RT_RUN_CONFIG))
$(eval $(call ev3rt_dir_app,$(EV3RT_RUN_NAME),$(EV3RT_RUN_CONFIG),$(APP),EV3RT_RUN,$(EV3RT_RUN_DIR)/runner.o))
EV3RT_LDLIBS_$(EV3RT_RUN_NAME)_$(EV3RT_RUN_CONFIG) += $(EV3SIM_LDLIBS_$(EV3RT_RUN_CONFIG))
# ev3sim run --debug (EV3RT_DEBUG=1, under a key of its own: app_build.c):
# the app and its SDK libraries at -O0, after every other flag, so that gdb
# steps through its lines and shows its variables
EV3RT_DEBUG ?= 0
ifeq ($(EV3RT_DEBUG),1)
EV3RT_APPFLAGS_$(EV3RT_RUN_NAME)_$(EV3RT_RUN_CONFIG) += -O0 -g
endif

.PHONY: ev3rt-app
ev3rt-app: $(EV3RT_RUN_DIR)/$(EV3RT_RUN_NAME)
endif

# `make ev3sim-run-check` (in make test): `ev3sim run` builds an app directory
# and runs it, ending with its summary line: examples/blink, examples/gyrosquare
# in a world file (examples/worlds/course.json) and refused a bad one, an app whose
# Makefile.inc adds a source from another directory (APPL_COBJS, APPL_DIRS,
# INCLUDES, mkfile_path) with its own ATT_MOD, one whose Makefile.inc sets
# COPTS, CDEFS, APPL_CFLAGS, SRCDIRS, LDFLAGS, APPL_LIBS, LIBS and OMIT_*
# (tests/ev3sim/apps/makeinc, an ET Robocon-style HRP3 app: INCLUDE("tecsgen.cfg")), an HRP3 app and an HRP2 app side by side
# (examples/notify, examples/dtq), an HRP3 app told only by a wait in µs in
# its source (tests/ev3sim/apps/usleep), an ET Robocon-style C++ app
# (tests/ev3sim/apps/etstyle: EV3RT 0.x's APPL_DIR under `ifdef app`, its own
# __dso_handle, ten modules' writable data, a singleton shared by nine of them,
# a duplicate and a stale ATT_MOD), an app with a main() and
# global names ev3lx uses inside (tests/ev3sim/apps/namespace); then
# tests/ev3sim/apps/misbehave crashes (status 4) and stalls (status 3), each
# reported with its source line from the runner `ev3sim run` built.
.PHONY: ev3sim-run-check
ev3sim-run-check: $(BUILD)/host/ev3sim $(LIB_host) $(EV3CFG)
	+$(Q)out=$$($(BUILD)/host/ev3sim run examples/blink --seconds 3 --click back:1500ms --quiet) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run examples/blink exited $$?"; exit 1; }; \
	summary=$$(printf '%s\n' "$$out" | tail -n 1); \
	case "$$summary" in \
	"app=blink robot=bare seconds=3 seed=1 "*" warnings=0 errors=0 bugs=0 sim_speed="*) \
		echo "ev3sim-run-check: $$summary";; \
	*) echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1;; \
	esac
	+$(Q)out=$$($(BUILD)/host/ev3sim run examples/gyrosquare --world examples/worlds/course.json --seconds 20 --quiet) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run examples/gyrosquare --world examples/worlds/course.json exited $$?"; exit 1; }; \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=gyrosquare robot=world seconds=20 seed=1 world=course .* contacts=0 .* warnings=0 errors=0 bugs=0 " || \
		{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
	echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"
	+$(Q)err=$$($(BUILD)/host/ev3sim run examples/gyrosquare --world tests/ev3sim/worlds/typo.json 2>&1 >/dev/null); status=$$?; \
	[ $$status = 2 ] && printf '%s\n' "$$err" | grep -q "^ev3sim run: --world: tests/ev3sim/worlds/typo.json: robot.whee_radius_mm: unknown key" || \
		{ echo "ev3sim-run-check: FAILED: a bad world file: status $$status: $$err"; exit 1; }; \
	echo "ev3sim-run-check: a bad world file: status 2, $$(printf '%s\n' "$$err" | head -n 1)"
	+$(Q)out=$$($(BUILD)/host/ev3sim run tests/ev3sim/apps/multisrc --outA large --seconds 2) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run tests/ev3sim/apps/multisrc exited $$?"; exit 1; }; \
	printf '%s\n' "$$out" | grep -q "NOTICE: multisrc: A turned [1-9][0-9]* degrees, 1 speed lookups" && \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=multisrc .* warnings=0 errors=0 bugs=0 " || \
		{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
	echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"
	+$(Q)out=$$($(BUILD)/host/ev3sim run tests/ev3sim/apps/makeinc --seconds 1) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run tests/ev3sim/apps/makeinc exited $$?"; exit 1; }; \
	printf '%s\n' "$$out" | grep -q "NOTICE: makeinc: gain 150, CDEFS and APPL_CFLAGS, not optimized, zlib [0-9.]*, sqrt 7, dly_tsk(250000) 250 ms" && \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=makeinc .* warnings=0 errors=0 bugs=0 " || \
		{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
	echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"
	+$(Q)out=$$($(BUILD)/host/ev3sim run tests/ev3sim/apps/usleep --seconds 1 2>&1) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run tests/ev3sim/apps/usleep exited $$?"; exit 1; }; \
	printf '%s\n' "$$out" | grep -q "NOTICE: usleep: tslp_tsk(250000) took 250 ms" && \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=usleep .* warnings=0 errors=0 bugs=0 " || \
		{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
	echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"
	+$(Q)for app in notify dtq; do \
		out=$$($(BUILD)/host/ev3sim run examples/$$app --seconds 4 --quiet) || \
			{ echo "ev3sim-run-check: FAILED: ev3sim run examples/$$app exited $$?"; exit 1; }; \
		printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=$$app .* warnings=0 errors=0 bugs=0 " || \
			{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
		echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"; \
	done
	+$(Q)out=$$($(BUILD)/host/ev3sim run tests/ev3sim/apps/etstyle --seconds 1) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run tests/ev3sim/apps/etstyle exited $$?"; exit 1; }; \
	printf '%s\n' "$$out" | grep -q "NOTICE: etstyle: 9 units stepped, sum 459, 9 registered" && \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=etstyle .* warnings=0 errors=0 bugs=0 " || \
		{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
	echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"
	+$(Q)out=$$($(BUILD)/host/ev3sim run tests/ev3sim/apps/namespace --seconds 1) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run tests/ev3sim/apps/namespace exited $$?"; exit 1; }; \
	printf '%s\n' "$$out" | grep -q "NOTICE: namespace: main() says 22" && \
	printf '%s\n' "$$out" | grep -q "NOTICE: namespace: ran 0.5 s" && \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=namespace .* warnings=0 errors=0 bugs=0 " || \
		{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
	echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"
	+$(Q)for case in "null 4 FATAL: crash: SIGSEGV" "stall 3 ev3sim run: the app stalled"; do \
		set -- $$case; what=$$1; want=$$2; shift 2; text="$$*"; \
		err=$$(EV3LX_MISBEHAVE=$$what EV3LX_STALL_MS=500 $(BUILD)/host/ev3sim run tests/ev3sim/apps/misbehave \
			--seconds 2 2>&1 >/dev/null); status=$$?; \
		if [ $$status != $$want ] || ! printf '%s\n' "$$err" | grep -q "$$text" || \
		   ! printf '%s\n' "$$err" | grep -qE "(main_task|spin_unseen) at .*app\.c:[0-9]"; then \
			echo "ev3sim-run-check: FAILED: misbehave $$what: status $$status (want $$want):"; \
			printf '%s\n' "$$err"; exit 1; \
		fi; \
		echo "ev3sim-run-check: misbehave $$what: status $$status, $$(printf '%s\n' "$$err" | grep -oE '(main_task|spin_unseen) at [^ ]*' | head -n 1)"; \
	done

TEST_SUITE_EXTRA += ev3sim-run-check

# `make ev3sim-run-check-host32` (in make test): build/host32/ev3sim builds
# an app for host32 (build/host32/ev3rt/, a 32-bit runner: ELF class 1) and
# runs it; --lcd and a world file are refused before the run with their
# reason (no 32-bit libpng or json-c), a built-in world runs.
.PHONY: ev3sim-run-check-host32
ev3sim-run-check-host32: $(BUILD)/host32/ev3sim $(LIB_host32) $(EV3CFG)
	+$(Q)err=$$($(BUILD)/host32/ev3sim run examples/blink --lcd $(BUILD)/host32/blink.png 2>&1 >/dev/null); status=$$?; \
	[ $$status = 2 ] && printf '%s\n' "$$err" | grep -q "no PNG writer (the 32-bit ev3sim links no libpng" || \
		{ echo "ev3sim-run-check-host32: FAILED: --lcd: status $$status: $$err"; exit 1; }; \
	echo "ev3sim-run-check-host32: --lcd refused: $$(printf '%s\n' "$$err" | head -n 1)"
	+$(Q)err=$$($(BUILD)/host32/ev3sim run examples/gyrosquare --world examples/worlds/course.json 2>&1 >/dev/null); status=$$?; \
	[ $$status = 2 ] && printf '%s\n' "$$err" | grep -q "no world file reader (the 32-bit ev3sim links no json-c or libpng" || \
		{ echo "ev3sim-run-check-host32: FAILED: --world FILE: status $$status: $$err"; exit 1; }; \
	echo "ev3sim-run-check-host32: --world FILE refused: $$(printf '%s\n' "$$err" | head -n 1)"
	+$(Q)out=$$($(BUILD)/host32/ev3sim run examples/gyrosquare --world arena --seconds 20 --quiet) && \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=gyrosquare robot=world seconds=20 seed=1 world=arena .* contacts=0 " || \
		{ echo "ev3sim-run-check-host32: FAILED: --world arena:"; printf '%s\n' "$$out"; exit 1; }
	+$(Q)out=$$($(BUILD)/host32/ev3sim run examples/blink --seconds 3 --click back:1500ms --quiet) || \
		{ echo "ev3sim-run-check-host32: FAILED: build/host32/ev3sim run examples/blink exited $$?"; exit 1; }; \
	summary=$$(printf '%s\n' "$$out" | tail -n 1); \
	case "$$summary" in \
	"app=blink robot=bare seconds=3 seed=1 "*" warnings=0 errors=0 bugs=0 sim_speed="*) ;; \
	*) echo "ev3sim-run-check-host32: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1;; \
	esac; \
	runner=$$(ls -t $(BUILD)/host32/ev3rt/run_blink-*/run_blink-????????????????| head -n 1); \
	[ "$$(od -An -tu1 -j4 -N1 "$$runner" | tr -d ' ')" = 1 ] || \
		{ echo "ev3sim-run-check-host32: FAILED: the runner $$runner is not a 32-bit program"; exit 1; }; \
	echo "ev3sim-run-check-host32: $$summary (32-bit runner $$runner)"
TEST_SUITE_EXTRA += ev3sim-run-check-host32

# `make adversarial-check` (in make test): bad input to ev3sim and its
# configurator and a rebuilt tree, each answered with its message and exit status
# (tests/ev3sim/adversarial_check.sh, TAP).
.PHONY: adversarial-check
adversarial-check: $(BUILD)/host/ev3sim $(LIB_host) $(EV3CFG)
	+$(Q)EV3SIM=$(abspath $(BUILD)/host/ev3sim) ROOT=$(CURDIR) WORK=$(abspath $(BUILD)/adversarial-check) \
		prove --verbose --exec sh tests/ev3sim/adversarial_check.sh
TEST_SUITE_EXTRA += adversarial-check

# `make ev3sim-gdb-check` (in make test): `ev3sim run --debug` builds an app at
# -O0 and gdb, in batch mode with the project's script
# (tools/gdb/ev3lx-tasks.py), stops in an app task and lists the app's tasks
# with their states, as docs/ev3sim.md's session does
# (tests/ev3sim/gdb_check.sh, TAP).
.PHONY: ev3sim-gdb-check
ev3sim-gdb-check: $(BUILD)/host/ev3sim $(LIB_host) $(EV3CFG)
	+$(Q)EV3SIM=$(abspath $(BUILD)/host/ev3sim) ROOT=$(CURDIR) prove --exec sh tests/ev3sim/gdb_check.sh
TEST_SUITE_EXTRA += ev3sim-gdb-check

# `make ev3sim-app-path-check` (in make test): `ev3sim run` on app directories
# whose paths make cannot hold ('$', spaces, quotes), an SDK library in such
# a directory, two directories of one name, four first runs of one app at
# once, and runners that cannot be executed (tests/ev3sim/app_paths_check.sh,
# TAP).
.PHONY: ev3sim-app-path-check
ev3sim-app-path-check: $(BUILD)/host/ev3sim $(LIB_host) $(EV3CFG)
	+$(Q)EV3SIM=$(abspath $(BUILD)/host/ev3sim) WORK=$(abspath $(BUILD)/ev3sim-app-path-check) \
		prove --exec sh tests/ev3sim/app_paths_check.sh

TEST_SUITE_EXTRA += ev3sim-app-path-check

# ev3sim's copy of examples/gyroboy (ev3sim/module.mk): the configuration as
# ev3sim_gyroboy_cfg, the app's settings and counters renamed ev3sim_gyroboy_*,
# everything else local.
EV3RT_SYMBOL_ev3sim_gyroboy := ev3sim_gyroboy_cfg
define ev3sim_gyroboy_rules
$(call ev3rt_app,ev3sim_gyroboy,$(1),examples/gyroboy/app.cfg,examples/gyroboy/app.c)

$(call EV3SIM_GYROBOY_OBJ,$(1)): $(BUILD)/$(1)/ev3rt/ev3sim_gyroboy/ev3sim_gyroboy.o
	$$(quiet) OBJCOPY $(1) $$@
	$(Q)$$(if $$(filter arm926-test,$(1)),arm-linux-gnueabi-objcopy,objcopy) \
		--redefine-sym gyroboy_params=ev3sim_gyroboy_params \
		--redefine-sym gyroboy_stats=ev3sim_gyroboy_stats \
		-G ev3sim_gyroboy_cfg -G ev3sim_gyroboy_params -G ev3sim_gyroboy_stats $$< $$@
endef
$(foreach c,$(HOST_CONFIGS),$(eval $(call ev3sim_gyroboy_rules,$(c))))

# tests/ev3sim/test_app_live runs the live view's server where the ev3sim
# program has one (host, host-san: Debian's libmicrohttpd is a 64-bit host
# library); elsewhere it checks that --live is refused.
EV3SIM_LIVE_TEST_CONFIGS := host host-san
$(foreach c,$(EV3SIM_LIVE_TEST_CONFIGS),$(eval \
	$(BUILD)/$(c)/tests/ev3sim/test_app_live.t: $(BUILD)/$(c)/obj/ev3sim/live_http.o))
$(foreach c,$(EV3SIM_LIVE_TEST_CONFIGS),$(eval \
	$(BUILD)/$(c)/tests/ev3sim/test_app_live.t: EV3SIM_LIVE_TEST_LIBS := $(BUILD)/$(c)/obj/ev3sim/live_http.o))
TEST_LDLIBS_ev3sim/test_app_live = $(EV3SIM_LIVE_TEST_LIBS)
$(foreach c,$(EV3SIM_LIVE_TEST_CONFIGS),$(BUILD)/$(c)/obj/ev3sim/live_http.o): ev3sim/live_page.html

# EV3RT-style apps beyond the configurator's rule (mk/ev3rt_app.mk):
#
#   examples/NAME/   each example app is built in every host configuration and
#                    linked into its test, tests/examples/test_NAME.c, which
#                    runs it in ev3sim's robots (ev3sim/run.h) and asserts what
#                    it does.
#   ev3rt-app        `make ev3rt-app APP=/abs/dir [EV3RT_LIB_DIR=/abs/dir]`
#                    builds the runner of any app directory,
#                    $(BUILD)/host/ev3rt/run_NAME/run_NAME: what `ev3sim run
#                    APP_DIR [--lib-dir DIR]` does before executing it.  The
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

EXAMPLES := $(patsubst examples/%/app.cfg,%,$(wildcard examples/*/app.cfg))

# $(1) = example, $(2) = config
define ev3rt_example_rules
$(call ev3rt_app,$(1),$(2),examples/$(1)/app.cfg,examples/$(1)/app.c)

$(BUILD)/$(2)/obj/tests/examples/test_$(1).o: tests/examples/test_$(1).c $(BUILD)/$(2)/ev3rt/$(1)/$(1).o
	@mkdir -p $$(@D)
	$$(quiet) CC $(2) $$<
	$(Q)$$(CC_$(2)) $$(call src_flags,$$<) $$(WARN) $$(CFLAGS_$(2)) $(KERNEL_DEFS) \
		-MMD -MP -MF $$(@:.o=.d) -MT $$@ -c $$< -o $$@.main.o
	$(Q)$$(CC_$(2)) -r -nostdlib -o $$@ $$@.main.o $(BUILD)/$(2)/ev3rt/$(1)/$(1).o
endef
$(foreach c,$(HOST_CONFIGS),$(foreach e,$(EXAMPLES),$(eval $(call ev3rt_example_rules,$(e),$(c)))))

# SDK library $(1) of app $(2) in configuration $(3): its objects compiled as
# the app's are (the app's include path, its pattern rules), in one archive.
define ev3rt_slib_rules
EV3RT_SLIB_OBJS_$(1) := $$(patsubst %,$(BUILD)/$(3)/ev3rt/$(2)/obj/%.o,$$(basename $$(EV3RT_SLIB_SRCS_$(1))))
$(BUILD)/$(3)/ev3rt/$(2)/lib/$(1).a: $$(EV3RT_SLIB_OBJS_$(1))
	@mkdir -p $$(@D)
	$$(quiet) AR $(3) $$@
	$(Q)rm -f $$@ && ar rcs $$@ $$^
-include $$(EV3RT_SLIB_OBJS_$(1):.o=.d)
endef

ifneq ($(APP),)
EV3RT_RUN_NAME := run_$(notdir $(APP))
EV3RT_RUN_DIR  := $(BUILD)/host/ev3rt/$(EV3RT_RUN_NAME)
# What EV3RT's build gives a Makefile.inc before reading it.
mkfile_path := $(APP)/
SRCLANG := c
APPL_COBJS :=
APPL_CXXOBJS :=
APPL_DIRS :=
APPL_LIBS :=
LIBS :=
INCLUDES :=
CONFIG_EV3RT_APPLICATION := 1
# SDK libraries: their Makefiles include $(EV3RT_SDK_LIB_DIR)/../Makefile.slib,
# so the libraries are seen through a directory of links in the build, beside
# ev3lx's Makefile.slib (mk/ev3rt/Makefile.slib), made before Makefile.inc is read.
EV3RT_LIB_DIR ?=
EV3RT_SDK_LIB_DIR := $(EV3RT_RUN_DIR)/sdk/library
EV3RT_SDK_LIBS :=
EV3RT_SDK_ARCHIVES :=
$(if $(shell set -e; rm -rf '$(EV3RT_RUN_DIR)/sdk'; mkdir -p '$(EV3RT_SDK_LIB_DIR)'; \
	cp mk/ev3rt/Makefile.slib '$(EV3RT_RUN_DIR)/sdk/Makefile.slib'; \
	$(if $(EV3RT_LIB_DIR),for d in '$(EV3RT_LIB_DIR)'/*/; do ln -s "$$d" '$(EV3RT_SDK_LIB_DIR)'/; done;) \
	echo ok),,$(error cannot prepare $(EV3RT_RUN_DIR)/sdk))
# the SDK libraries Makefile.inc includes, each needed in EV3RT_LIB_DIR
EV3RT_WANTED_LIBS := $(shell sed -n 's|.*$$(EV3RT_SDK_LIB_DIR)/\([^/]*\)/Makefile.*|\1|p' '$(APP)/Makefile.inc' 2>/dev/null)
$(foreach l,$(EV3RT_WANTED_LIBS),$(if $(wildcard $(EV3RT_SDK_LIB_DIR)/$(l)/Makefile),,$(error \
	$(APP)/Makefile.inc includes EV3RT SDK library '$(l)': give the directory holding $(l)/ \
	with ev3sim run APP_DIR --lib-dir DIR$(if $(EV3RT_LIB_DIR), ($(EV3RT_LIB_DIR) has no $(l)/Makefile)))))
-include $(APP)/Makefile.inc
ifeq ($(SRCLANG),c++)
EV3RT_RUN_MAIN := $(APP)/app.cpp
else
EV3RT_RUN_MAIN := $(APP)/app.c
endif
EV3RT_RUN_DIRS := $(APP) $(foreach d,$(APPL_DIRS),$(if $(filter /%,$(d)),$(d),$(APP)/$(d))) \
	$(shell find '$(APP)' -type d -name src)
# the source of object $(1) with extension $(2): the first directory that has it
ev3rt_run_src = $(firstword $(wildcard $(addsuffix /$(basename $(1))$(2),$(EV3RT_RUN_DIRS))) $(APP)/$(basename $(1))$(2))
EV3RT_RUN_SRCS := $(EV3RT_RUN_MAIN) $(foreach o,$(APPL_COBJS),$(call ev3rt_run_src,$(o),.c)) \
	$(foreach o,$(APPL_CXXOBJS),$(call ev3rt_run_src,$(o),.cpp))

$(EV3RT_RUN_DIR)/runner.o: ev3sim/app_runner.c
	@mkdir -p $(@D)
	$(quiet) CC host $<
	$(Q)$(CC_host) $(call src_flags,$<) $(WARN) $(CFLAGS_host) $(KERNEL_DEFS) \
		-DEV3SIM_APP_NAME='"$(notdir $(APP))"' -c $< -o $@

EV3RT_LIBS_$(EV3RT_RUN_NAME)_host := $(APPL_LIBS)
EV3RT_DOMLIBS_$(EV3RT_RUN_NAME)_host := $(EV3RT_SDK_ARCHIVES)
# the runner is ev3sim's command line: it writes --lcd's PNG with libpng and --lcd-video's GIF
# with giflib, as the ev3sim program does
$(eval $(call ev3rt_app,$(EV3RT_RUN_NAME),host,$(APP)/app.cfg,$(EV3RT_RUN_SRCS),$(EV3RT_RUN_DIR)/runner.o $(BUILD)/host/obj/ev3sim/lcd_png.o $(BUILD)/host/obj/ev3sim/lcd_gif.o))
EV3RT_LDLIBS_$(EV3RT_RUN_NAME)_host := -lpng -lgif $(filter-out -lc,$(LIBS))
EV3RT_INC_$(EV3RT_RUN_NAME)_host += $(INCLUDES) $(patsubst %,-I%,$(shell find '$(APP)' -type d -name include))
$(foreach l,$(EV3RT_SDK_LIBS),$(eval $(call ev3rt_slib_rules,$(l),$(EV3RT_RUN_NAME),host)))
# the objects ATT_MOD names come from Makefile.inc too
$(EV3RT_RUN_DIR)/gen/kernel_cfg.c: $(wildcard $(APP)/Makefile.inc)

.PHONY: ev3rt-app
ev3rt-app: $(EV3RT_RUN_DIR)/$(EV3RT_RUN_NAME)
endif

# `ev3sim run DIR` builds DIR's runner with a make of its own (ev3rt-app).
# Checks that run the same app (ev3sim-audio-check and ev3sim-lcd-check both
# run examples/hello, in parallel in `make test`) have that runner built
# first, once, by this target, so that two such makes never write the same
# files: theirs then find it up to date.  The directory is named as ev3sim
# names it (its real path).
.PHONY: ev3sim-runner-hello
ev3sim-runner-hello: $(BUILD)/host/ev3sim $(LIB_host) $(EV3CFG)
	+$(Q)$(MAKE) -s --no-print-directory APP=$(realpath examples/hello) ev3rt-app

# `make ev3sim-run-check` (in make test): `ev3sim run` builds an app directory
# and runs it, ending with its summary line: examples/blink, and an app whose
# Makefile.inc adds a source from another directory (APPL_COBJS, APPL_DIRS,
# INCLUDES, mkfile_path) with its own ATT_MOD.
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
	+$(Q)out=$$($(BUILD)/host/ev3sim run tests/ev3sim/apps/multisrc --outA large --seconds 2) || \
		{ echo "ev3sim-run-check: FAILED: ev3sim run tests/ev3sim/apps/multisrc exited $$?"; exit 1; }; \
	printf '%s\n' "$$out" | grep -q "NOTICE: multisrc: A turned [1-9][0-9]* degrees, 1 speed lookups" && \
	printf '%s\n' "$$out" | tail -n 1 | grep -q "^app=multisrc .* warnings=0 errors=0 bugs=0 " || \
		{ echo "ev3sim-run-check: FAILED: unexpected output:"; printf '%s\n' "$$out"; exit 1; }; \
	echo "ev3sim-run-check: $$(printf '%s\n' "$$out" | tail -n 1)"

TEST_SUITE_EXTRA += ev3sim-run-check

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

# Checks of the layering (mk/layers.mk), both in `make test`.
#
# `make layer-check`: every #include line and every link edge between the
# layers' objects follows an edge of LAYER_EDGES (mk/layer_check.sh), after
# a self-test on fake layers proves each kind of violation is caught.
#
# It reads every source and header of the layers' directories and every
# object below build/host/obj and build/am1808/obj, so it waits for all of
# those objects (the library's, the tests', the programs'): in `make test` the
# builds run in parallel with it, and a half-written object must not be read.
# Its result is kept (build/layer-check.txt) and redone only when one of these
# inputs changed: a source (their set and the layers' settings in the key),
# an object (through the library, test or program it is built into), the
# scripts or the layers' definition.
LAYER_CHECK_OUT := $(BUILD)/layer-check.txt
LAYER_CHECK_SRCS = $(sort $(shell find $(LAYERS) \( -name '*.c' -o -name '*.h' \) 2>/dev/null))
LAYER_CHECK_ENV = LAYERS='$(LAYERS)' SUBLAYERS_host_sim='$(SUBLAYERS_host_sim)' \
	$(foreach l,$(LAYERS),LAYER_EDGES_$(l)='$(LAYER_EDGES_$(l))' HDR_$(l)='$(HDR_$(l))')
LAYER_CHECK_KEY := $(BUILD)/layer-check.key
$(eval $(call key_file_rule,$(LAYER_CHECK_KEY),$$(LAYER_CHECK_ENV) $$(LAYER_CHECK_SRCS)))

.PHONY: layer-check
layer-check: $(LAYER_CHECK_OUT)
	@cat $<

$(LAYER_CHECK_OUT): $(LAYER_CHECK_KEY) $(LAYER_CHECK_SRCS) $(LIB_host) $(addprefix $(BUILD)/host/,$(HOST_PROGRAMS)) \
		$(TESTS_host) $(BUILD)/am1808/libev3lx.a mk/layer_check.sh mk/layer_check_selftest.sh \
		mk/layers.mk mk/layer_checks.mk
	@{ bash mk/layer_check_selftest.sh $(abspath $(BUILD))/layer-check-selftest && \
		$(LAYER_CHECK_ENV) bash mk/layer_check.sh $(BUILD)/host/obj $(BUILD)/am1808/obj; } > $@.tmp || \
		{ cat $@.tmp; rm -f $@.tmp; exit 1; }
	@mv $@.tmp $@
TEST_SUITE_EXTRA += layer-check

# `make header-check`: every public header of every layer
# compiles on its own, included twice (the include guard holds), with the one
# compile recipe of its configuration and its layer's include path, warnings
# as errors: on the host for all layers, with arm-none-eabi-gcc for the layers
# that go to the brick (host-only headers excepted).  The test helpers in
# tests/lib are test code, checked by the tests that use them.

HDRCHECK_LAYERS_host   := rtos_stub linux_compat ev3_drivers hacks api host_sim ev3sim
HDRCHECK_LAYERS_am1808 := rtos_stub linux_compat ev3_drivers hacks api
HDRCHECK_HOST_ONLY     := rtos_stub/include/rtos_host.h
# ev3api.h includes the app's kernel_cfg.h, which exists only in an app's
# build: it is checked as the configurator's pass sees it (TOPPERS_CFG1_OUT);
# every example's build checks it whole.
HDRCHECK_PARTS         :=
HDRCHECK_FLAGS_api/ev3api.h := -DTOPPERS_CFG1_OUT
HDRCHECK               := $(BUILD)/header-check

# "path-of-header include-name" pairs of a layer: the name relative to its header directory.
# (api/library holds SDK libraries in C++, checked by the C++ pass below)
hdrcheck_pairs = $(foreach d,$(HDR_$(1)),$(foreach h,$(filter-out $(HDRCHECK_PARTS) api/library/%,$(sort $(shell find $(d) -name '*.h' 2>/dev/null))),$(h)@$(patsubst $(d)/%,%,$(h))))
HDRCHECK_PAIRS_host   := $(foreach l,$(HDRCHECK_LAYERS_host),$(call hdrcheck_pairs,$(l)))
HDRCHECK_PAIRS_am1808 := $(filter-out $(addsuffix @%,$(HDRCHECK_HOST_ONLY)),\
	$(foreach l,$(HDRCHECK_LAYERS_am1808),$(call hdrcheck_pairs,$(l))))

# $(1) = config, $(2) = header path, $(3) = its include name
define hdrcheck_rule
$(HDRCHECK)/$(1)/$(2:.h=.o): $(2)
	@mkdir -p $$(@D)
	@printf '#include "%s"\n#include "%s"\n' '$(3)' '$(3)' > $$(@:.o=.c)
	$(Q)$$(call compile,$(1),$(2)) $(HDRCHECK_FLAGS_$(2)) -MMD -MP -c $$(@:.o=.c) -o $$@
-include $(HDRCHECK)/$(1)/$(2:.h=.d)
endef
$(foreach c,host am1808,$(foreach p,$(HDRCHECK_PAIRS_$(c)),\
	$(eval $(call hdrcheck_rule,$(c),$(word 1,$(subst @, ,$(p))),$(word 2,$(subst @, ,$(p)))))))

HDRCHECK_OBJS := $(foreach c,host am1808,$(foreach p,$(HDRCHECK_PAIRS_$(c)),$(HDRCHECK)/$(c)/$(patsubst %.h,%.o,$(word 1,$(subst @, ,$(p))))))

# The headers an app includes compile as C++ too (g++, -Wall -Wextra -Werror):
# EV3RT's apps may be C++ (app.cpp), and every one of these declares its
# functions with C linkage.
HDRCHECK_CXX_HDRS := $(filter-out api/ev3api_brick_io.h,$(wildcard api/*.h api/syssvc/*.h)) \
	$(addprefix rtos_stub/include/,kernel.h kernel_hrp3.h t_stddef.h t_syslog.h t_stdlib.h target_kernel.h ev3.h syssvc/syslog.h)
# ev3lx's SDK libraries' headers (api/library/LIB/include) are an app's
# too, included by name with the library's include/ on the path as the app's
# build puts it; they are checked as EV3RT's app build compiles C++
# (-std=gnu++11) as well.
HDRCHECK_CXX_HDRS += $(sort $(wildcard api/library/*/include/*.h))
HDRCHECK_CXX_OBJS := $(patsubst %.h,$(HDRCHECK)/cxx/%.o,$(HDRCHECK_CXX_HDRS))
$(HDRCHECK)/cxx/%.o: %.h
	@mkdir -p $(@D)
	@printf '#include "%s"\n#include "%s"\n' '$(abspath $<)' '$(abspath $<)' > $(@:.o=.cpp)
	$(Q)$(CCACHE) g++ -std=gnu++17 -Wall -Wextra -Werror -Wno-unused-parameter $(call layer_inc,api) \
		$(HDRCHECK_FLAGS_$<) -DTOPPERS_CFG1_OUT $(CFLAGS_host) $(KERNEL_DEFS) -MMD -MP -c $(@:.o=.cpp) -o $@
	$(Q)$(if $(filter api/library/%,$<),$(CCACHE) g++ -std=gnu++11 -Wall -Wextra -Werror -Wno-unused-parameter \
		$(call layer_inc,api) -I$(dir $<) -DTOPPERS_CFG1_OUT $(CFLAGS_host) $(KERNEL_DEFS) \
		-c $(@:.o=.cpp) -o $(@:.o=.gnu++11.o))
-include $(HDRCHECK_CXX_OBJS:.o=.d)

.PHONY: header-check
header-check: $(HDRCHECK_OBJS) $(HDRCHECK_CXX_OBJS)
	@echo "header-check: $(words $(HDRCHECK_PAIRS_host)) headers compile alone (twice included) on the host, $(words $(HDRCHECK_PAIRS_am1808)) for the AM1808, $(words $(HDRCHECK_CXX_HDRS)) of an app's as C++"
TEST_SUITE_EXTRA += header-check

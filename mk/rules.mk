# Rules shared by the host configurations.
#
# Components append to:
#   HOST_SRCS      sources of libev3lx.a in every host configuration
#   HOST_LIB_EXTRA_<config>  objects built otherwise that go into that library
#   TEST_SUPPORT_SRCS  sources linked into every test (tests/lib/, with its headers)
#   TEST_LDLIBS_<path>, TEST_LDLIBS_<config>_<path>  what a test (tests/<path>.c) links
#                  besides, in every configuration or in one
#   HOST_PROGRAMS  programs built in build/host/ (each NAME with NAME_SRCS)
# Tests are every tests/**/test_*.c: one TAP program each, linked against
# the library; build/<config>/tests/<path>/test_x.t mirrors the source tree.

TEST_SRCS := $(sort $(shell find tests -name 'test_*.c' 2>/dev/null))

# Test programs run in parallel, two per CPU: every test boots its own
# simulated brick in its own process and virtual time (the qemu-arm runs wait
# on the emulator's translation as much as on the CPU).
PROVE_JOBS ?= $(shell echo $$(( $(NPROC) * 2 )))
# The slowest tests start first, so that a run does not end waiting on one
# long test: prove keeps each test's time in build/<config>/.prove and orders
# the next run by it (--state=slow,save; tests added since run too, removed ones
# are dropped); a first run takes the directories of whole-robot simulations,
# the longest tests, before the others (each directory's tests as -r finds them),
# and only saves the times: prove's "slow" without a state file would say "No
# saved state, selection will be empty" (and then run every test anyway).
PROVE_FIRST := examples ev3sim
TEST_TOP_DIRS := $(sort $(foreach t,$(TEST_SRCS),$(word 2,$(subst /, ,$(t)))))
# prove's --state for state file $(1) (relative to where prove runs).
prove_state = $$(test -f $(1) && echo slow,save || echo save)
PROVE_DIRS := $(addprefix tests/,$(filter $(PROVE_FIRST),$(TEST_TOP_DIRS)) \
	$(filter-out $(PROVE_FIRST),$(TEST_TOP_DIRS)))

# The library of configuration $(1): its objects, modules and libev3lx.a.
define host_lib_rules
OBJS_$(1)      := $$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$$(HOST_SRCS))
LIB_$(1)       := $(BUILD)/$(1)/libev3lx.a

$(call obj_rule,$(1),$(BUILD)/$(1))
$(call module_link_rule,$(1),$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$(HOST_SRCS)))

$(call key_file_rule,$(BUILD)/$(1)/lib-members.key,$$(OBJS_$(1)) $$(HOST_LIB_EXTRA_$(1)))
$$(LIB_$(1)): $$(call module_objs,$$(OBJS_$(1))) $$(HOST_LIB_EXTRA_$(1)) $(BUILD)/$(1)/lib-members.key
	@mkdir -p $$(@D)
	$$(quiet) AR $(1) $$@
	$(Q)rm -f $$@
	$(Q)$$(if $$(filter arm926-test,$(1)),arm-linux-gnueabi-ar,ar) rcs $$@ $$(filter-out %.key,$$^)

-include $$(OBJS_$(1):.o=.d)
endef

# A test configuration $(1): the library, the test programs and their prove run.
define host_config_rules
$(call host_lib_rules,$(1))
SUPPORT_OBJS_$(1) := $$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$$(TEST_SUPPORT_SRCS))
TESTS_$(1)     := $$(patsubst %.c,$(BUILD)/$(1)/%.t,$$(TEST_SRCS))

$(BUILD)/$(1)/tests/%.t: $(BUILD)/$(1)/obj/tests/%.o $$(SUPPORT_OBJS_$(1)) $$(LIB_$(1))
	@mkdir -p $$(@D)
	$$(quiet) LD $(1) $$@
	$(Q)$$(CC_$(1)) $$(CFLAGS_$(1)) $$(LDFLAGS_$(1)) -o $$@ $$< $$(SUPPORT_OBJS_$(1)) \
		-Wl,--start-group $$(LIB_$(1)) -Wl,--end-group -lm $$(TEST_LDLIBS_$$*) $$(TEST_LDLIBS_$(1)_$$*)

.PHONY: tests-$(1) prove-$(1)
tests-$(1): $$(TESTS_$(1))

# prove -r runs every test program it finds: one whose source was renamed or
# removed is deleted first, or its old binary would still run (and pass).
prove-$(1): tests-$(1)
	@echo "=== prove: $(1) ==="
	$(Q)cd $(BUILD)/$(1) && printf '%s\n' $$(patsubst %.c,%.t,$$(TEST_SRCS)) | LC_ALL=C sort > .test-programs && \
		find tests -name '*.t' | LC_ALL=C sort | LC_ALL=C comm -23 - .test-programs | while read -r stale; do \
		echo "prove-$(1): $$$$stale: its source is gone, removed"; rm -f "$$$$stale"; done
	@cd $(BUILD)/$(1) && prove -j$(PROVE_JOBS) --state=$$(call prove_state,.prove) --exec '$$(RUN_$(1))' -r $(PROVE_DIRS)

-include $$(SUPPORT_OBJS_$(1):.o=.d) $$(patsubst %.c,$(BUILD)/$(1)/obj/%.d,$$(TEST_SRCS))
endef
$(foreach c,$(HOST_CONFIGS),$(eval $(call host_config_rules,$(c))))

# Program $(1) in configuration $(2): the host's, host32's (HOST32_PROGRAMS)
# and the simulator's profile-guided builds (mk/pgo.mk).  A program's sources
# and libraries in one configuration may differ: NAME_SRCS_CONFIG and
# NAME_LDLIBS_CONFIG, where defined, replace NAME_SRCS and NAME_LDLIBS.
program_var = $(if $(filter undefined,$(origin $(1)_$(2)_$(3))),$($(1)_$(2)),$($(1)_$(2)_$(3)))
define host_program_rules
$(BUILD)/$(2)/$(1): $$(patsubst %.c,$(BUILD)/$(2)/obj/%.o,$$(call program_var,$(1),SRCS,$(2))) $$(LIB_$(2))
	@mkdir -p $$(@D)
	$$(quiet) LD $(2) $$@
	$(Q)$$(CC_$(2)) $$(CFLAGS_$(2)) -o $$@ $$(patsubst %.c,$(BUILD)/$(2)/obj/%.o,$$(call program_var,$(1),SRCS,$(2))) \
		-Wl,--start-group $$(LIB_$(2)) -Wl,--end-group -lm $$(call program_var,$(1),LDLIBS,$(2))
-include $$(patsubst %.c,$(BUILD)/$(2)/obj/%.d,$$(call program_var,$(1),SRCS,$(2)))
endef
$(foreach p,$(HOST_PROGRAMS),$(eval $(call host_program_rules,$(p),host)))
$(foreach p,$(HOST32_PROGRAMS),$(eval $(call host_program_rules,$(p),host32)))

.PHONY: host-all
host-all: $(LIB_host) $(addprefix $(BUILD)/host/,$(HOST_PROGRAMS)) tests-host

# (the suite, `make test`: mk/suite.mk)
# (key_file_rule, for checks kept as stamps: mk/config.mk)

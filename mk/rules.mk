# Rules shared by the host configurations.
#
# Components append to:
#   HOST_SRCS      sources of libev3lx.a in every host configuration
#   HOST_LIB_EXTRA_<config>  objects built otherwise that go into that library
#   TEST_SUPPORT_SRCS  sources linked into every test (tests/lib/, with its headers)
#   HOST_PROGRAMS  programs built in build/host/ (each NAME with NAME_SRCS)
# Tests are every tests/**/test_*.c: one TAP program each, linked against
# the library; build/<config>/tests/<path>/test_x.t mirrors the source tree.

TEST_SRCS := $(sort $(shell find tests -name 'test_*.c' 2>/dev/null))

# Test programs run in parallel, two per CPU: every test boots its own
# simulated brick in its own process and virtual time (the qemu-arm runs wait
# on the emulator's translation as much as on the CPU).
PROVE_JOBS ?= $(shell echo $$(( $(NPROC) * 2 )))

# $(1) = config
define host_config_rules
OBJS_$(1)      := $$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$$(HOST_SRCS))
SUPPORT_OBJS_$(1) := $$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$$(TEST_SUPPORT_SRCS))
LIB_$(1)       := $(BUILD)/$(1)/libev3lx.a
TESTS_$(1)     := $$(patsubst %.c,$(BUILD)/$(1)/%.t,$$(TEST_SRCS))

$(call obj_rule,$(1),$(BUILD)/$(1))
$(call module_link_rule,$(1),$(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$(HOST_SRCS)))

$$(LIB_$(1)): $$(call module_objs,$$(OBJS_$(1))) $$(HOST_LIB_EXTRA_$(1))
	@mkdir -p $$(@D)
	$$(quiet) AR $(1) $$@
	$(Q)rm -f $$@
	$(Q)$$(if $$(filter arm926-test,$(1)),arm-linux-gnueabi-ar,ar) rcs $$@ $$^

$(BUILD)/$(1)/tests/%.t: $(BUILD)/$(1)/obj/tests/%.o $$(SUPPORT_OBJS_$(1)) $$(LIB_$(1))
	@mkdir -p $$(@D)
	$$(quiet) LD $(1) $$@
	$(Q)$$(CC_$(1)) $$(CFLAGS_$(1)) $$(LDFLAGS_$(1)) -o $$@ $$< $$(SUPPORT_OBJS_$(1)) \
		-Wl,--start-group $$(LIB_$(1)) -Wl,--end-group -lm

.PHONY: tests-$(1) prove-$(1)
tests-$(1): $$(TESTS_$(1))

prove-$(1): tests-$(1)
	@echo "=== prove: $(1) ==="
	@cd $(BUILD)/$(1) && prove -j$(PROVE_JOBS) --exec '$$(RUN_$(1))' -r tests

-include $$(OBJS_$(1):.o=.d) $$(SUPPORT_OBJS_$(1):.o=.d) $$(patsubst %.c,$(BUILD)/$(1)/obj/%.d,$$(TEST_SRCS))
endef
$(foreach c,$(HOST_CONFIGS),$(eval $(call host_config_rules,$(c))))

# Programs (host configuration only).
define host_program_rules
$(BUILD)/host/$(1): $$(patsubst %.c,$(BUILD)/host/obj/%.o,$$($(1)_SRCS)) $$(LIB_host)
	@mkdir -p $$(@D)
	$$(quiet) LD host $$@
	$(Q)$$(CC_host) $$(CFLAGS_host) -o $$@ $$(patsubst %.c,$(BUILD)/host/obj/%.o,$$($(1)_SRCS)) \
		-Wl,--start-group $$(LIB_host) -Wl,--end-group -lm $$($(1)_LDLIBS)
-include $$(patsubst %.c,$(BUILD)/host/obj/%.d,$$($(1)_SRCS))
endef
$(foreach p,$(HOST_PROGRAMS),$(eval $(call host_program_rules,$(p))))

.PHONY: host-all test-suite
host-all: $(LIB_host) $(addprefix $(BUILD)/host/,$(HOST_PROGRAMS)) tests-host

# The suite: three prove runs; any failure fails the whole target, but every run is shown.
test-suite: $(foreach c,$(HOST_CONFIGS),tests-$(c)) $(TEST_SUITE_EXTRA_DEPS)
	@status=0; \
	for c in $(HOST_CONFIGS); do \
		$(MAKE) --no-print-directory prove-$$c || status=1; \
	done; \
	for t in $(TEST_SUITE_EXTRA); do \
		$(MAKE) --no-print-directory $$t || status=1; \
	done; \
	if [ $$status = 0 ]; then echo "=== make test: all runs passed ==="; \
	else echo "=== make test: FAILED ==="; fi; \
	exit $$status

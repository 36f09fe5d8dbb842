# Checks of how Linux code is built (mk/config.mk: nostdinc_flags, module_objs).
#
# `make nostdinc-check`: in every configuration a module's driver unit (the
# hack file) sees only Linux's namespace — a C library header, a Linux header
# linux_compat lacks (the host's /usr/include/linux has it), and the kernel's
# own headers (kernel.h, t_stddef.h, sil.h, t_syslog.h, rtos_cfg.h; with
# HRP2_DIR also its chip header am1808.h) fail to compile, as under kbuild.
# `make module-check`: the modules' private namespaces (mk/module_check.sh) in
# every configuration's library, and the users' modules linked together.

NOSTDINC_PROBES := linux/videodev2.h stdio.h stdlib.h string.h sys/types.h stdint.h limits.h \
	kernel.h t_stddef.h sil.h t_syslog.h rtos_cfg.h am1808.h
NOSTDINC_PROBE_SRC := hacks/nostdinc_probe_hack.c
NOSTDINC_CONFIGS := host host32 arm926-test am1808
# The AM1808 build is freestanding (-ffreestanding), where the compiler's own
# <stdint.h> stands alone: it is the compiler's, allowed as under kbuild.
nostdinc_probes = $(if $(filter am1808,$(1)),$(filter-out stdint.h,$(NOSTDINC_PROBES)),$(NOSTDINC_PROBES))

.PHONY: nostdinc-check module-check
nostdinc-check:
	@mkdir -p $(BUILD)
	@fail=0; $(foreach c,$(NOSTDINC_CONFIGS),for h in $(call nostdinc_probes,$(c)); do \
		if printf '#include <%s>\n' "$$h" | $(call compile,$(c),$(NOSTDINC_PROBE_SRC)) -x c -c - -o /dev/null \
			> $(BUILD)/nostdinc-probe.err 2>&1; then \
			echo "nostdinc-check: a module in configuration $(c) compiles with <$$h>"; fail=1; \
		elif ! grep -q "No such file\|no include path" $(BUILD)/nostdinc-probe.err; then \
			cat $(BUILD)/nostdinc-probe.err; echo "nostdinc-check: <$$h> in $(c) failed otherwise"; fail=1; \
		fi; done;) \
	[ $$fail = 0 ] && echo "nostdinc-check: in $(words $(NOSTDINC_CONFIGS)) configurations a driver unit cannot reach a C library, host kernel or RTOS kernel header ($(NOSTDINC_PROBES))"; \
	exit $$fail

MODULE_CHECK_LIBS := $(foreach c,$(HOST_CONFIGS),$(LIB_$(c))) $(AM1808_LIB)
module-check: $(MODULE_CHECK_LIBS) $(foreach c,$(HOST_CONFIGS) am1808,$(LEGACY_OBJS_$(c)))
	@$(foreach c,$(HOST_CONFIGS),bash mk/module_check.sh nm '$(LD_$(c))' $(LIB_$(c)) $(BUILD)/$(c)/module-check $(LEGACY_OBJS_$(c)) &&) \
		bash mk/module_check.sh arm-none-eabi-nm $(LD_am1808) $(AM1808_LIB) $(AM1808)/module-check $(LEGACY_OBJS_am1808)

TEST_SUITE_EXTRA += nostdinc-check module-check

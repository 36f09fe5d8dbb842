# `make kbuild-check`: build ev3_drivers/ as genuine out-of-tree Linux modules against
# Debian's linux-headers with W=1 and sparse (C=2); any warning fails.  The sources are
# copied byte-for-byte into build/kbuild/ so that kbuild's objects stay out of the tree.

KDIR ?= $(firstword $(wildcard /usr/src/linux-headers-*-amd64))
KBUILD_OUT := $(BUILD)/kbuild
KBUILD_DRIVERS := $(wildcard ev3_drivers/d_*.c)

.PHONY: kbuild-check
kbuild-check: deps-check
	@test -n "$(KDIR)" || { echo "kbuild-check: no linux-headers-*-amd64 in /usr/src (make deps)"; exit 1; }
	@rm -rf $(KBUILD_OUT) && mkdir -p $(KBUILD_OUT)
	@test -n "$(KBUILD_DRIVERS)" || { echo "kbuild-check: no drivers in ev3_drivers/"; exit 1; }
	@cp -p $(wildcard ev3_drivers/*.c ev3_drivers/*.h) ev3_drivers/Kbuild $(KBUILD_OUT)/
	@sed -i 's/^obj-m := .*/obj-m := $(patsubst ev3_drivers/%.c,%.o,$(KBUILD_DRIVERS))/' $(KBUILD_OUT)/Kbuild
	@echo "kbuild-check: $(notdir $(KBUILD_DRIVERS)) against $(KDIR) (W=1 C=2)"
	@$(MAKE) --no-print-directory -C $(KDIR) M=$(abspath $(KBUILD_OUT)) W=1 C=2 modules \
		> $(KBUILD_OUT)/build.log 2>&1; status=$$?; \
	warnings=$$(grep -E 'warning:|error:|sparse:' $(KBUILD_OUT)/build.log | grep -v 'Skipping BTF' || true); \
	if [ $$status != 0 ] || [ -n "$$warnings" ]; then \
		cat $(KBUILD_OUT)/build.log; echo "kbuild-check: FAILED"; exit 1; fi; \
	ls $(KBUILD_OUT)/*.ko | sed 's/^/kbuild-check: built /'; echo "kbuild-check: clean (no warnings)"

# `make verbatim-check`: ev3_drivers/ holds genuine Linux only — no RTOS, simulator or
# hack identifiers, and no #ifdef for them (the hack files adapt the drivers instead).
VERBATIM_FORBIDDEN := TOPPERS|sil_[a-z]|host_sim|rtos|ER_UINT|cal_svc|prb_mem|EV3LX|__HOST__|\blx_[a-z]|_hack|kernel\.h"|t_stddef

.PHONY: verbatim-check
verbatim-check:
	@hits=$$(grep -nE '$(VERBATIM_FORBIDDEN)' ev3_drivers/*.[ch] ev3_drivers/Kbuild || true); \
	if [ -n "$$hits" ]; then echo "$$hits"; \
		echo "verbatim-check: ev3_drivers/ mentions the RTOS, the simulator or the hacks"; exit 1; fi; \
	echo "verbatim-check: $(words $(wildcard ev3_drivers/*.[ch])) files in ev3_drivers/ are RTOS- and simulator-free"

TEST_SUITE_EXTRA += verbatim-check kbuild-check

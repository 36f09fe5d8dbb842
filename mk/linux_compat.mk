# linux_compat checks beyond the tests (in `make test`; linux_compat's headers
# are checked by `make header-check`, mk/header_check.mk):
#
# `make scratch-kbuild-check`: the scratch driver written against Linux headers
#   only (tests/linux_compat/scratch/scratch_drv.c, which tests run on ev3lx)
#   builds unchanged as an out-of-tree module against Debian's 6.1
#   linux-headers with W=1 and sparse (C=2), without a warning (as kbuild-check).

SCRATCH_DIR        := tests/linux_compat/scratch
SCRATCH_KBUILD_OUT := $(BUILD)/kbuild-scratch

SCRATCH_KBUILD_SRCS := $(SCRATCH_DIR)/scratch_drv.c $(SCRATCH_DIR)/scratch_uapi.h

# Kept as a stamp, as kbuild-check's (mk/kbuild.mk): remade when an input changed.
SCRATCH_KBUILD_KEY := $(BUILD)/kbuild-scratch.key
$(eval $(call key_file_rule,$(SCRATCH_KBUILD_KEY),$$(KBUILD_TOOLS_KEY)))

.PHONY: scratch-kbuild-check
scratch-kbuild-check: deps-check $(SCRATCH_KBUILD_OUT)/summary.txt
	@cat $(SCRATCH_KBUILD_OUT)/summary.txt

$(SCRATCH_KBUILD_OUT)/summary.txt: $(SCRATCH_KBUILD_KEY) $(SCRATCH_KBUILD_SRCS) mk/linux_compat.mk \
		$(kbuild_kdir_files) | deps-check
	@test -n "$(KDIR)" || { echo "scratch-kbuild-check: no linux-headers-*-amd64 in /usr/src (make deps)"; exit 1; }
	@rm -rf $(SCRATCH_KBUILD_OUT) && mkdir -p $(SCRATCH_KBUILD_OUT)
	@cp -p $(SCRATCH_KBUILD_SRCS) $(SCRATCH_KBUILD_OUT)/
	@echo 'obj-m := scratch_drv.o' > $(SCRATCH_KBUILD_OUT)/Kbuild
	@echo "scratch-kbuild-check: scratch_drv.c against $(KDIR) (W=1 C=2)" > $@.tmp
	@$(MAKE) --no-print-directory -C $(KDIR) M=$(abspath $(SCRATCH_KBUILD_OUT)) W=1 C=2 modules \
		> $(SCRATCH_KBUILD_OUT)/build.log 2>&1; status=$$?; \
	warnings=$$(grep -E 'warning:|error:|sparse:' $(SCRATCH_KBUILD_OUT)/build.log | grep -v 'Skipping BTF' || true); \
	if [ $$status != 0 ] || [ -n "$$warnings" ]; then \
		cat $@.tmp $(SCRATCH_KBUILD_OUT)/build.log; echo "scratch-kbuild-check: FAILED"; exit 1; fi; \
	echo "scratch-kbuild-check: built $(SCRATCH_KBUILD_OUT)/scratch_drv.ko, clean (no warnings)" >> $@.tmp
	@mv $@.tmp $@

TEST_SUITE_EXTRA += scratch-kbuild-check

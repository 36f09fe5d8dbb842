# linux_compat checks beyond the tests (both are in `make test`):
#
# `make linux-headers-check`: every header under linux_compat/include, in a
#   generated translation unit that includes it twice (include guard), compiles
#   on its own with host gcc and with arm-none-eabi-gcc, warnings as errors.
# `make scratch-kbuild-check`: the scratch driver written against Linux headers
#   only (tests/linux_compat/scratch/scratch_drv.c, which tests run on ev3lx)
#   builds unchanged as an out-of-tree module against Debian's 6.1
#   linux-headers with W=1 and sparse (C=2), without a warning (as kbuild-check).

LXH_DIRS     := linux_compat/include linux_compat/mach-davinci/include
LXH_HEADERS  := $(sort $(foreach d,$(LXH_DIRS),$(patsubst $(d)/%,%,$(shell find $(d) -name '*.h' 2>/dev/null))))
LXH_OUT      := $(BUILD)/linux-headers-check
LXH_OBJS     := $(foreach h,$(LXH_HEADERS),$(LXH_OUT)/host/$(h:.h=.o) $(LXH_OUT)/am1808/$(h:.h=.o))

$(LXH_OUT)/src/%.c:
	@mkdir -p $(@D)
	@printf '#include <%s>\n#include <%s>\n' '$*.h' '$*.h' > $@

$(LXH_OUT)/host/%.o: $(LXH_OUT)/src/%.c
	@mkdir -p $(@D)
	@$(CC_host) -std=gnu11 $(LINUX_INC) $(COMMON_INC) $(WARN) $(CFLAGS_host) $(KERNEL_DEFS) -MMD -MP -c $< -o $@

$(LXH_OUT)/am1808/%.o: $(LXH_OUT)/src/%.c
	@mkdir -p $(@D)
	@$(CC_am1808) -std=gnu11 $(LINUX_INC) $(COMMON_INC) $(WARN) $(CFLAGS_am1808) $(KERNEL_DEFS) -MMD -MP -c $< -o $@
-include $(LXH_OBJS:.o=.d)

.PRECIOUS: $(LXH_OUT)/src/%.c
.PHONY: linux-headers-check
linux-headers-check: $(LXH_OBJS)
	@echo "linux-headers-check: $(words $(LXH_HEADERS)) headers compile alone (twice included) for host and AM1808"

SCRATCH_DIR        := tests/linux_compat/scratch
SCRATCH_KBUILD_OUT := $(BUILD)/kbuild-scratch

.PHONY: scratch-kbuild-check
scratch-kbuild-check: deps-check
	@test -n "$(KDIR)" || { echo "scratch-kbuild-check: no linux-headers-*-amd64 in /usr/src (make deps)"; exit 1; }
	@rm -rf $(SCRATCH_KBUILD_OUT) && mkdir -p $(SCRATCH_KBUILD_OUT)
	@cp -p $(SCRATCH_DIR)/scratch_drv.c $(SCRATCH_DIR)/scratch_uapi.h $(SCRATCH_KBUILD_OUT)/
	@echo 'obj-m := scratch_drv.o' > $(SCRATCH_KBUILD_OUT)/Kbuild
	@echo "scratch-kbuild-check: scratch_drv.c against $(KDIR) (W=1 C=2)"
	@$(MAKE) --no-print-directory -C $(KDIR) M=$(abspath $(SCRATCH_KBUILD_OUT)) W=1 C=2 modules \
		> $(SCRATCH_KBUILD_OUT)/build.log 2>&1; status=$$?; \
	warnings=$$(grep -E 'warning:|error:|sparse:' $(SCRATCH_KBUILD_OUT)/build.log | grep -v 'Skipping BTF' || true); \
	if [ $$status != 0 ] || [ -n "$$warnings" ]; then \
		cat $(SCRATCH_KBUILD_OUT)/build.log; echo "scratch-kbuild-check: FAILED"; exit 1; fi; \
	echo "scratch-kbuild-check: built $(SCRATCH_KBUILD_OUT)/scratch_drv.ko, clean (no warnings)"

TEST_SUITE_EXTRA += linux-headers-check scratch-kbuild-check

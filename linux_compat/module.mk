# linux_compat: the Linux kernel API over rtos_stub.
#   include/linux, include/asm, include/asm-generic   headers at Linux paths
#   include/linux_compat/   linux_compat's own interfaces (context, config, report)
#   src/*.c                 both targets;  src/host/*.c, src/am1808/*.c   one target only
#   mach-davinci/           the DaVinci (AM1808) machine: include/mach/, GPIO banks, IRQ lines
HOST_SRCS   += $(sort $(wildcard linux_compat/src/*.c linux_compat/src/host/*.c linux_compat/mach-davinci/*.c))
AM1808_SRCS += $(sort $(wildcard linux_compat/src/*.c linux_compat/src/am1808/*.c linux_compat/mach-davinci/*.c))

# Every linux_compat header must compile on its own (host and AM1808).
LX_HEADERS := $(sort $(shell find linux_compat/include linux_compat/mach-davinci/include -name '*.h' 2>/dev/null))
LX_HDRCHECK_host   := $(patsubst %.h,$(BUILD)/host/hdrcheck/%.o,$(LX_HEADERS))
LX_HDRCHECK_am1808 := $(patsubst %.h,$(BUILD)/am1808/hdrcheck/%.o,$(LX_HEADERS))

$(BUILD)/host/hdrcheck/linux_compat/%.o: linux_compat/%.h
	@mkdir -p $(@D)
	$(CC_host) -std=gnu11 $(LINUX_INC) $(COMMON_INC) $(WARN) $(CFLAGS_host) $(KERNEL_DEFS) -x c -c $< -o $@

$(BUILD)/am1808/hdrcheck/linux_compat/%.o: linux_compat/%.h
	@mkdir -p $(@D)
	$(CC_am1808) -std=gnu11 $(LINUX_INC) $(COMMON_INC) $(WARN) $(CFLAGS_am1808) $(KERNEL_DEFS) -x c -c $< -o $@

.PHONY: linux-compat-hdrcheck
linux-compat-hdrcheck: $(LX_HDRCHECK_host) $(LX_HDRCHECK_am1808)
am1808: $(LX_HDRCHECK_am1808)
host-all: $(LX_HDRCHECK_host)
TEST_SUITE_EXTRA_DEPS += linux-compat-hdrcheck

# The AM1808 target: libev3lx.a built with arm-none-eabi-gcc for the ARM926EJ-S.
# Components append target sources to AM1808_SRCS (host-only code stays out).

CC_am1808     := arm-none-eabi-gcc
AR_am1808     := arm-none-eabi-ar
CFLAGS_am1808 := -mcpu=arm926ej-s -marm -Os -ffreestanding -ffunction-sections \
	-fdata-sections -DEV3LX_AM1808=1
AM1808_OBJS   := $(patsubst %.c,$(BUILD)/am1808/obj/%.o,$(AM1808_SRCS))
AM1808_LIB    := $(BUILD)/am1808/libev3lx.a
# Every rtos_stub header must compile alone for the target.
AM1808_HDR_CHECKS := $(patsubst %.h,$(BUILD)/am1808/hdrcheck/%.o,$(wildcard rtos_stub/include/*.h))
AM1808_HDR_CHECKS := $(filter-out %/rtos_host.o,$(AM1808_HDR_CHECKS))

$(BUILD)/am1808/obj/%.o: %.c
	@mkdir -p $(@D)
	$(CC_am1808) $(call src_flags,$<) $(WARN) $(CFLAGS_am1808) $(KERNEL_DEFS) -MMD -MP -c $< -o $@

$(BUILD)/am1808/hdrcheck/%.o: %.h
	@mkdir -p $(@D)
	$(CC_am1808) -std=c11 $(COMMON_INC) $(WARN) $(CFLAGS_am1808) $(KERNEL_DEFS) -x c -c $< -o $@

$(AM1808_LIB): $(AM1808_OBJS)
	@mkdir -p $(@D)
	rm -f $@
	$(AR_am1808) rcs $@ $^

.PHONY: am1808
am1808: $(AM1808_HDR_CHECKS) $(AM1808_LIB)
	@echo "am1808: $(AM1808_LIB) ($(words $(AM1808_OBJS)) objects)"

-include $(AM1808_OBJS:.o=.d)

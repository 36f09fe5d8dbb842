# The AM1808 target: libev3lx.a built with arm-none-eabi-gcc for the
# ARM926EJ-S, a link-check firmware image against the HRP2 service calls, a
# U-Boot uImage, and a size report.  Components append target sources to
# AM1808_SRCS (host-only code stays out).

CC_am1808     := $(CCACHE) arm-none-eabi-gcc
AR_am1808     := arm-none-eabi-ar
# The production library: linux_compat's debugging checks off, as a Linux
# kernel without CONFIG_DEBUG_ATOMIC_SLEEP / CONFIG_DEBUG_SPINLOCK
# (linux_compat/include/linux_compat/debug.h; the host configurations keep them).
LX_DEBUG_OFF  := -DLX_DEBUG_ATOMIC_SLEEP=0 -DLX_DEBUG_SPINLOCK=0
CFLAGS_am1808 := -mcpu=arm926ej-s -marm -Os -g $(DEBUG_PREFIX_MAP) -ffreestanding \
	-fno-merge-constants -fno-reorder-functions -DEV3LX_AM1808=1 -DEV3LX_MEM_SECTIONS=1 $(LX_DEBUG_OFF)
AM1808        := $(BUILD)/am1808

# Against a real kernel: make am1808 HRP2_DIR=<an HRP2 tree> compiles every
# library file with that kernel's headers and settings in place of rtos_stub's
# (its kernel.h, t_stddef.h, sil.h, t_syslog.h, syssvc/syslog.h, the AM1808
# chip and EV3 target headers with their tick and kernel limits): the kernel's
# directories come first as system headers, rtos_stub/include only after them
# for what the kernel lacks (rtos_cfg.h), the compiler's include-fixed gives
# limits.h under -nostdinc (HRP2's tool_stddef.h needs it), and no tick or
# kernel limit of ev3lx's own is defined.  Kernel-domain code keeps
# TOPPERS_SVC_CALL, the API its user-domain traps.  The IDs and object counts
# are the firmware configurator's: EV3LX_CFG_DIR=<the directory of its
# kernel_cfg.h> (without it, ev3cfg --library's from cfg/ev3lx.cfg, with
# rtos_cfg.h's counts: a compile check only).  The library goes to
# build/am1808-hrp2/; the link-check image is rtos_stub's (make am1808).
ifneq ($(HRP2_DIR),)
ifeq ($(wildcard $(HRP2_DIR)/include/kernel.h),)
$(error HRP2_DIR=$(HRP2_DIR): no include/kernel.h there; give the root of an HRP2 source tree)
endif
ifeq ($(wildcard $(HRP2_DIR)/arch/arm_gcc/am1808/am1808.h),)
$(error HRP2_DIR=$(HRP2_DIR): no arch/arm_gcc/am1808/am1808.h there; the tree must have the AM1808 chip (EV3RT's HRP2))
endif
AM1808        := $(BUILD)/am1808-hrp2
HRP2_TARGET   ?= ev3_gcc
HRP2_INC      := $(addprefix -isystem $(HRP2_DIR)/,include arch . target/$(HRP2_TARGET) \
	arch/arm_gcc/am1808 arch/arm_gcc/common arch/gcc) \
	-isystem $(shell arm-none-eabi-gcc -print-file-name=include-fixed)
KERNEL_DEFS   := -DEV3LX_FNCD_BASE=$(EV3LX_FNCD_BASE) '-DINTPRI_TICK=($(INTPRI_TICK))' -D__TARGET_ARCH_ARM=5 \
	-DEV3LX_HRP2_KERNEL=1
compile_adjust_am1808 = $(subst -Irtos_stub/include,$(HRP2_INC) -idirafter rtos_stub/include,$(1))
endif
AM1808_OBJS   := $(patsubst %.c,$(AM1808)/obj/%.o,$(AM1808_SRCS))
AM1808_LIB    := $(AM1808)/libev3lx.a
FW_OBJS := $(AM1808)/startup.o $(AM1808)/fw_main.o $(AM1808)/hrp2_link_provider.o \
	$(AM1808)/newlib_glue.o $(AM1808)/fw_api_roots.o
# Reproducible image: the time stamp is the last commit's (or 0 outside git).
SOURCE_DATE_EPOCH ?= $(shell git log -1 --format=%ct 2>/dev/null || echo 0)

$(eval $(call obj_rule,am1808,$(AM1808)))
$(eval $(call module_link_rule,am1808,$(AM1808_OBJS)))

# The member list is a key: a source taken out of the library rebuilds it
# (the archive is made anew), or its old object would stay in.
$(eval $(call key_file_rule,$(AM1808)/lib-members.key,$(AM1808_OBJS)))
$(AM1808_LIB): $(call module_objs,$(AM1808_OBJS)) $(AM1808)/lib-members.key
	@mkdir -p $(@D)
	$(quiet) AR am1808 $@
	$(Q)rm -f $@
	$(Q)$(AR_am1808) rcs $@ $(filter %.o,$^)

$(AM1808)/startup.o: am1808/startup.S
	@mkdir -p $(@D)
	$(CC_am1808) -mcpu=arm926ej-s -marm -c $< -o $@

# The whole EV3 API the library defines, rooted (am1808/api_roots.sh): the image
# is what an application calling all of it keeps after --gc-sections.
AM1808_API_OBJS = $(filter $(AM1808)/obj/api/%,$(AM1808_OBJS))
$(AM1808)/fw_api_roots.c: am1808/api_roots.sh $(AM1808_API_OBJS) $(wildcard api/*.h)
	@mkdir -p $(@D)
	$(quiet) GEN am1808 $@
	$(Q)API_OBJS="$(AM1808_API_OBJS)" bash am1808/api_roots.sh $(call compile,am1808,am1808/fw_main.c) > $@.tmp
	$(Q)mv $@.tmp $@

$(AM1808)/fw_api_roots.o: $(AM1808)/fw_api_roots.c
	$(quiet) CC am1808 $<
	$(Q)$(call compile,am1808,am1808/fw_main.c) -Wno-cast-function-type -c $< -o $@

$(AM1808)/%.o: am1808/%.c
	@mkdir -p $(@D)
	$(quiet) CC am1808 $<
	$(Q)$(call compile,am1808,$<) -MMD -MP -c $< -o $@

# The firmware image: startup, the library's KEEP'd tables and what fw_main reaches.
$(AM1808)/ev3lx.elf: $(FW_OBJS) $(AM1808_LIB) am1808/ev3lx.ld
	$(CC_am1808) -mcpu=arm926ej-s -marm -nostartfiles -T am1808/ev3lx.ld -specs=nano.specs \
		-Wl,--gc-sections -Wl,-Map,$(AM1808)/ev3lx.map -o $@ $(FW_OBJS) \
		-Wl,--start-group $(AM1808_LIB) -lc_nano -lgcc -Wl,--end-group

$(AM1808)/ev3lx.bin: $(AM1808)/ev3lx.elf
	arm-none-eabi-objcopy -O binary $< $@

$(AM1808)/uImage: $(AM1808)/ev3lx.bin
	SOURCE_DATE_EPOCH=$(SOURCE_DATE_EPOCH) mkimage -A arm -O linux -T kernel -C none \
		-a 0xC0008000 -e 0xC0008000 -n "ev3lx" -d $< $@ > /dev/null

.PHONY: am1808 am1808-link-check am1808-section-check am1808-uimage-check size
ifeq ($(HRP2_DIR),)
am1808: deps-check $(AM1808_LIB) $(AM1808)/uImage
	@echo "am1808: $(AM1808_LIB) ($(words $(AM1808_OBJS)) objects), $(AM1808)/uImage"
else
am1808: deps-check $(AM1808_LIB)
	@echo "am1808: $(AM1808_LIB) ($(words $(AM1808_OBJS)) objects) against the kernel headers of $(HRP2_DIR)"
endif

am1808-link-check: $(FW_OBJS) $(AM1808_LIB)
	@bash am1808/check_link.sh $(AM1808)

# Every allocated section of the library is one an HRP2 firmware's memory
# configuration places (am1808/check_sections.sh): no orphans.
am1808-section-check: $(AM1808_LIB)
	@bash am1808/check_sections.sh $(AM1808_LIB)

am1808-uimage-check: $(AM1808)/uImage
	@mkimage -l $< > $(AM1808)/uImage.txt; \
	grep -q 'Image Type:.*ARM Linux Kernel Image (uncompressed)' $(AM1808)/uImage.txt && \
	grep -q 'Load Address: c0008000' $(AM1808)/uImage.txt && \
	grep -q 'Entry Point:  *c0008000' $(AM1808)/uImage.txt || \
	{ cat $(AM1808)/uImage.txt; echo "uimage-check: FAILED"; exit 1; }; \
	echo "uimage-check: $< is an ARM image loading and starting at 0xC0008000"

size: $(AM1808_LIB) $(AM1808)/ev3lx.elf
	@bash am1808/size_report.sh $(AM1808) | tee $(AM1808)/size.md

TEST_SUITE_EXTRA += am1808-link-check am1808-section-check am1808-uimage-check
TEST_SUITE_EXTRA_DEPS += $(AM1808_LIB) $(FW_OBJS)

-include $(AM1808_OBJS:.o=.d)

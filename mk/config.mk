# Build configurations.
#   host        — the host backend, native gcc
#   host-san    — the same under ASan + UBSan
#   host32      — the host backend built -m32 (gcc-multilib): the target's 32-bit
#                 `unsigned long` and pointers, natively, with x86's trap
#   arm926-test — the host backend cross-built for ARMv5 Linux, run under qemu-arm
#   am1808      — the target library (arm-none-eabi, freestanding), see mk/am1808.mk

HOST_CONFIGS := host host-san host32 arm926-test

WARN := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
	-Wpointer-arith -Wundef -Wno-unused-parameter

# Directories whose code is written against the Linux kernel API: they see
# linux_compat/include and use gnu11 (typeof, statement expressions).
LINUX_DIRS := linux_compat hacks ev3_drivers tests/linux_compat tests/hacks tests/ev3_drivers tests/legacy bench/timers

# Layers and their include directories.
include mk/layers.mk

# Linux code is held to kbuild W=1: -Wextra without -Wmissing-field-initializers
# (LEGO fills struct miscdevice positionally: { minor, name, fops }).
LINUX_INC  := -D__KERNEL__ -Wno-missing-field-initializers -Ilinux_compat/include -Ilinux_compat/mach-davinci/include
# Code generation as kbuild sets it for every kernel object, in every
# configuration — the list from Linux 6.1's top-level Makefile (Debian's
# linux-headers-6.1 package: KBUILD_CFLAGS), plus -funsigned-char, which
# kbuild passes on every architecture since Linux 6.2 ("kbuild: treat char as
# always unsigned"; ARM's ABI makes char unsigned anyway): drivers may
# type-pun through pointers, rely on wrapping signed arithmetic, keep null
# checks after a dereference, compare `char` command bytes above 127 as
# unsigned, and must not get stores the source does not contain (another
# context may own the neighbouring field).  -fno-common: a tentative definition
# is a definition, so two modules' `int Hw;` are two symbols the module link
# keeps apart, never one merged common block.  Left out of 6.1's list:
# -fshort-wchar (these objects link with the C library's 4-byte wchar_t; no
# Linux code here uses wchar_t), -fno-PIE (the host programs are PIE), the
# configuration-dependent -fstack-protector* and the architecture's own
# (-mcmodel=kernel, -mno-red-zone: kernel-mode x86 code).
LINUX_CODEGEN := -funsigned-char -fno-strict-aliasing -fno-common -fno-delete-null-pointer-checks \
	-fno-strict-overflow -fno-allow-store-data-races -fno-stack-check -fconserve-stack \
	-fno-builtin-wcslen

# Build-time kernel settings (TIC_NUME/TIC_DENO: tick length in ms; TNUM_FNCD:
# the highest extended service call function code, for the library and every
# configuration alike).
TIC_NUME ?= 1
TIC_DENO ?= 5
TNUM_FNCD ?= 256
# EV3LX_FNCD_BASE: the library's first function code (hacks/hack_interface.h);
# its modules take EV3LX_FNCD_BASE .. EV3LX_FNCD_BASE + 126 (the hacks,
# then the brick I/O service).
EV3LX_FNCD_BASE ?= 64
# INTPRI_TICK: the tick's interrupt priority, which every Linux line shares
# (EV3RT's INTPRI_TIMER, -28, by default).
INTPRI_TICK ?= -28
KERNEL_DEFS := -DTIC_NUME=$(TIC_NUME)U -DTIC_DENO=$(TIC_DENO)U -DTNUM_FNCD=$(TNUM_FNCD) \
	-DEV3LX_FNCD_BASE=$(EV3LX_FNCD_BASE) '-DINTPRI_TICK=($(INTPRI_TICK))'

# A compiler cache where the machine has one (`make deps` installs ccache): a
# clean clone recompiles nothing the cache has already compiled.  Objects do not
# depend on the clone's directory (sources are named relative to it, debug info
# maps it to "."), so the cache may ignore the directory.
CCACHE := $(if $(shell command -v ccache 2>/dev/null),ccache)
export CCACHE_BASEDIR := $(CURDIR)
export CCACHE_NOHASHDIR := 1
DEBUG_PREFIX_MAP := -fdebug-prefix-map=$(CURDIR)=.

CC_host        := $(CCACHE) gcc
CXX_host       := $(CCACHE) g++
CFLAGS_host    := -O2 -g $(DEBUG_PREFIX_MAP) -DEV3LX_HOST=1
LDFLAGS_host   :=
RUN_host       :=

CC_host-san     := $(CCACHE) gcc
CXX_host-san    := $(CCACHE) g++
CFLAGS_host-san := -O1 -g $(DEBUG_PREFIX_MAP) -DEV3LX_HOST=1 -fsanitize=address,undefined \
	-fno-omit-frame-pointer -fno-sanitize-recover=all
# Linux code under UBSan as kbuild builds it for x86: CONFIG_UBSAN_ALIGNMENT
# defaults to n where unaligned accesses are efficient (lib/Kconfig.ubsan:
# default !HAVE_EFFICIENT_UNALIGNED_ACCESS), so a driver's deliberate
# unaligned word store (TI's soft-UART HAL clearing PRU RAM) is not UB there.
LINUX_SAN_host-san := -fno-sanitize=alignment
LDFLAGS_host-san := -fsanitize=address,undefined
RUN_host-san    :=

# -m32 is part of the compiler's name, not of its flags: every use of the
# compiler (its include directory, an app's partial link, a C++ link) is a
# 32-bit one.  Not position-independent, as the brick's image is not: i386
# PIC code gets its address from a __x86.get_pc_thunk.* function, one COMDAT
# copy per object, which an app's domain relink (--force-group-allocation,
# mk/ev3rt_app.mk) would turn into clashing definitions.  The peripheral window
# sits at its physical address, as on the brick (host_sim/src/core/space.c).
# Debian's gcc-multilib gives -m32 the C library's 32-bit headers but not the
# kernel's user-space <asm/*.h> (glibc's <errno.h> includes <asm/errno.h>),
# which only the amd64 multiarch directory has: Linux's x86 uapi headers are
# one set for both ABIs (<asm/unistd.h> picks unistd_32.h under __i386__), so
# host32 sees that directory, and only it, after the system's own.
HOST32_ASM_DIR  := /usr/include/x86_64-linux-gnu/asm
HOST32_SYSINC   := $(BUILD)/host32/sysinc
$(if $(wildcard $(HOST32_SYSINC)/asm),,$(shell mkdir -p $(HOST32_SYSINC) && ln -sfn $(HOST32_ASM_DIR) $(HOST32_SYSINC)/asm))
# Floating point in SSE2 registers, not the x87's 80-bit ones: double
# arithmetic then rounds to double at every step (FLT_EVAL_METHOD 0), as on
# x86-64 and the ARM, so that the simulation's physics gives the same results
# in every configuration (and `x == 1e-4` compares doubles, not a double with
# a long double constant).
HOST32_ARCH     := -m32 -msse2 -mfpmath=sse -fno-pie -no-pie -idirafter $(HOST32_SYSINC)
CC_host32       := $(CCACHE) gcc $(HOST32_ARCH)
CXX_host32      := $(CCACHE) g++ $(HOST32_ARCH)
CFLAGS_host32   := -O2 -g $(DEBUG_PREFIX_MAP) -DEV3LX_HOST=1
LDFLAGS_host32  :=
RUN_host32      :=

CC_arm926-test     := $(CCACHE) arm-linux-gnueabi-gcc
CXX_arm926-test    := $(CCACHE) arm-linux-gnueabi-g++
CFLAGS_arm926-test := -O2 -g $(DEBUG_PREFIX_MAP) -DEV3LX_HOST=1 -mcpu=arm926ej-s -marm
LDFLAGS_arm926-test := -static
RUN_arm926-test    := qemu-arm -cpu arm926 -L /usr/arm-linux-gnueabi

# std and include path for one source file: its layer's include directories (mk/layers.mk)
is_linux_src = $(filter $(addsuffix /%,$(LINUX_DIRS)),$(1))
src_flags = $(if $(call is_linux_src,$(1)),-std=gnu11 $(LINUX_INC) $(LINUX_CODEGEN),-std=c11) $(call layer_inc,$(call LAYER_OF,$(1)))
# warnings for one source file: kernel code keeps GNU void-pointer arithmetic, as kbuild's W=1 does
warn_flags = $(if $(call is_linux_src,$(1)),$(filter-out -Wpointer-arith,$(WARN)),$(WARN))

# Linux code proper — the modules (hacks with their drivers), linux_compat's
# portable implementation and every header under linux_compat — is compiled as
# kbuild compiles it: -nostdinc, with only the compiler's own include
# directory (stddef.h, stdarg.h, stdbool.h) beside the layers' headers, so a
# C library name never reaches a driver and a header linux_compat lacks is an
# error instead of the host's /usr/include/linux one.  Only the host's
# platform glue (linux_compat/src/host: signals, the simulated hardware's side)
# and the test programs, which speak TAP through stdio, use the C library.
NOSTDINC_DIRS := hacks linux_compat/src linux_compat/mach-davinci linux_compat/include tests/legacy
# the test programs among the users' modules (tests/legacy and its genuine/ home)
LEGACY_TEST_PATTERNS := tests/legacy/test_% tests/legacy/genuine/test_%
is_nostdinc_src = $(filter-out linux_compat/src/host/%,$(filter $(addsuffix /%,$(NOSTDINC_DIRS)),$(filter-out $(LEGACY_TEST_PATTERNS),$(1))))
# the compiler's own include directory, per configuration (CC_am1808 is set in mk/am1808.mk)
cc_include = $(or $(CC_INCLUDE_$(1)),$(eval CC_INCLUDE_$(1) := $(shell $(CC_$(1)) -print-file-name=include))$(CC_INCLUDE_$(1)))
nostdinc_flags = $(if $(call is_nostdinc_src,$(2)),-nostdinc -isystem $(call cc_include,$(1)))

# Modules.  Each hack file with the driver it includes is one module, linked
# as one relocatable object with a private namespace, as a .ko is: compiled
# -fvisibility=hidden, `ld -r`, then every hidden symbol localized, so only the
# module's EXPORT_SYMBOL*s and the hack's interface (declared with visibility
# "default" in its header) stay global.  Two modules defining the same global
# names then link into one library, as two .ko files load into one kernel.
# A module is two translation units: the hack file (hacks/<m>_hack.c), which
# includes the driver and sees only Linux headers, and its RTOS side
# (hacks/<m>_svc.c: the service calls and the configuration fragment), which
# sees the kernel's; they share the module's private header (<m>_module.h).
is_module_src = $(filter hacks/%_hack.c hacks/%_svc.c,$(1))
module_flags = $(if $(call is_module_src,$(2)),-fvisibility=hidden)
# a library's object list with each module's objects replaced by its linked one
is_hack_obj = $(and $(findstring /obj/hacks/,$(1)),$(filter %_hack.o %_svc.o,$(1)))
module_objs = $(foreach o,$(1),$(if $(call is_hack_obj,$(o)),$(if $(filter %_hack.o,$(o)),$(o:.o=.mod.o)),$(o)))

# The driver's translation unit (a hack file, which includes the driver) is
# compiled without the kernel's header directory: a kernel header (kernel.h,
# t_stddef.h, rtos_cfg.h, sil.h; against a real kernel tree also its chip
# headers, which come in its place) reaching a driver's unit is a build error
# in every configuration.  make nostdinc-check proves it.
is_driver_tu = $(filter hacks/%_hack.c,$(1))
driver_tu_filter = $(if $(call is_driver_tu,$(1)),$(filter-out -I$(HDR_rtos_stub),$(2)),$(2))
LD_host := ld
LD_host-san := ld
LD_host32 := ld -m elf_i386
LD_arm926-test := arm-linux-gnueabi-ld
LD_am1808 := arm-none-eabi-ld
OBJCOPY_host := objcopy
OBJCOPY_host-san := objcopy
OBJCOPY_host32 := objcopy
OBJCOPY_arm926-test := arm-linux-gnueabi-objcopy
OBJCOPY_am1808 := arm-none-eabi-objcopy

# Links objects $(3) of configuration $(1) into module $(2) (X.mod.o, beside it
# X.r.o): one relocatable object, its hidden symbols made local.
module_link = $(LD_$(1)) -r -o $(2:.mod.o=.r.o) $(3) && $(OBJCOPY_$(1)) --localize-hidden $(2:.mod.o=.r.o) $(2)

# The module link rule of configuration $(1) for the library objects $(2)
# (a static pattern rule: the linked modules are targets in their own right,
# remade when missing).
define module_link_rule
$(filter %.mod.o,$(call module_objs,$(2))): %_hack.mod.o: %_hack.o %_svc.o
	$$(quiet) MOD $(1) $$@
	$(Q)$$(call module_link,$(1),$$@,$$^)
endef

# The kernel domain — the host kernel, linux_compat and the hacks with their
# drivers — calls the kernel's service calls by function call under their
# _kernel_ names, as HRP2 compiles its kernel and system services
# (TOPPERS_SVC_CALL, rtos_stub/include/svc_call.h); everything else (the EV3
# API, applications, tests) is user-domain code, whose calls are
# target_svc.h's software interrupts on the brick.
KERNEL_DOMAIN_DIRS := rtos_stub/src linux_compat hacks
kernel_domain_flags = $(if $(filter $(addsuffix /%,$(KERNEL_DOMAIN_DIRS)),$(1)),-DTOPPERS_SVC_CALL)

# The object IDs every source takes from the configurator's kernel_cfg.h
# (cfg/ev3lx.cfg, cfg/module.mk): searched last, after an app's own
# kernel_cfg.h, and never by a driver's unit (the kernel's directories are
# not on its path).
cfg_inc = $(if $(call is_driver_tu,$(1)),,-idirafter $(EV3LX_CFG_DIR))

# The one compile command of configuration $(1) for source (or header) $(2):
# every object, firmware file and header check is compiled through it.
# A configuration may rewrite its command (compile_adjust_<config>: the AM1808
# against a real HRP2 tree takes the kernel's headers for rtos_stub's).
compile_cmd = $(CC_$(1)) $(call cc_flags,$(1),$(call nostdinc_flags,$(1),$(2)) $(call driver_tu_filter,$(2),$(call src_flags,$(2))) \
	$(call warn_flags,$(2)) $(call module_flags,$(1),$(2)) $(call kernel_domain_flags,$(2)) $(call cfg_inc,$(2))) \
	$(CFLAGS_$(1)) $(if $(call is_linux_src,$(2)),$(LINUX_SAN_$(1))) $(KERNEL_DEFS)
compile = $(if $(compile_adjust_$(1)),$(call compile_adjust_$(1),$(call compile_cmd,$(1),$(2))),$(call compile_cmd,$(1),$(2)))

# Flags of configuration $(1)'s compiler: clang (the fuzzing build) has no
# -fno-allow-store-data-races (it never invents stores the source lacks) nor
# -fconserve-stack (kbuild passes it only to gcc too).
GCC_ONLY_FLAGS := -fno-allow-store-data-races -fconserve-stack
cc_flags = $(if $(filter clang%,$(notdir $(CC_$(1)))),$(filter-out $(GCC_ONLY_FLAGS),$(2)),$(2))

# Checks kept as stamps (kbuild, bench-quick, report, ...) are remade only when
# an input changed.  Inputs that are files are prerequisites; what is not a
# file's time stamp — the set of files (one removed, one added with an old
# time), a tool's version, a setting — goes into a key file: $(1) holding the
# text $(2), rewritten only when that text changes, and a prerequisite of the
# stamp.  The text is computed when make considers the key (it may run tools).
# Make compares and writes it itself, with no file in between: two makes may
# consider one key at once (a check's own make beside the suite's, both
# needing a configuration's compile key), and a key that is the same is only
# read.
define key_file_rule
key_text_$(1) = $(2)
$(1): FORCE_KEY
	$$(if $$(shell mkdir -p $$(@D) && echo ok),,$$(error cannot create $$(@D)))
	$$(if $$(call same_text,$$(file <$$@),$$(key_text_$$@)),,$$(file >$$@,$$(key_text_$$@)))
endef
# Non-empty if texts $(1) and $(2) are equal as words (each within the other,
# framed).  Both are stripped: $(file <) of GNU make 4.3 keeps the file's final
# newline when the file is longer than its 200-byte read buffer, so a long key
# read back would never equal its text and would be rewritten on every make,
# recompiling its whole configuration.
same_text = $(and $(findstring x$(strip $(1))x,x$(strip $(2))x),$(findstring x$(strip $(2))x,x$(strip $(1))x))
.PHONY: FORCE_KEY

# The object rule of configuration $(1) for the objects under $(2)/obj.  The
# configuration's compiler and flags are a key of their own ($(2)/compile.key)
# that every object depends on — this rule's, and those the configuration's
# other compile rules make (EV3RT apps, legacy modules, the configurator's
# test) — so a changed flag recompiles the objects that an old one made (the
# compiler cache makes that cheap where nothing changed).
define obj_rule
$(call key_file_rule,$(2)/compile.key,$(CC_$(1)) $(CFLAGS_$(1)) $(KERNEL_DEFS) $(LINUX_CODEGEN) $(LINUX_SAN_$(1)))
$(2)/obj/%.o: %.c $(2)/compile.key $(EV3LX_CFG_DIR)/kernel_cfg.h
	@mkdir -p $$(@D)
	$$(quiet) CC $(1) $$<
	$(Q)$$(call compile,$(1),$$<) -MMD -MP -c $$< -o $$@
	$$(call record_driver_hashes,$$@,$$<)
endef

# Quiet build lines ("CC host path"); make V=1 shows the full commands.
ifeq ($(V),1)
Q :=
quiet = @true
else
Q := @
quiet = @printf '  %-6s %-12s %s\n'
endif

# Where the drivers are: the hack files in EV3LX_HACK_DIRS include them by name
# (#include "any_name.c"), resolved in the hack's directory, then in DRIVER_DIRS.
# An out-of-tree driver directory (its driver, headers and hack file) is added
# with EXTRA_DRIVER_DIRS=path (documented in docs/porting.md); kbuild-check,
# verbatim-check (mk/kbuild.mk) and report (mk/report.mk) then cover it like
# ev3_drivers/.  Defined here, before the mk/*.mk whose rules list the drivers.
EV3LX_HACK_DIRS ?= hacks
EXTRA_DRIVER_DIRS ?=
# A driver from outside ev3_drivers/, its test as its hack file (docs/porting.md).
EXAMPLE_DRIVER_DIRS := tests/linux_compat/porting/edge_watch tests/linux_compat/porting/gpio_events \
	tests/linux_compat/porting/ev3_buttons tests/linux_compat/porting/ehrpwm_chip \
	tests/linux_compat/porting/ads7957_adc tests/linux_compat/porting/dc_motor \
	tests/linux_compat/porting/ecap_chip tests/linux_compat/porting/nxt_us tests/linux_compat/porting/ev3_uart
DRIVER_DIRS := ev3_drivers $(EXAMPLE_DRIVER_DIRS) $(EXTRA_DRIVER_DIRS)
# (found once per make, when first needed)
DRIVER_FILES = $(or $(DRIVER_FILES_FOUND),$(eval DRIVER_FILES_FOUND := $(sort $(shell \
	bash cloc_report/find_drivers.sh "$(EV3LX_HACK_DIRS)" "$(DRIVER_DIRS)" | cut -d' ' -f2)))$(DRIVER_FILES_FOUND))

# linux_compat: the Linux kernel API over rtos_stub.
#   include/linux, include/asm, include/asm-generic   headers at Linux paths
#   include/linux_compat/   linux_compat's own interfaces (context, config, report)
#   src/*.c                 both targets (generic);  src/host/*.c, src/am1808/*.c   one target only
#                           (linux_compat/platform.h: I/O windows, reports, halting)
#   mach-davinci/           the DaVinci (AM1808) machine: include/mach/, GPIO banks, IRQ lines
HOST_SRCS   += $(sort $(wildcard linux_compat/src/*.c linux_compat/src/host/*.c linux_compat/mach-davinci/*.c))
AM1808_SRCS += $(sort $(wildcard linux_compat/src/*.c linux_compat/src/am1808/*.c linux_compat/mach-davinci/*.c))

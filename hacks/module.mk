# hacks: one small file per reused Linux driver — the driver source included
# verbatim, then its interface as extended service calls (and a header of
# call wrappers for applications, on the include path via -Ihacks).
HOST_SRCS   += $(sort $(wildcard hacks/*.c))
AM1808_SRCS += $(sort $(wildcard hacks/*.c))

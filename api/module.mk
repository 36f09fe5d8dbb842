# api: the EV3 C API (ev3api.h) over the hacks' extended service calls.
HOST_SRCS   += $(sort $(wildcard api/src/*.c))
AM1808_SRCS += $(sort $(wildcard api/src/*.c))

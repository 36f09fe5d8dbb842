# api: the EV3 C API (ev3api.h) over the hacks' extended service calls.
HOST_SRCS   += $(sort $(wildcard api/src/*.c))
# app_malloc.c is what a host-built app's renamed malloc and new call; on the
# brick an app's newlib allocates from its domain's heap itself.
AM1808_SRCS += $(filter-out api/src/app_malloc.c,$(sort $(wildcard api/src/*.c)))

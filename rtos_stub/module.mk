# rtos_stub: TOPPERS/HRP2 API subset.
#   include/          kernel.h, sil.h, t_stddef.h, t_syslog.h (both targets), rtos_cfg.h, rtos_host.h
#   src/host/         the deterministic host kernel in virtual time (host configurations only)
HOST_SRCS   += $(sort $(wildcard rtos_stub/src/host/*.c))

HOST_PROGRAMS += rtos_demo
rtos_demo_SRCS := rtos_stub/demo/rtos_demo.c

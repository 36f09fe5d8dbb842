# bench: `make bench` (mk/bench.mk, docs/bench.md).  Nothing here goes into
# libev3lx.a: the host bench and the instruction counter are host programs,
# the ARMv5 bench program is linked by mk/bench.mk.
HOST_PROGRAMS += bench_host insn_count
bench_host_SRCS := bench/bench_host.c bench/bench_brick.c
insn_count_SRCS := bench/insn_count.c
BENCH_ARM_SRCS  := bench/bench_arm.c bench/bench_brick.c

# `make bench`: the EV3 API against the paper's Table 2 (docs/bench.md).
#   make bench         10 000 calls each on the full brick: table + build/bench/bench.csv,
#                      the README's table in build/bench/readme.md
#   make bench-readme  the same, and the table put into README.md
#   make bench-quick   200 calls, a short light-brick QEMU run: proves that every
#                      figure is produced (part of `make test`); asserts no speed
# The host programs (bench_host, insn_count) are HOST_PROGRAMS of bench/module.mk;
# the ARMv5 program is linked here against the arm926-test library, like a test
# (the host-checked build), and again against a production variant of it
# (build/arm926-bench-prod): the code that runs on the brick (LINUX_DIRS and
# the api) and the kernel whose service calls are counted (rtos_stub) compiled
# as the AM1808 library is — -Os, no PIE, linux_compat's debugging checks off
# ($(LX_DEBUG_OFF)) — the simulator (host_sim) shared with arm926-test.
BENCH_OUT       := $(BUILD)/bench
BENCH_ARM       := $(BUILD)/arm926-test/bench/bench_arm
BENCH_ARM_OBJS  := $(patsubst %.c,$(BUILD)/arm926-test/obj/%.o,$(BENCH_ARM_SRCS))
BENCH_LOG_SHIM  := $(BUILD)/host/bench/qemu_log_buffer.so

BENCH_PROD          := $(BUILD)/arm926-bench-prod
BENCH_PROD_ARM      := $(BENCH_PROD)/bench/bench_arm
BENCH_PROD_LIB      := $(BENCH_PROD)/libev3lx.a
BENCH_PROD_OWN_SRCS := $(foreach s,$(HOST_SRCS),$(if $(call is_linux_src,$(s)),$(s))) \
	$(filter api/% rtos_stub/%,$(HOST_SRCS))
BENCH_PROD_LIB_OBJS := $(patsubst %.c,$(BENCH_PROD)/obj/%.o,$(BENCH_PROD_OWN_SRCS)) \
	$(patsubst %.c,$(BUILD)/arm926-test/obj/%.o,$(filter-out $(BENCH_PROD_OWN_SRCS),$(HOST_SRCS)))

# The production variant is a configuration of its own, compiled by the one
# recipe: the brick's code as the AM1808 library compiles it (-Os, the checks
# off, position-dependent; mk/am1808.mk), for the ARM926 under Linux (whose
# compiler makes PIE code by default; the bench programs link -static, not
# PIE).  It differs from the brick's library only where it must: the kernel
# under it is rtos_stub's host kernel instead of HRP2, and memcpy/memset are
# glibc's instead of newlib's.
CC_arm926-bench-prod     := $(CC_arm926-test)
CFLAGS_arm926-bench-prod := $(filter-out -O2,$(CFLAGS_arm926-test)) -Os -fno-pie $(LX_DEBUG_OFF)
$(eval $(call obj_rule,arm926-bench-prod,$(BENCH_PROD)))

$(BENCH_PROD_LIB): $(BENCH_PROD_LIB_OBJS)
	@mkdir -p $(@D)
	$(quiet) AR bench-prod $@
	$(Q)rm -f $@
	$(Q)arm-linux-gnueabi-ar rcs $@ $^

$(BENCH_ARM): $(BENCH_ARM_OBJS) $(LIB_arm926-test)
	@mkdir -p $(@D)
	$(CC_arm926-test) $(CFLAGS_arm926-test) $(LDFLAGS_arm926-test) -o $@ $(BENCH_ARM_OBJS) \
		-Wl,--start-group $(LIB_arm926-test) -Wl,--end-group -lm

$(BENCH_PROD_ARM): $(BENCH_ARM_OBJS) $(BENCH_PROD_LIB)
	@mkdir -p $(@D)
	$(CC_arm926-test) $(CFLAGS_arm926-test) $(LDFLAGS_arm926-test) -o $@ $(BENCH_ARM_OBJS) \
		-Wl,--start-group $(BENCH_PROD_LIB) -Wl,--end-group -lm

# The timer queues' scaling program (bench/timers: Linux code, see LINUX_DIRS),
# against the production library only.
BENCH_TIMERS      := $(BENCH_PROD)/bench/bench_timers
BENCH_TIMERS_OBJS := $(BENCH_PROD)/obj/bench/timers/bench_timers.o

$(BENCH_TIMERS): $(BENCH_TIMERS_OBJS) $(BENCH_PROD_LIB)
	@mkdir -p $(@D)
	$(CC_arm926-test) $(CFLAGS_arm926-test) $(LDFLAGS_arm926-test) -o $@ $(BENCH_TIMERS_OBJS) \
		-Wl,--start-group $(BENCH_PROD_LIB) -Wl,--end-group -lm

# Functions with their source files, for the counter's attribution; QEMU runs a
# stripped copy (it would look every executed block's symbol up for the log).
BENCH_ARM_BINS := $(BENCH_ARM) $(BENCH_PROD_ARM) $(BENCH_TIMERS)

$(addsuffix .syms,$(BENCH_ARM_BINS)): %.syms: %
	arm-linux-gnueabi-nm -n -S -l --defined-only $< > $@

$(addsuffix .stripped,$(BENCH_ARM_BINS)): %.stripped: %
	arm-linux-gnueabi-strip -o $@ $<

$(BENCH_LOG_SHIM): bench/qemu_log_buffer.c
	@mkdir -p $(@D)
	$(CC_host) -std=gnu11 -O2 $(WARN) -shared -fPIC -o $@ $< -ldl

BENCH_DEPS := $(BUILD)/host/bench_host $(BUILD)/host/insn_count $(BENCH_ARM).syms \
	$(BENCH_ARM).stripped $(BENCH_PROD_ARM).syms $(BENCH_PROD_ARM).stripped $(BENCH_LOG_SHIM) \
	$(BENCH_TIMERS).syms $(BENCH_TIMERS).stripped $(BUILD)/host/ev3sim $(AM1808_LIB) $(AM1808)/ev3lx.elf

# The production build's inline locking fast path has a test of its own:
# test_irqsave, which every configuration runs checked, runs again against
# the production library under qemu-arm (in `make test`).
PROD_TESTS       := tests/linux_compat/locking/test_irqsave
PROD_TEST_BINS   := $(patsubst %,$(BENCH_PROD)/%.t,$(PROD_TESTS))
PROD_SUPPORT_OBJS := $(patsubst %.c,$(BENCH_PROD)/obj/%.o,$(TEST_SUPPORT_SRCS))

$(BENCH_PROD)/%.t: $(BENCH_PROD)/obj/%.o $(PROD_SUPPORT_OBJS) $(BENCH_PROD_LIB)
	@mkdir -p $(@D)
	$(quiet) LD bench-prod $@
	$(Q)$(CC_arm926-test) $(CFLAGS_arm926-test) $(LDFLAGS_arm926-test) -o $@ $< $(PROD_SUPPORT_OBJS) \
		-Wl,--start-group $(BENCH_PROD_LIB) -Wl,--end-group -lm

.PHONY: prod-tests
prod-tests: $(PROD_TEST_BINS)
	@echo "=== prove: production build (arm926, checks off) ==="
	@prove --exec '$(RUN_arm926-test)' $(PROD_TEST_BINS)

TEST_SUITE_EXTRA += prod-tests
TEST_SUITE_EXTRA_DEPS += $(PROD_TEST_BINS)

# `make bench` writes the README's table under build/ and leaves the tree as it
# was; `make bench-readme` (or `make bench UPDATE_README=1`) also puts it into
# README.md, for a commit that changes the counts.
.PHONY: bench bench-quick bench-readme
bench: deps-check $(BENCH_DEPS) pgo
	@bash bench/run_bench.sh full $(BENCH_OUT) $(BUILD)
	@bash bench/readme_table.sh $(BENCH_OUT)/bench.csv > $(BENCH_OUT)/readme.md
	@if [ "$(UPDATE_README)" = 1 ]; then \
		bash bench/update_readme.sh README.md $(BENCH_OUT)/readme.md && \
		echo "bench: README.md's table regenerated from $(BENCH_OUT)/bench.csv"; \
	else \
		echo "bench: README table in $(BENCH_OUT)/readme.md (README.md untouched; make bench-readme puts it there)"; \
	fi

bench-readme:
	@$(MAKE) --no-print-directory bench UPDATE_README=1

# The quick run is kept with its output (build/bench/quick/run.log) and redone
# only when an input changed: the programs, the scripts, README.md (whose table
# it checks) and QEMU (its version in the key: it counts the instructions).
# The host's nanoseconds it prints are not asserted, so a kept run's stand.
BENCH_QUICK_OUT := $(BENCH_OUT)/quick
BENCH_QUICK_KEY := $(BUILD)/bench-quick.key
$(eval $(call key_file_rule,$(BENCH_QUICK_KEY),$$(shell qemu-arm --version | head -n 1)))

bench-quick: deps-check $(BENCH_QUICK_OUT)/run.log
	@cat $(BENCH_QUICK_OUT)/run.log

$(BENCH_QUICK_OUT)/run.log: $(BENCH_DEPS) $(BENCH_QUICK_KEY) bench/run_bench.sh bench/insn_count_selftest.sh \
		README.md | deps-check
	@mkdir -p $(@D)
	@bash bench/run_bench.sh quick $(BENCH_QUICK_OUT) $(BUILD) > $@.tmp 2>&1 || { cat $@.tmp; rm -f $@.tmp; exit 1; }
	@mv $@.tmp $@

TEST_SUITE_EXTRA += bench-quick
TEST_SUITE_EXTRA_DEPS += $(BENCH_DEPS)

-include $(BENCH_ARM_OBJS:.o=.d) $(patsubst %.c,$(BENCH_PROD)/obj/%.d,$(BENCH_PROD_OWN_SRCS)) \
	$(PROD_SUPPORT_OBJS:.o=.d) $(patsubst %,$(BENCH_PROD)/obj/%.d,$(PROD_TESTS)) $(BENCH_TIMERS_OBJS:.o=.d)

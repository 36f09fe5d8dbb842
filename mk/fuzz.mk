# Fuzzing with libFuzzer (clang): `make fuzz` builds every harness
# (tests/**/test_fuzz_*.c, each also a TAP test replaying its corpus in
# `make test`) against the library instrumented for coverage, ASan and UBSan,
# runs each for FUZZ_SECONDS, and replaces the committed corpus
# tests/fuzz/corpus/NAME/ by the smallest set of the old and the new inputs
# that keeps all their coverage (libFuzzer's -merge into an empty directory).  The
# figures of the campaign (executions, crashes) go to build/fuzz/report.txt;
# a crash leaves its input in build/fuzz/crash-NAME-*.  docs/reliability.md.

FUZZ_SECONDS ?= 60
FUZZ_DEPS    := clang:clang
FUZZ_RT      := $(firstword $(wildcard /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a))

CC_fuzz     := clang
CFLAGS_fuzz := -O1 -g -DEV3LX_HOST=1 -DEV3LX_LIBFUZZER=1 -fsanitize=fuzzer-no-link,address,undefined \
	-fno-omit-frame-pointer -fno-sanitize-recover=all -Wno-error -Wno-unknown-warning-option

FUZZ_SRCS  := $(sort $(shell find tests -name 'test_fuzz_*.c' 2>/dev/null))
FUZZ_NAMES := $(patsubst test_fuzz_%.c,%,$(notdir $(FUZZ_SRCS)))
OBJS_fuzz  := $(patsubst %.c,$(BUILD)/fuzz/obj/%.o,$(HOST_SRCS))
SUPPORT_OBJS_fuzz := $(patsubst %.c,$(BUILD)/fuzz/obj/%.o,$(TEST_SUPPORT_SRCS))

$(eval $(call obj_rule,fuzz,$(BUILD)/fuzz))

$(BUILD)/fuzz/libev3lx.a: $(OBJS_fuzz)
	@mkdir -p $(@D)
	$(quiet) AR fuzz $@
	$(Q)rm -f $@
	$(Q)ar rcs $@ $^

# the configurator's harness carries cfg_gen (mk/ev3rt_app.mk)
$(eval $(call ev3rt_cfg_unit_test,fuzz,tests/cfg/test_fuzz_cfg))

# fuzz_NAME from tests/.../test_fuzz_NAME.c
define fuzz_harness_rule
$(BUILD)/fuzz/fuzz_$(patsubst test_fuzz_%.c,%,$(notdir $(1))): $(BUILD)/fuzz/obj/$(1:.c=.o) $$(SUPPORT_OBJS_fuzz) $(BUILD)/fuzz/libev3lx.a
	$$(quiet) LD fuzz $$@
	$(Q)$(CC_fuzz) -fsanitize=fuzzer,address,undefined -o $$@ $$< $$(SUPPORT_OBJS_fuzz) \
		-Wl,--start-group $(BUILD)/fuzz/libev3lx.a -Wl,--end-group -lm
endef
$(foreach s,$(FUZZ_SRCS),$(eval $(call fuzz_harness_rule,$(s))))

.PHONY: fuzz fuzz-deps fuzz-build
fuzz-deps:
	@if ! command -v clang >/dev/null || [ -z "$(FUZZ_RT)" ]; then \
		line="apt-get install -y --no-install-recommends clang libclang-rt-14-dev"; \
		if [ "$$(id -u)" != 0 ]; then echo "fuzz: as root run: $$line"; exit 1; fi; \
		DEBIAN_FRONTEND=noninteractive $$line || { apt-get update && DEBIAN_FRONTEND=noninteractive $$line; }; \
	fi

fuzz-build: fuzz-deps
	@$(MAKE) --no-print-directory $(addprefix $(BUILD)/fuzz/fuzz_,$(FUZZ_NAMES))

# One harness after the other (the machine's cores are the simulation's): new
# inputs in build/fuzz/found/NAME, then the corpus minimised with them.
fuzz: fuzz-build
	@mkdir -p $(BUILD)/fuzz; rm -f $(BUILD)/fuzz/crash-*; : > $(BUILD)/fuzz/report.txt; status=0; \
	for n in $(FUZZ_NAMES); do \
		mkdir -p $(BUILD)/fuzz/found/$$n tests/fuzz/corpus/$$n; \
		echo "fuzz: $$n for $(FUZZ_SECONDS) s"; \
		( cd $(BUILD)/fuzz && ./fuzz_$$n -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
			-artifact_prefix=crash-$$n- -max_len=4096 found/$$n ../../tests/fuzz/corpus/$$n ) \
			> $(BUILD)/fuzz/$$n.log 2>&1; rc=$$?; \
		execs=$$(awk '/stat::number_of_executed_units/ { print $$2 }' $(BUILD)/fuzz/$$n.log); \
		crashes=$$(ls $(BUILD)/fuzz/crash-$$n-* 2>/dev/null | wc -l); \
		echo "$$n executions=$${execs:-0} crashes=$$crashes exit=$$rc" | tee -a $(BUILD)/fuzz/report.txt; \
		[ $$rc = 0 ] && [ $$crashes = 0 ] || status=1; \
		rm -rf $(BUILD)/fuzz/min/$$n; mkdir -p $(BUILD)/fuzz/min/$$n; \
		( cd $(BUILD)/fuzz && ./fuzz_$$n -merge=1 min/$$n ../../tests/fuzz/corpus/$$n found/$$n ) \
			>> $(BUILD)/fuzz/$$n.log 2>&1 && [ -n "$$(ls $(BUILD)/fuzz/min/$$n)" ] && \
			rm -f tests/fuzz/corpus/$$n/* && cp $(BUILD)/fuzz/min/$$n/* tests/fuzz/corpus/$$n/; \
	done; \
	echo "fuzz: report in $(BUILD)/fuzz/report.txt"; exit $$status

# `make reliability`: docs/reliability.md's figures from runs made now
# (mk/reliability.sh), in build/reliability/figures.md.
.PHONY: reliability
reliability: $(BUILD)/host-pgo/ev3sim
	@mkdir -p $(BUILD)/reliability
	@bash mk/reliability.sh $(BUILD)/host-pgo/ev3sim > $(BUILD)/reliability/figures.md
	@cat $(BUILD)/reliability/figures.md
	@echo "reliability: $(BUILD)/reliability/figures.md"

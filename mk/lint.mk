# Static analysis (docs/lint.md).
#   make lint        cppcheck over every C file that is built; part of `make test`
#   make lint-tidy   clang-tidy (mk/lint/clang-tidy.yaml) over the same files, incremental
#   make lint-full   both
# Each fails on any finding that is not suppressed.  Suppress a false positive where it
# is, with the reason on the same comment: `cppcheck-suppress <id> ; <reason>` or
# `NOLINT(<check>): <reason>` / `NOLINTNEXTLINE(...)`.  ev3_drivers/ stays genuine Linux
# (no tool comments) and files being changed by someone else are not touched: their
# entries go in mk/lint/cppcheck.supp or mk/lint/clang-tidy.supp, a reason above each.
#
# Both tools read build/lint/compile_commands.json, generated from the build's own
# per-file flags (src_flags, warn_flags, KERNEL_DEFS): each file is analysed as it is
# compiled for the host, the AM1808-only files with EV3LX_AM1808.  cppcheck also reads
# build/lint/am1808/compile_commands.json: the files both targets share, as compiled for
# the AM1808.  ev3_drivers/*.c are analysed where they are compiled: in their hack file.

LINT_OUT         := $(BUILD)/lint
LINT_DB          := $(LINT_OUT)/compile_commands.json
LINT_AM1808_DB   := $(LINT_OUT)/am1808/compile_commands.json
LINT_CPPCHECK_SUPP := mk/lint/cppcheck.supp
LINT_TIDY_CONFIG := mk/lint/clang-tidy.yaml
LINT_TIDY_SUPP   := mk/lint/clang-tidy.supp
LINT_TIDY_FILTER := mk/lint/clang_tidy_filter.awk

# Every C file that is built: the libraries, the test support, the tests, the programs.
LINT_HOST_SRCS := $(sort $(wildcard $(HOST_SRCS) $(TEST_SUPPORT_SRCS) $(TEST_SRCS) \
	$(foreach p,$(HOST_PROGRAMS),$($(p)_SRCS)) $(bench_host_SRCS) $(insn_count_SRCS) \
	$(BENCH_ARM_SRCS)))
LINT_AM1808_SRCS := $(sort $(filter-out $(LINT_HOST_SRCS),$(AM1808_SRCS)) $(wildcard am1808/*.c))
LINT_SRCS := $(LINT_HOST_SRCS) $(LINT_AM1808_SRCS)
LINT_SHARED_SRCS := $(sort $(filter $(LINT_HOST_SRCS),$(AM1808_SRCS)))

# Compile flags per configuration: the build's, without -Werror (clang-tidy reports a
# compiler warning as a finding of its own, by name).
lint_flags_host   = $(filter-out -fno-allow-store-data-races,$(call src_flags,$(1))) $(filter-out -Werror,$(call warn_flags,$(1))) \
	-DEV3LX_HOST=1 $(KERNEL_DEFS)
lint_flags_am1808 = $(filter-out -fno-allow-store-data-races,$(call src_flags,$(1))) $(filter-out -Werror,$(call warn_flags,$(1))) \
	-DEV3LX_AM1808=1 -ffreestanding $(KERNEL_DEFS)
lint_cfg = $(if $(filter $(1),$(LINT_AM1808_SRCS)),am1808,host)
lint_flags = $(call lint_flags_$(call lint_cfg,$(1)),$(1))

# $(1) = file, $(2) = its flags
lint_entry = {"directory": "$(CURDIR)", "file": "$(1)", "command": "gcc $(strip $(2)) -c $(1) -o /dev/null"}
define lint_newline


endef
lint_comma := ,
lint_db_text = [$(lint_newline)$(subst } {,}$(lint_comma)$(lint_newline){,$(1))$(lint_newline)]
LINT_DB_TEXT = $(call lint_db_text,$(foreach f,$(LINT_SRCS),$(call lint_entry,$(f),$(call lint_flags,$(f)))))
LINT_AM1808_DB_TEXT = $(call lint_db_text,$(foreach f,$(LINT_SHARED_SRCS),$(call lint_entry,$(f),$(call lint_flags_am1808,$(f)))))

# Rewritten only when the text changes, so that clang-tidy's per-file results stay valid.
$(LINT_DB): FORCE_LINT_DB
	$(if $(shell mkdir -p $(@D) && echo ok),,$(error lint: cannot create $(@D)))
	$(file >$@.tmp,$(LINT_DB_TEXT))
	@cmp -s $@.tmp $@ && rm $@.tmp || mv $@.tmp $@

$(LINT_AM1808_DB): FORCE_LINT_DB
	$(if $(shell mkdir -p $(@D) && echo ok),,$(error lint: cannot create $(@D)))
	$(file >$@.tmp,$(LINT_AM1808_DB_TEXT))
	@cmp -s $@.tmp $@ && rm $@.tmp || mv $@.tmp $@

.PHONY: FORCE_LINT_DB lint lint-tidy lint-full

# cppcheck: warning/performance/portability, POSIX and GNU libc models (gnu after posix:
# its mmap takes fd -1 for MAP_ANONYMOUS).  Its per-file cache lives in a directory named
# after the configuration, because cppcheck does not notice a changed library or
# suppression list by itself.
CPPCHECK_FLAGS := --enable=warning,performance,portability --std=c11 --inline-suppr \
	--library=posix --library=gnu --suppressions-list=$(LINT_CPPCHECK_SUPP) \
	--error-exitcode=1 --quiet -j$(NPROC) \
	--template='{file}:{line}:{column}: {severity}: {message} [{id}]' \
	--template-location='{file}:{line}:{column}: note: {info}'

lint: deps-check $(LINT_DB) $(LINT_AM1808_DB)
	@key=$$( { cppcheck --version; echo "$(CPPCHECK_FLAGS)"; cat $(LINT_CPPCHECK_SUPP); } | md5sum | cut -c1-12); \
	find $(LINT_OUT) $(dir $(LINT_AM1808_DB)) -maxdepth 1 -name 'cppcheck-*' ! -name "cppcheck-$$key" \
		-exec rm -rf {} +; \
	echo "lint: cppcheck, $(words $(LINT_SRCS)) files for their own target," \
		"$(words $(LINT_SHARED_SRCS)) shared ones for the AM1808 too"; \
	: > $(LINT_OUT)/cppcheck.log; status=0; \
	for db in $(LINT_DB) $(LINT_AM1808_DB); do \
		cache=$$(dirname $$db)/cppcheck-$$key; mkdir -p $$cache; \
		cppcheck $(CPPCHECK_FLAGS) --cppcheck-build-dir=$$cache --project=$$db \
			2>> $(LINT_OUT)/cppcheck.log || status=1; \
	done; \
	if [ $$status != 0 ] || [ -s $(LINT_OUT)/cppcheck.log ]; then cat $(LINT_OUT)/cppcheck.log; \
		echo "lint: cppcheck FAILED: fix each finding, or suppress it with its reason (docs/lint.md)"; \
		exit 1; fi; \
	echo "lint: cppcheck clean"

# clang-tidy: one raw log per file, redone when the file, a header it includes, the build
# flags (mk/config.mk) or the check set change, but not when another file comes or goes;
# then the suppressions are applied to all logs together (so an entry that matches
# nothing is reported as stale).
LINT_TIDY_LOGS := $(patsubst %.c,$(LINT_OUT)/tidy/%.log,$(LINT_SRCS))

$(LINT_OUT)/tidy/%.log: %.c $(LINT_TIDY_CONFIG) mk/config.mk | $(LINT_DB)
	@mkdir -p $(@D)
	$(quiet) TIDY lint $<
	$(Q)gcc -MM -MP -MT $@ $(call lint_flags,$<) $< > $(@:.log=.d)
	$(Q)clang-tidy --quiet --config-file=$(LINT_TIDY_CONFIG) -p $(LINT_DB) $< > $@.tmp 2>&1 || true
	$(Q)mv $@.tmp $@

lint-tidy: deps-check $(LINT_TIDY_LOGS)
	@echo "lint: clang-tidy, $(words $(LINT_SRCS)) files"
	@awk -v root=$(CURDIR) -f $(LINT_TIDY_FILTER) $(LINT_TIDY_SUPP) $(LINT_TIDY_LOGS) \
		> $(LINT_OUT)/clang-tidy.log; status=$$?; cat $(LINT_OUT)/clang-tidy.log; \
	if [ $$status != 0 ]; then \
		echo "lint: clang-tidy FAILED: fix each finding, or suppress it with its reason (docs/lint.md)"; \
		exit 1; fi; \
	echo "lint: clang-tidy clean"

lint-full: lint lint-tidy

-include $(wildcard $(patsubst %.log,%.d,$(LINT_TIDY_LOGS)))

# cppcheck takes about 15 s of CPU for the tree (seconds when little changed); clang-tidy
# takes minutes and stays out of the suite.
TEST_SUITE_EXTRA += lint

# `make test`: the suite — four prove runs and the checks (TEST_SUITE_EXTRA,
# appended by the other mk/*.mk; this file is read after them).  All of them
# are the goals of one make, so the builds, the prove runs and the checks
# share the job slots instead of queueing behind each other, and the kbuild,
# lint and report checks fill the slots the prove runs leave.  -k: any failure
# fails the whole target, but every run is still made and reported.
#
# The ARMv5 tests are built first, by a make of their own: make queues every
# job it can start in the order it finds them, so in the one make a test whose
# last prerequisite is done late (the examples' apps, linked into their tests)
# waits behind every compile of the other configurations, and the qemu-arm
# prove run, the longest, would start last and end the suite alone.  A failure
# there is made and reported again by the second make.
#
# Output (make test V=1 shows everything instead, as before): each run's full
# output goes to build/logs/test/RUN.log — every recipe line of a run goes
# through `mk/quiet.sh shell` (the run's private .SHELLFLAGS), which appends
# its output to the log and, if the line fails, prints the failure with the
# log's tail on the terminal — and a passing run prints one line (suite-RUN,
# `mk/quiet.sh result`).  Those lines reach the terminal on file descriptor
# SUITE_FD (a copy of stdout that bash allocates among the free ones: a fixed
# number could be one of make's jobserver pipes): the make's own output (the build lines of every configuration)
# goes to build/logs/test/make.log, summed up per configuration at the end,
# with its errors if a build failed.  The result comes last.
TEST_SUITE_RUNS = prove-arm926-test prove-host-san prove-host prove-host32 $(TEST_SUITE_EXTRA)
SUITE_LOGS := $(BUILD)/logs/test
# The configurations the suite builds, for its build summary.
SUITE_CONFIGS := host host-san host32 arm926-test am1808 bench-prod

.PHONY: test-suite
ifeq ($(V),1)
test-suite:
	@$(MAKE) --no-print-directory -k tests-arm926-test || true
	@if $(MAKE) --no-print-directory -k -Otarget $(TEST_SUITE_RUNS) $(TEST_SUITE_EXTRA_DEPS); \
	then echo "=== make test: all runs passed ==="; \
	else echo "=== make test: FAILED ==="; exit 1; fi
else
test-suite:
	@rm -rf $(SUITE_LOGS) && mkdir -p $(SUITE_LOGS)
	@$(MAKE) --no-print-directory -k tests-arm926-test > $(SUITE_LOGS)/make-arm926-tests.log 2>&1 || true
	@exec {suite_fd}>&1; \
	if $(MAKE) --no-print-directory -k -Otarget SUITE_FD=$$suite_fd $(addprefix suite-,$(TEST_SUITE_RUNS)) \
		$(TEST_SUITE_EXTRA_DEPS) > $(SUITE_LOGS)/make.log 2>&1; then status=0; else status=1; fi; \
	bash mk/quiet.sh suite-end $(SUITE_LOGS) $$status "$(TEST_SUITE_RUNS)" "$(SUITE_CONFIGS)"
endif

# The suite's quiet runs (the make that test-suite runs with SUITE_FD set).
ifneq ($(SUITE_FD),)
define suite_run_rules
$(1): private .SHELLFLAGS := mk/quiet.sh shell $(SUITE_FD) $(SUITE_LOGS)/$(1).log -c
.PHONY: suite-$(1)
suite-$(1): $(1)
	@bash mk/quiet.sh result $(1) $(SUITE_LOGS)/$(1).log >&$(SUITE_FD)
	@touch $(SUITE_LOGS)/$(1).ok
endef
$(foreach r,$(TEST_SUITE_RUNS),$(eval $(call suite_run_rules,$(r))))
endif

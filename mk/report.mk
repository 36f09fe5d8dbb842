# `make report`: reused versus written lines, counted by cloc (cloc_report/).
#   make report                               every driver the hack files include
#   make report REUSED="dirs/files" GLUE="dirs/files" [SHIM="dirs/files"]   any port
REPORT_DIR := $(BUILD)/report

.PHONY: report report-check
report: deps-check
	@if [ -n "$(REUSED)" ]; then \
		bash cloc_report/reuse_report.sh $(REPORT_DIR) "$(REUSED)" "$(GLUE)" "$(SHIM)"; \
	else \
		$(MAKE) --no-print-directory $(foreach c,$(HOST_CONFIGS),$(LIB_$(c)) $(call driver_test_objs,$(c))) \
			$(AM1808_LIB) kbuild-check \
			> $(REPORT_DIR).log 2>&1 || \
			echo "report: note: a build step failed (see $(REPORT_DIR).log); hashes may be missing"; \
		bash cloc_report/reuse_report.sh $(REPORT_DIR); \
	fi
	@echo "report: $(REPORT_DIR)/reuse.md, $(REPORT_DIR)/reuse.csv"

report-check: report
	@bash cloc_report/check_totals.sh $(REPORT_DIR)
	@bash cloc_report/check_proof.sh

TEST_SUITE_EXTRA += report-check

# Where the drivers are: the hack files in EV3LX_HACK_DIRS include them by name
# (#include "any_name.c"), resolved in the hack's directory, then in DRIVER_DIRS.
# An out-of-tree driver directory (its driver, headers and hack file) is added
# with EXTRA_DRIVER_DIRS=path (documented in docs/porting.md); kbuild-check,
# verbatim-check and report then cover it like ev3_drivers/.
EV3LX_HACK_DIRS ?= hacks
EXTRA_DRIVER_DIRS ?=
# A driver from outside ev3_drivers/, its test as its hack file (docs/porting.md).
EXAMPLE_DRIVER_DIRS := tests/linux_compat/porting/edge_watch
DRIVER_DIRS := ev3_drivers $(EXAMPLE_DRIVER_DIRS) $(EXTRA_DRIVER_DIRS)
DRIVER_FILES = $(sort $(shell bash cloc_report/find_drivers.sh "$(EV3LX_HACK_DIRS)" "$(DRIVER_DIRS)" | cut -d' ' -f2))
# The builds whose compile-time driver hashes the report requires.
REPORT_CONFIGS := $(HOST_CONFIGS) am1808 kbuild
export HACK_DIRS = $(EV3LX_HACK_DIRS)
export DRIVER_DIRS
export BUILD_CONFIGS = $(REPORT_CONFIGS)

# Objects of test files that act as a driver's hack file (in DRIVER_DIRS), per configuration.
driver_test_objs = $(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$(filter $(addsuffix /%,$(DRIVER_DIRS)),$(TEST_SRCS)))

# The compile rule's hook: after compiling a hack file, record the sha256 of
# every driver its compiler read (from the dependency file just written).
record_driver_hashes = $(if $(filter $(addsuffix /%,$(EV3LX_HACK_DIRS) $(DRIVER_DIRS)),$(2)),$(Q)bash cloc_report/record_driver_hashes.sh $(1))

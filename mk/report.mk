# `make report`: reused versus written lines, counted by cloc (cloc_report/).
#   make report                               every driver the hack files include
#   make report REUSED="dirs/files" GLUE="dirs/files" [SHIM="dirs/files"]   any port
REPORT_DIR := $(BUILD)/report

# Where the drivers are (DRIVER_DIRS, DRIVER_FILES): mk/config.mk.

# The builds whose compile-time driver hashes the report requires.
REPORT_CONFIGS := $(HOST_CONFIGS) am1808 kbuild
export HACK_DIRS = $(EV3LX_HACK_DIRS)
export DRIVER_DIRS
export BUILD_CONFIGS = $(REPORT_CONFIGS)

# The sources whose objects record driver hashes: those in the hack and
# driver directories (the hack files, and the tests that act as one).
is_hash_recording_src = $(filter $(addsuffix /%,$(EV3LX_HACK_DIRS) $(DRIVER_DIRS)),$(1))

# The compile rule's hook: after compiling a hack file, record the sha256 of
# every driver its compiler read (from the dependency file just written).
record_driver_hashes = $(if $(call is_hash_recording_src,$(2)),$(Q)bash cloc_report/record_driver_hashes.sh $(1))

# The objects of configuration $(1) that record driver hashes, among its
# sources $(2): what the report reads of that build (OBJ.drivers beside each).
hash_recording_objs = $(patsubst %.c,$(BUILD)/$(1)/obj/%.o,$(call is_hash_recording_src,$(2)))

# The report of the tree's drivers is kept (REPORT_STAMP beside it) and
# redone only when one of its inputs changed: the files it counts (every C
# source and header below REPORT_SRC_DIRS and the driver and hack
# directories; their set is in the key, as are the settings and cloc's
# version), the scripts, and the builds whose compile-time driver hashes it
# checks (each compiled hack file records them beside its object, so the
# objects below are remade whenever a record is; kbuild's are in its kept
# summary's directory).  Only those objects: the report reads nothing else of
# a build, so it compiles a few hack files per configuration where their
# objects are missing, never a whole library (the sanitizer build's is not
# part of `make`, whose main job runs the report).  `make report` still writes the report
# when a build fails (then with the missing hashes); report-check, in `make
# test`, takes the stamp as a prerequisite, so the suite's one make builds
# each input once (kbuild-check's included), in parallel with the other runs.
# `make report REUSED=...` writes another report in the same place, and
# removes the stamp.
REPORT_STAMP := $(REPORT_DIR)/reuse.stamp
REPORT_BUILDS = $(foreach c,$(HOST_CONFIGS),$(call hash_recording_objs,$(c),$(HOST_SRCS) $(TEST_SRCS))) \
	$(call hash_recording_objs,am1808,$(AM1808_SRCS)) $(KBUILD_OUT)/summary.txt
REPORT_SRC_DIRS := linux_compat rtos_stub tests api/library
REPORT_SRCS = $(sort $(shell find $(REPORT_SRC_DIRS) $(EV3LX_HACK_DIRS) $(DRIVER_DIRS) -type f \
	\( -name '*.c' -o -name '*.cpp' -o -name '*.h' -o -name '*.S' \) 2>/dev/null))
REPORT_KEY := $(BUILD)/report.key
$(eval $(call key_file_rule,$(REPORT_KEY),$$(shell cloc --version) $$(EV3LX_HACK_DIRS) $$(DRIVER_DIRS) \
	$$(REPORT_CONFIGS) $$(REPORT_SRCS)))

.PHONY: report report-check
report: deps-check
	@if [ -n "$(REUSED)" ]; then \
		rm -f $(REPORT_STAMP); \
		bash cloc_report/reuse_report.sh $(REPORT_DIR) "$(REUSED)" "$(GLUE)" "$(SHIM)"; \
	elif $(MAKE) --no-print-directory $(REPORT_BUILDS) > $(REPORT_DIR).log 2>&1; then \
		$(MAKE) --no-print-directory $(REPORT_STAMP) && cat $(REPORT_DIR)/reuse.md; \
	else \
		echo "report: note: a build step failed (see $(REPORT_DIR).log); hashes may be missing"; \
		rm -f $(REPORT_STAMP); \
		bash cloc_report/reuse_report.sh $(REPORT_DIR); \
	fi
	@echo "report: $(REPORT_DIR)/reuse.md, $(REPORT_DIR)/reuse.csv"

$(REPORT_STAMP): $(REPORT_KEY) $(REPORT_BUILDS) $(REPORT_SRCS) $(wildcard cloc_report/*.sh) mk/report.mk | deps-check
	@rm -f $@
	@bash cloc_report/reuse_report.sh $(REPORT_DIR) > /dev/null
	@touch $@

# The checks of the report's counts and of its proof, kept with their output
# as the report is (their inputs: the report, hence the files it counts, and
# the scripts).
report-check: $(REPORT_DIR)/check.txt
	@cat $(REPORT_DIR)/reuse.md
	@echo "report: $(REPORT_DIR)/reuse.md, $(REPORT_DIR)/reuse.csv"
	@cat $<

$(REPORT_DIR)/check.txt: $(REPORT_STAMP) $(wildcard cloc_report/*.sh)
	@{ bash cloc_report/check_totals.sh $(REPORT_DIR) && bash cloc_report/check_proof.sh; } > $@.tmp || \
		{ cat $@.tmp; rm -f $@.tmp; exit 1; }
	@mv $@.tmp $@

TEST_SUITE_EXTRA += report-check

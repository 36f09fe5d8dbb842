# `make report`: reused versus written lines, counted by cloc (cloc_report/).
#   make report                               ev3lx's three modules
#   make report REUSED="dirs/files" GLUE="dirs/files" [SHIM="dirs/files"]   any port
REPORT_DIR := $(BUILD)/report

.PHONY: report report-check
report: deps-check
	@if [ -n "$(REUSED)" ]; then \
		bash cloc_report/reuse_report.sh $(REPORT_DIR) "$(REUSED)" "$(GLUE)" "$(SHIM)"; \
	else \
		$(MAKE) --no-print-directory $(LIB_host) kbuild-check > $(REPORT_DIR).log 2>&1 || \
			echo "report: note: a build step failed (see $(REPORT_DIR).log); hashes may be missing"; \
		bash cloc_report/reuse_report.sh $(REPORT_DIR); \
	fi
	@echo "report: $(REPORT_DIR)/reuse.md, $(REPORT_DIR)/reuse.csv"

report-check: report
	@bash cloc_report/check_totals.sh $(REPORT_DIR)

TEST_SUITE_EXTRA += report-check

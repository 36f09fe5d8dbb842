# The main job `make` runs after building: the paper's experiment on the host,
# by the profile-guided ev3sim (mk/pgo.mk).  ev3sim balances the simulated
# gyro boy for 30 virtual seconds (two pushes, at 10 s and 20 s, so the plot
# shows it recovering) while a 1 kHz logger writes the gyro to the serial log,
# writes the plot, the series and the log to build/ev3sim/, then `make report`
# counts reused versus written lines; the balance summary is shown again at
# the end.
EV3SIM_OUT := $(BUILD)/ev3sim
EV3SIM_MAIN_ARGS := balance --seconds 30 --push 10:0.2 --push 20:-0.2 \
	--plot $(EV3SIM_OUT)/balance.png --csv $(EV3SIM_OUT)/balance.csv --log $(EV3SIM_OUT)/gyro.log

.PHONY: main-job
main-job: $(BUILD)/host-pgo/ev3sim
	@mkdir -p $(EV3SIM_OUT)
	@echo "=== ev3sim $(EV3SIM_MAIN_ARGS)"
	@$(BUILD)/host-pgo/ev3sim $(EV3SIM_MAIN_ARGS) | tee $(EV3SIM_OUT)/summary.txt
	@$(if $(filter 1,$(V)),echo "=== make report")
	@$(if $(filter 1,$(V)),$(MAKE) --no-print-directory report,bash mk/quiet.sh step report $(BUILD)/logs/report.log $(MAKE) --no-print-directory report)
	@echo "=== summary"
	@echo "ev3sim balance: $$(tail -n 1 $(EV3SIM_OUT)/summary.txt)"
	@echo "plot: $(EV3SIM_OUT)/balance.png  series: $(EV3SIM_OUT)/balance.csv  serial log: $(EV3SIM_OUT)/gyro.log"
	@echo "reuse report: $(BUILD)/report/reuse.md: $$(sed -n 's/^- Without the shared shim: //p' $(BUILD)/report/reuse.md)"
	@grep -q '^result=upright' $(EV3SIM_OUT)/summary.txt || { echo "main job: the robot fell"; exit 1; }

# The main job `make` runs after building: for now, a short demo of the host kernel.
.PHONY: main-job
main-job: $(BUILD)/host/rtos_demo
	$(BUILD)/host/rtos_demo

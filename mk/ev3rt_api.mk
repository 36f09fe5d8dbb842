# `make ev3rt-link-check`: an EV3RT app using the API groups ev3lx does not
# provide yet (LCD) compiles cleanly and fails to link, the
# linker naming every call.
EV3RT_NOT_YET_CALLS := lcd__ev3_lcd_draw_string lcd__ev3_image_load

.PHONY: ev3rt-link-check
ev3rt-link-check: $(LIB_host)
	@mkdir -p $(BUILD)/host/ev3rt_link
	$(Q)$(call compile,host,tests/ev3rt_link/not_yet_app.c) \
		-c tests/ev3rt_link/not_yet_app.c -o $(BUILD)/host/ev3rt_link/not_yet_app.o
	$(Q)if $(CC_host) -o $(BUILD)/host/ev3rt_link/not_yet_app $(BUILD)/host/ev3rt_link/not_yet_app.o \
		$(LIB_host) -lm > $(BUILD)/host/ev3rt_link/link.log 2>&1; then \
		echo "ev3rt-link-check: FAILED: an app using unsupported API groups linked"; exit 1; fi
	$(Q)for c in $(EV3RT_NOT_YET_CALLS); do \
		grep -q "undefined reference to \`ev3lx_not_yet_supported__$$c'" $(BUILD)/host/ev3rt_link/link.log || \
		{ echo "ev3rt-link-check: FAILED: the link error does not name $$c"; \
		  cat $(BUILD)/host/ev3rt_link/link.log; exit 1; }; done
	@echo "ev3rt-link-check: $(words $(EV3RT_NOT_YET_CALLS)) unsupported calls fail to link, each named"

TEST_SUITE_EXTRA += ev3rt-link-check

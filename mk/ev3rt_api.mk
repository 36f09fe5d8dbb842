# `make ev3rt-link-check`: an EV3RT app calling the API groups ev3lx provided
# last (LCD) compiles cleanly; while some are not provided (EV3RT_NOT_YET_CALLS,
# group__call) it fails to link, the linker naming every one, else it links.
EV3RT_NOT_YET_CALLS :=

.PHONY: ev3rt-link-check
ev3rt-link-check: $(LIB_host)
	@mkdir -p $(BUILD)/host/ev3rt_link
	$(Q)$(call compile,host,tests/ev3rt_link/not_yet_app.c) -Itests/ev3rt_link \
		-c tests/ev3rt_link/not_yet_app.c -o $(BUILD)/host/ev3rt_link/not_yet_app.o
	$(Q)if $(CC_host) -o $(BUILD)/host/ev3rt_link/not_yet_app $(BUILD)/host/ev3rt_link/not_yet_app.o \
		$(LIB_host) -lm > $(BUILD)/host/ev3rt_link/link.log 2>&1; then \
		[ -z "$(EV3RT_NOT_YET_CALLS)" ] || \
		{ echo "ev3rt-link-check: FAILED: an app using unsupported API groups linked"; exit 1; }; \
	elif [ -z "$(EV3RT_NOT_YET_CALLS)" ]; then \
		echo "ev3rt-link-check: FAILED: the app does not link"; cat $(BUILD)/host/ev3rt_link/link.log; exit 1; fi
	$(Q)for c in $(EV3RT_NOT_YET_CALLS); do \
		grep -q "undefined reference to \`ev3lx_not_yet_supported__$$c'" $(BUILD)/host/ev3rt_link/link.log || \
		{ echo "ev3rt-link-check: FAILED: the link error does not name $$c"; \
		  cat $(BUILD)/host/ev3rt_link/link.log; exit 1; }; done
	@echo "ev3rt-link-check: $(if $(EV3RT_NOT_YET_CALLS),$(words $(EV3RT_NOT_YET_CALLS)) unsupported calls fail to link and are named,the app using the LCD calls links)"

TEST_SUITE_EXTRA += ev3rt-link-check

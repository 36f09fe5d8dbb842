# `make ev3sim-lcd-check` (in make test): `ev3sim run examples/hello --lcd`
# writes the display's last frame as a PNG; decoded here independently of
# libpng (perl's core zlib), it is 178 x 128 8-bit grey with only black and
# white pixels, and its dark pixels are as many as ev3sim counted on the
# panel (lcd_dark_pixels in the summary) - hello's drawing, not a blank frame.
# The same run's --lcd-video GIF, decoded by perl too (mk/gif_frames.pl): more
# than one frame (the blank panel, then the drawing), delays adding up to the
# run's 2 s, and its last frame the PNG's.  Either on a full disk (the other
# written): a failure naming /dev/full.
LCD_CHECK_PNG := $(BUILD)/ev3sim/hello.png
LCD_CHECK_GIF := $(BUILD)/ev3sim/hello.gif

.PHONY: ev3sim-lcd-check
ev3sim-lcd-check: $(BUILD)/host/ev3sim $(LIB_host) $(EV3CFG)
	@mkdir -p $(dir $(LCD_CHECK_PNG))
	+$(Q)out=$$($(BUILD)/host/ev3sim run examples/hello --seconds 2 --quiet --lcd $(LCD_CHECK_PNG) \
		--lcd-video $(LCD_CHECK_GIF)) || \
		{ echo "ev3sim-lcd-check: FAILED: ev3sim run examples/hello exited $$?"; exit 1; }; \
	want=$$(printf '%s\n' "$$out" | tail -n 1 | sed -n 's/.* lcd_dark_pixels=\([0-9]*\) .*/\1/p'); \
	got=$$(perl mk/png_dark_pixels.pl $(LCD_CHECK_PNG)) || \
		{ echo "ev3sim-lcd-check: FAILED: $(LCD_CHECK_PNG): $$got"; exit 1; }; \
	if [ -z "$$want" ] || [ "$$got" != "$$want" ] || [ "$$got" -lt 500 ]; then \
		echo "ev3sim-lcd-check: FAILED: the PNG has $$got dark pixels, the panel $$want"; exit 1; fi; \
	echo "ev3sim-lcd-check: $(LCD_CHECK_PNG) is 178 x 128 grey with the panel's $$got dark pixels"; \
	set -- $$(perl mk/gif_frames.pl $(LCD_CHECK_GIF)) || \
		{ echo "ev3sim-lcd-check: FAILED: $(LCD_CHECK_GIF) does not decode"; exit 1; }; \
	if [ "$$1" -lt 2 ] || [ "$$2" -lt 198 ] || [ "$$2" -gt 202 ] || [ "$$3" != "$$want" ]; then \
		echo "ev3sim-lcd-check: FAILED: the GIF has $$1 frames, $$2 cs, $$3 dark pixels at the end"; exit 1; fi; \
	echo "ev3sim-lcd-check: $(LCD_CHECK_GIF): $$1 frames over $$2 cs, the last one the PNG's"
	+$(Q)for opt in --lcd --lcd-video; do \
		other=$$([ $$opt = --lcd ] && echo "--lcd-video $(LCD_CHECK_GIF)" || echo "--lcd $(LCD_CHECK_PNG)"); \
		if err=$$($(BUILD)/host/ev3sim run examples/hello --seconds 1 --quiet $$opt /dev/full $$other 2>&1 >/dev/null); \
		then echo "ev3sim-lcd-check: FAILED: $$opt /dev/full exited 0"; exit 1; fi; \
		case "$$err" in *"cannot write /dev/full"*) ;; \
		*) echo "ev3sim-lcd-check: FAILED: $$opt /dev/full: $$err"; exit 1;; esac; \
	done; \
	echo "ev3sim-lcd-check: --lcd and --lcd-video on a full disk: status 1, the file named"

TEST_SUITE_EXTRA += ev3sim-lcd-check

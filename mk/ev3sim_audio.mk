# `make ev3sim-audio-check` (in make test): `ev3sim run examples/hello --audio`
# writes what the speaker played as a WAV file; its header is 32 kHz 16-bit
# mono, and the first note (A4, 200 ms) is found at 440 Hz for 200 ms.
AUDIO_CHECK_WAV := $(BUILD)/ev3sim/hello.wav

.PHONY: ev3sim-audio-check
ev3sim-audio-check: $(BUILD)/host/ev3sim $(LIB_host) $(EV3CFG)
	@mkdir -p $(dir $(AUDIO_CHECK_WAV))
	+$(Q)out=$$($(BUILD)/host/ev3sim run examples/hello --seconds 2 --quiet --audio $(AUDIO_CHECK_WAV)) || \
		{ echo "ev3sim-audio-check: FAILED: ev3sim run examples/hello exited $$?"; exit 1; }
	$(Q)hdr=$$(od -An -v -t u4 -j 24 -N 8 $(AUDIO_CHECK_WAV) | tr -s ' '); \
	[ "$$hdr" = " 32000 64000" ] || { echo "ev3sim-audio-check: FAILED: not 32 kHz 16-bit mono ($$hdr)"; exit 1; }
	$(Q)od -An -v -t d2 -j 44 $(AUDIO_CHECK_WAV) | tr -s ' ' '\n' | grep -v '^$$' | awk ' \
		{ s = $$1; i = NR - 1 } \
		s != 0 && start < 0 { start = i } \
		start >= 0 && !done && prev < 16384 && s >= 16384 { if (!n) e0 = i; e1 = i; n++ } \
		start >= 0 && !done && s != 0 { last = i } \
		start >= 0 && !done && i - last > 640 { done = 1 } \
		{ prev = s } \
		BEGIN { start = -1 } \
		END { ms = (last + 1 - start) / 32.0; hz = (n - 1) * 32000.0 / (e1 - e0); \
		      printf "ev3sim-audio-check: first note %.2f ms at %.2f Hz\n", ms, hz; \
		      exit !(ms > 199 && ms < 201.5 && hz > 439.5 && hz < 440.8) }' || \
		{ echo "ev3sim-audio-check: FAILED: the first note is not A4 for 200 ms"; exit 1; }

TEST_SUITE_EXTRA += ev3sim-audio-check

# cfg: the app.cfg configurator (ev3cfg), a host tool the build runs.  Its
# sources are not part of libev3lx.a; mk/ev3rt_app.mk holds the rules that
# configure, compile and link an EV3RT-style app with it.
EV3CFG := $(BUILD)/tools/ev3cfg
EV3CFG_SRCS := cfg/ev3cfg.c cfg/cfg_gen.c

$(EV3CFG): $(EV3CFG_SRCS) cfg/cfg_gen.h
	@mkdir -p $(@D)
	$(quiet) CC tools $@
	$(Q)gcc -std=c11 -D_POSIX_C_SOURCE=200809L $(WARN) -O2 -g -o $@ $(EV3CFG_SRCS)

# The same under ASan+UBSan with LeakSanitizer: make cfg-error-check runs it on
# every bad configuration, so that no error path leaks or reads out of bounds.
EV3CFG_SAN := $(BUILD)/host-san/tools/ev3cfg

$(EV3CFG_SAN): $(EV3CFG_SRCS) cfg/cfg_gen.h
	@mkdir -p $(@D)
	$(quiet) CC host-san $@
	$(Q)$(CC_host-san) -std=c11 -D_POSIX_C_SOURCE=200809L $(WARN) $(CFLAGS_host-san) $(LDFLAGS_host-san) \
		-o $@ $(EV3CFG_SRCS)

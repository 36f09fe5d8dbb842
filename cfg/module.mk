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

# The library's static-API fragment, cfg/ev3lx.cfg, read by ev3cfg --library:
# the kernel_cfg.h every library source takes its IDs from (IDs at the top of
# each kind's range, as (TNUM_xxx - n)), and a kernel_cfg.c with the table
# ev3lx_cfg, which tests/cfg/test_ev3lx_fragment.c compares with the C tables
# the host boots.  A firmware built against a real HRP2 kernel gives its own
# configurator's kernel_cfg.h instead: make am1808 HRP2_DIR=... EV3LX_CFG_DIR=<dir>.
EV3LX_CFG_GEN := $(BUILD)/gen/ev3lx
EV3LX_CFG_DIR ?= $(EV3LX_CFG_GEN)
EV3LX_CFG_CPP_INC := -Iapi -Ihacks -Ilinux_compat/include -Ilinux_compat/mach-davinci/include \
	-Irtos_stub/include -Iev3_drivers
EV3LX_CFG_DEPS := cfg/ev3lx.cfg $(wildcard api/*.h hacks/*.h rtos_stub/include/*.h \
	linux_compat/include/linux_compat/*.h linux_compat/mach-davinci/include/*/*.h)

# Every library object depends on the kernel_cfg.h it was compiled with
# (mk/config.mk's obj_rule: the compiler's dependency lists leave it out, a
# header of a system directory), so the files are replaced only when their
# text changes: a header edit that leaves the IDs alone recompiles nothing.
$(EV3LX_CFG_GEN)/stamp: $(EV3CFG) $(EV3LX_CFG_DEPS)
	@mkdir -p $(@D)/new
	$(quiet) CFG ev3lx $(@D)/kernel_cfg.h
	$(Q)$(EV3CFG) --library --kernel hrp2 --symbol ev3lx_cfg -o $(@D)/new $(EV3LX_CFG_CPP_INC) \
		$(KERNEL_DEFS) cfg/ev3lx.cfg
	$(Q)for f in kernel_cfg.h kernel_cfg.c; do cmp -s $(@D)/new/$$f $(@D)/$$f || cp $(@D)/new/$$f $(@D)/$$f; done
	$(Q)touch $@
$(EV3LX_CFG_GEN)/kernel_cfg.h $(EV3LX_CFG_GEN)/kernel_cfg.c: $(EV3LX_CFG_GEN)/stamp ;
# The fragment's test includes kernel_cfg.c, which its dependency list leaves
# out like the header: a fragment edit that changes only the tables recompiles it.
$(foreach c,$(HOST_CONFIGS),$(eval $(BUILD)/$(c)/obj/tests/hacks/test_ev3lx_fragment.o: $(EV3LX_CFG_GEN)/kernel_cfg.c))

# The simulator's programs built with profile feedback: `ev3sim` and
# `bench_host` as users run them, $(BUILD)/host-pgo/{ev3sim,bench_host}.
#
# The simulator's hot paths are long chains of small, data-dependent branches
# (the register routes, the event queue, the models' fast cases) whose likely
# sides gcc cannot know from the source; a profile of real runs tells it,
# and it lays the hot paths out straight and inlines where the calls are
# frequent, across files (link-time optimisation).  Same sources, same
# semantics: neither changes what a program computes (no floating-point
# reassociation without -ffast-math, which ev3lx never uses), and `make
# bench` checks it — it compares the profile-guided ev3sim's balance run
# with the -O2 build's, byte for byte, before it reports a speed.
#
#   host-prof  the host configuration instrumented (-fprofile-generate): its
#              programs write a profile (one .gcda per object, below
#              $(BUILD)/pgo-profile) when they exit
#   host-pgo   the host configuration compiled with that profile
#              (-fprofile-use) and optimised at link time (-flto); a source
#              the training runs never reached is compiled as -O2 would
#              (-fprofile-partial-training)
#
# The training runs are the simulator's own workloads, short and with other
# seeds and settings than the benchmark's: a balancing run with a push, the
# motor and sensor applications, and the register-level bench.  The profile
# is deterministic (virtual time), so two builds of one tree are identical.
# The test suite runs on the -O2 build (build/host), whose tests would each
# pay for a link-time optimisation of the library here.
PGO_CONFIGS := host-prof host-pgo
PGO_PROGRAMS := ev3sim bench_host

# Both stages name each object's profile after its source, in one place: gcc
# keys a static function's profile by that name (-dumpbase), so a profile
# written by host-prof's object is found and valid for host-pgo's.  No
# compiler cache: the cache could not know that a profile is an input.
PGO_DATA := $(BUILD)/pgo-profile
pgo_dumpbase = -dumpbase $(PGO_DATA)/$(patsubst $(BUILD)/host-prof/%,%,$(patsubst $(BUILD)/host-pgo/%,%,$@))
# host-pgo also optimises across files (-flto: the kernel's and the
# simulator's small functions inline into their hot callers), except in
# a module (a hack with its driver), which must stay one relocatable object
# with its hidden symbols made local (mk/config.mk), and in an EV3RT app's
# objects, which are relinked and renamed (mk/ev3rt_app.mk) — both keep
# their code as compiled.
pgo_lto = $(if $(filter $(BUILD)/host-pgo/ev3rt/%,$@),,$(if $(call is_module_src,$<),,-flto=auto))
CC_host-prof       := gcc
CXX_host-prof      := g++
CFLAGS_host-prof    = $(CFLAGS_host) -fprofile-generate $(pgo_dumpbase)
CC_host-pgo        := gcc
CXX_host-pgo       := g++
# An EV3RT app's own code is compiled as in host, without the profile: its
# basic blocks are its virtual CPU time (rtos_host.h, CPU time), so a block
# structure the profile changed would change the simulation's results.
pgo_use = $(if $(filter $(BUILD)/host-pgo/ev3rt/%,$@),,-fprofile-use -fprofile-partial-training \
	-Wno-missing-profile $(pgo_dumpbase))
CFLAGS_host-pgo     = $(CFLAGS_host) $(pgo_use) $(pgo_lto)
$(foreach c,$(PGO_CONFIGS),$(eval LD_$(c) := $(LD_host))$(eval OBJCOPY_$(c) := $(OBJCOPY_host)))

PGO_PROFILE := $(BUILD)/host-pgo/profile.stamp
PGO_TRAIN    = $(BUILD)/host-prof/$(1)

# Each configuration's library (with ev3sim's gyro boy, ev3sim/module.mk) and programs.
$(foreach c,$(PGO_CONFIGS),$(eval HOST_LIB_EXTRA_$(c) += $(call EV3SIM_GYROBOY_OBJ,$(c))))
$(foreach c,$(PGO_CONFIGS),$(eval $(call host_lib_rules,$(c))))
$(foreach c,$(PGO_CONFIGS),$(eval $(call ev3sim_gyroboy_rules,$(c))))
$(foreach c,$(PGO_CONFIGS),$(foreach p,$(PGO_PROGRAMS),$(eval $(call host_program_rules,$(p),$(c)))))

# Which objects get the profile and -flto is decided per object ($@ above),
# which the configuration's compile key (its flags as text) cannot see: an
# edit here rebuilds the objects whose flags depend on that choice.
$(EV3RT_OBJS_ev3sim_gyroboy_host-pgo) $(BUILD)/host-pgo/ev3rt/ev3sim_gyroboy/kernel_cfg.o: mk/pgo.mk

# Every object of host-pgo is compiled with the profile, so after it.
$(OBJS_host-pgo) $(foreach p,$(PGO_PROGRAMS),$(patsubst %.c,$(BUILD)/host-pgo/obj/%.o,$($(p)_SRCS))) \
	$(EV3RT_OBJS_ev3sim_gyroboy_host-pgo) $(BUILD)/host-pgo/ev3rt/ev3sim_gyroboy/kernel_cfg.o: $(PGO_PROFILE)

# The training runs, each writing (or adding to) the profile of every object
# it ran.
$(PGO_PROFILE): $(foreach p,$(PGO_PROGRAMS),$(BUILD)/host-prof/$(p))
	$(quiet) PROFILE host-prof $(PGO_PROGRAMS)
	$(Q)rm -rf $(PGO_DATA)
	$(Q)$(call PGO_TRAIN,ev3sim) balance --seconds 4 --seed 11 --push 2:0.15 --no-progress > /dev/null
	$(Q)$(call PGO_TRAIN,ev3sim) motor --port B --speed 40 --seconds 2 > /dev/null
	$(Q)$(call PGO_TRAIN,ev3sim) sensors > /dev/null
	$(Q)$(call PGO_TRAIN,bench_host) 100 1 > /dev/null
	$(Q)mkdir -p $(@D) && touch $@

.PHONY: pgo
pgo: $(foreach p,$(PGO_PROGRAMS),$(BUILD)/host-pgo/$(p))

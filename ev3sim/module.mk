# ev3sim: the simulated brick as a program.  The reusable parts
# (robot physics, the balance application, the serial log channel, the run
# harness and the command line) are library sources so that tests/ev3sim/
# can run them in every configuration; only main.c is the program's own.
# Host only: nothing goes into AM1808_SRCS.
HOST_SRCS     += $(sort $(wildcard ev3sim/src/*.c))
HOST_PROGRAMS += ev3sim
ev3sim_SRCS   := ev3sim/main.c ev3sim/lcd_png.c ev3sim/lcd_gif.c ev3sim/world_file.c ev3sim/live_http.c
ev3sim_LDLIBS := -lpng -lgif -ljson-c
# build/host32/ev3sim: the simulator with the target's 32-bit types, for
# modules written for them (`volatile unsigned long *` registers); without
# the image writers (--lcd, --lcd-video) and the live view's server (--live),
# as gcc-multilib brings no 32-bit libpng, giflib or libmicrohttpd.
HOST32_PROGRAMS += ev3sim
ev3sim_SRCS_host32 := ev3sim/main.c
ev3sim_LDLIBS_host32 :=

# `ev3sim balance` runs examples/gyroboy, an EV3RT app, built by the
# configurator like any app (mk/ev3rt_examples.mk) under its own configuration
# symbol and with every other symbol made local, so the library's copy never
# meets a test's own gyroboy.
EV3SIM_GYROBOY_OBJ = $(BUILD)/$(1)/ev3rt/ev3sim_gyroboy/ev3sim_gyroboy.lib.o
$(foreach c,$(HOST_CONFIGS),$(eval HOST_LIB_EXTRA_$(c) += $(call EV3SIM_GYROBOY_OBJ,$(c))))

# The world file reader (world_file.c: json-c and libpng, the program's only)
# is tested where the configuration has both libraries, the 64-bit hosts;
# elsewhere its test finds no reader and skips.
WORLD_FILE_TEST_CONFIGS := host host-san
$(foreach c,$(WORLD_FILE_TEST_CONFIGS),\
	$(eval TEST_LDLIBS_$(c)_ev3sim/test_world_file := $(BUILD)/$(c)/obj/ev3sim/world_file.o -ljson-c -lpng)\
	$(eval $(BUILD)/$(c)/tests/ev3sim/test_world_file.t: $(BUILD)/$(c)/obj/ev3sim/world_file.o))
# --live's server links the page in (.incbin): its object depends on it in
# every configuration that compiles it.
$(foreach c,host host-san host-prof host-pgo,$(BUILD)/$(c)/obj/ev3sim/live_http.o): ev3sim/live_page.html

# ev3sim: the simulated brick as a program.  The reusable parts
# (robot physics, the balance application, the serial log channel, the run
# harness and the command line) are library sources so that tests/ev3sim/
# can run them in every configuration; only main.c is the program's own.
# Host only: nothing goes into AM1808_SRCS.
HOST_SRCS     += $(sort $(wildcard ev3sim/src/*.c))
HOST_PROGRAMS += ev3sim
ev3sim_SRCS   := ev3sim/main.c

# ev3lx — top-level build.  `make` builds everything and runs the main job;
# `make test` runs the whole suite on host, host+sanitizers, the 32-bit host
# (gcc -m32) and ARMv5 (qemu).
#
# Components describe their sources in <dir>/module.mk; build configurations,
# rules and extra targets live in mk/*.mk.  All output goes below build/.

.DEFAULT_GOAL := all
.SUFFIXES:
.DELETE_ON_ERROR:
# Keep the objects of test programs (intermediate files of a pattern chain).
.SECONDARY:
SHELL := /bin/bash

NPROC := $(shell nproc 2>/dev/null || echo 2)
ifeq ($(MAKELEVEL)$(filter -j%,$(MAKEFLAGS)),0)
MAKEFLAGS += -j$(NPROC)
endif
MAKEFLAGS += --no-builtin-rules

BUILD := build

include mk/deps.mk
include mk/config.mk
include $(sort $(wildcard */module.mk))
include mk/rules.mk
include $(filter-out mk/deps.mk mk/config.mk mk/layers.mk mk/rules.mk mk/suite.mk,$(sort $(wildcard mk/*.mk)))
# the suite's runs are every mk/*.mk's: read last
include mk/suite.mk

# `make` builds everything, then runs the main job.  Quietly (make V=1 shows
# every command and all output): the builds' output goes to build/logs/build.log,
# summed up in one line per configuration, or with its tail if it failed
# (mk/quiet.sh); the main job prints its result last.
.PHONY: all test clean main-job build-all
BUILD_ALL_CONFIGS := host host32 am1808 host-prof host-pgo
build-all: host-all $(BUILD)/host32/ev3sim am1808 pgo

ifeq ($(V),1)
all: deps-check build-all
	@$(MAKE) --no-print-directory main-job
else
all: deps-check
	@bash mk/quiet.sh build $(BUILD)/logs/build.log "$(BUILD_ALL_CONFIGS)" $(MAKE) --no-print-directory build-all
	@$(MAKE) --no-print-directory main-job
endif

test: deps-check
	@$(MAKE) --no-print-directory test-suite

clean:
	rm -rf $(BUILD)

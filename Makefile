# ev3lx — top-level build.  `make` builds everything and runs the main job;
# `make test` runs the whole suite on host, host+sanitizers and ARMv5 (qemu).
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
include $(filter-out mk/deps.mk mk/config.mk mk/layers.mk mk/rules.mk,$(sort $(wildcard mk/*.mk)))

.PHONY: all test clean main-job
all: deps-check host-all am1808 pgo
	@$(MAKE) --no-print-directory main-job

test: deps-check
	@$(MAKE) --no-print-directory test-suite

clean:
	rm -rf $(BUILD)

# appinfo.mk — an EV3RT app's Makefile.inc read as EV3RT's app build reads
# it (public sources: ev3rt-git/ev3rt-hrp2-sdk, common/Makefile.app and
# Makefile.prj.common; ev3rt-git/ev3rt-hrp3-sdk, common/Makefile.app and
# Makefile.img, with ev3rt-git/ev3rt-hrp3, target/ev3_gcc/dmloader/app/
# Makefile.lum), in a make of its own so that nothing it sets meets
# ev3lx's build, and what it says written as assignments for that build:
#
#   make -s -f mk/ev3rt/appinfo.mk APP=/abs/app PREFIX=P SDKDIR=dir \
#        [EV3RT_LIB_DIR=/abs/libs] info
#
# writes SDKDIR/appinfo.mk defining
#   P_SRCS      the app's sources: app.c (app.cpp if SRCLANG is c++), each
#               APPL_COBJS as .c and APPL_CXXOBJS as .cpp, looked for in the
#               app's directory, its APPL_DIRS (APPL_DIR, EV3RT 0.x's name) and SRCDIRS and every src/
#               below it
#   P_INCLUDES  INCLUDES, with every include/ below the app and the SDK
#               libraries' include/
#   P_CFLAGS    COPTS, CDEFS and APPL_CFLAGS (EV3RT gives them to every
#               compile of the app), less the ARM target's machine options
#               (-m...), which mean nothing to the simulator's compiler; -O0
#               under OMIT_OPTIMIZATION (EV3RT then gives no -O2)
#   P_OMIT_WALL OMIT_WARNING_ALL (EV3RT then compiles without -Wall)
#   P_LDFLAGS   LDFLAGS' library paths and linker options (-L, -Wl,), not
#               the loader's placement (-T, -Wl,-T..., TEXT_START_ADDRESS)
#   P_LDLIBS    APPL_LIBS and LIBS (but -lc, always linked)
# APPL_ASMOBJS (assembly sources: ARM code, which the simulator's host cannot
# run) is an error naming them.  OMIT_DEBUG_INFO is read and left: ev3lx
# keeps the app's debug information, which its crash reports use.
#   P_SLIBS     the SDK libraries it included, and P_SLIB_SRCS_<lib> each.
# An SDK library is included from $(EV3RT_SDK_LIB_DIR)/<lib>/Makefile and
# includes $(EV3RT_SDK_LIB_DIR)/../Makefile.slib in turn: SDKDIR/library
# holds a link to each library of ev3lx's own (api/library: libcpp-ev3, as
# EV3RT's release SDKs carry it) and of EV3RT_LIB_DIR, whose library of a
# name ev3lx has replaces ev3lx's; SDKDIR/Makefile.slib is ev3lx's
# (mk/ev3rt/Makefile.slib).  A library the app includes that neither has is
# an error naming it.
.SUFFIXES:
MAKEFLAGS += --no-builtin-rules
comma := ,

# ev3lx's SDK libraries, beside this file's tree
EV3LX_LIB_DIR := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))../../api/library)

$(if $(APP),,$(error appinfo.mk: APP is not set))
$(if $(and $(PREFIX),$(SDKDIR)),,$(error appinfo.mk: PREFIX and SDKDIR must be set))
# where the assignments go (the caller renames it to SDKDIR/appinfo.mk)
OUT ?= $(SDKDIR)/appinfo.mk

# What EV3RT's build gives a Makefile.inc before reading it.
mkfile_path := $(APP)/
SRCLANG := c
APPL_COBJS :=
APPL_CXXOBJS :=
APPL_DIRS :=
APPL_DIR :=
APPL_LIBS :=
LIBS :=
INCLUDES :=
COPTS :=
CDEFS :=
APPL_CFLAGS :=
LDFLAGS :=
SRCDIRS :=
APPL_ASMOBJS :=
OMIT_WARNING_ALL :=
OMIT_OPTIMIZATION :=
OMIT_DEBUG_INFO :=
CONFIG_EV3RT_APPLICATION := 1
# EV3RT builds an app with `make app=DIR` from its workspace: some apps'
# Makefile.inc test it (ev3rt-git/ev3rt-hrp2-sdk, common/Makefile.workspace)
app := $(notdir $(patsubst %/,%,$(APP)))
EV3RT_SDK_LIB_DIR := $(SDKDIR)/library
EV3RT_SDK_LIBS :=

# Other makes may read the same app at once (every make of the tree reads
# the examples; ev3sim runs of several apps run side by side), and the
# build compiles the libraries' sources through these links: nothing is
# removed that another make may be reading, every file and link is replaced
# in one step (rename), and only links to libraries neither EV3LX_LIB_DIR
# nor EV3RT_LIB_DIR has are dropped (a library of both is linked from
# EV3RT_LIB_DIR only, so the link never changes between two makes).  A link is made under a hidden name (.NAME.PID) before its
# rename: the sweep's glob never sees it, so one make's sweep cannot remove
# the link another make is about to rename ('mv: cannot stat
# .../library/running_average.3504' failed ev3sim-audio-check).
$(if $(shell set -e; mkdir -p '$(EV3RT_SDK_LIB_DIR)'; \
	cp '$(dir $(lastword $(MAKEFILE_LIST)))Makefile.slib' '$(SDKDIR)/Makefile.slib.'$$$$; \
	mv -f '$(SDKDIR)/Makefile.slib.'$$$$ '$(SDKDIR)/Makefile.slib'; \
	for l in '$(EV3RT_SDK_LIB_DIR)'/*; do \
		[ -L "$$l" ] || continue; \
		[ -d '$(EV3LX_LIB_DIR)'/"$${l##*/}" ] || \
		$(if $(EV3RT_LIB_DIR),[ -d '$(EV3RT_LIB_DIR)'/"$${l##*/}" ] ||) rm -f "$$l"; \
	done; \
	link_lib() { \
		ln -sfn "$$1" '$(EV3RT_SDK_LIB_DIR)'/."$$2".$$$$; \
		mv -fT '$(EV3RT_SDK_LIB_DIR)'/."$$2".$$$$ '$(EV3RT_SDK_LIB_DIR)'/"$$2"; \
	}; \
	for d in '$(EV3LX_LIB_DIR)'/*/; do \
		[ -d "$$d" ] || continue; n=$$(basename "$$d"); \
		$(if $(EV3RT_LIB_DIR),[ -d '$(EV3RT_LIB_DIR)'/"$$n" ] && continue;) \
		link_lib "$$d" "$$n"; \
	done; \
	$(if $(EV3RT_LIB_DIR),for d in '$(EV3RT_LIB_DIR)'/*/; do \
		link_lib "$$d" "$$(basename "$$d")"; \
	done;) \
	echo ok),,$(error cannot prepare $(SDKDIR)))
wanted_libs := $(shell sed -n 's|.*$$(EV3RT_SDK_LIB_DIR)/\([^/]*\)/Makefile.*|\1|p' '$(APP)/Makefile.inc' 2>/dev/null)
$(foreach l,$(wanted_libs),$(if $(wildcard $(EV3RT_SDK_LIB_DIR)/$(l)/Makefile),,$(error \
	$(APP)/Makefile.inc includes EV3RT SDK library '$(l)': give the directory holding $(l)/ \
	with ev3sim run APP_DIR --lib-dir DIR$(if $(EV3RT_LIB_DIR), ($(EV3RT_LIB_DIR) has no $(l)/Makefile)))))

-include $(APP)/Makefile.inc

main_src := $(APP)/$(if $(filter c++,$(SRCLANG)),app.cpp,app.c)
$(if $(strip $(APPL_ASMOBJS)),$(error $(APP)/Makefile.inc: APPL_ASMOBJS ($(strip $(APPL_ASMOBJS))): \
	assembly sources are ARM code for the brick, which the simulator's host cannot run))
src_dirs := $(APP) $(foreach d,$(APPL_DIRS) $(APPL_DIR) $(SRCDIRS),$(if $(filter /%,$(d)),$(d),$(APP)/$(d))) \
	$(shell find -H '$(APP)' -type d -name src)
# the source of object $(1) with extension $(2): the first directory that has it
src_of = $(firstword $(wildcard $(addsuffix /$(basename $(1))$(2),$(src_dirs))) $(APP)/$(basename $(1))$(2))
srcs := $(main_src) $(foreach o,$(APPL_COBJS),$(call src_of,$(o),.c)) \
	$(foreach o,$(APPL_CXXOBJS),$(call src_of,$(o),.cpp))

.PHONY: info
info:
	$(file >$(OUT),# $(APP)/Makefile.inc as read by mk/ev3rt/appinfo.mk)
	$(file >>$(OUT),$(PREFIX)_SRCS := $(srcs))
	$(file >>$(OUT),$(PREFIX)_INCLUDES := $(INCLUDES) $(patsubst %,-I%,$(shell find -H '$(APP)' -type d -name include)))
	$(file >>$(OUT),$(PREFIX)_CFLAGS := $(filter-out -m%,$(COPTS) $(CDEFS) $(APPL_CFLAGS)) $(if $(OMIT_OPTIMIZATION),-O0))
	$(file >>$(OUT),$(PREFIX)_OMIT_WALL := $(if $(OMIT_WARNING_ALL),1))
	$(file >>$(OUT),$(PREFIX)_LDFLAGS := $(filter -L% -Wl$(comma)%,$(filter-out -Wl$(comma)-T% -Wl$(comma)--section-start%,$(LDFLAGS))))
	$(file >>$(OUT),$(PREFIX)_LDLIBS := $(APPL_LIBS) $(filter-out -lc,$(LIBS)))
	$(file >>$(OUT),$(PREFIX)_SLIBS := $(EV3RT_SDK_LIBS))
	$(foreach l,$(EV3RT_SDK_LIBS),$(file >>$(OUT),$(PREFIX)_SLIB_SRCS_$(l) := $(EV3RT_SLIB_SRCS_$(l))))
	@:

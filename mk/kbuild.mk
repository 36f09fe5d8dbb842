# `make kbuild-check`: build every driver the hack files include (DRIVER_FILES,
# mk/report.mk) as genuine out-of-tree Linux modules against Debian's linux-headers
# with W=1 and sparse (C=2); any warning fails.  The drivers and the headers of their
# directories are copied byte-for-byte into build/kbuild/ so that kbuild's objects
# stay out of the tree; the sha256 of each file kbuild compiled (per its .cmd file)
# goes to build/kbuild/drivers.sha256 for the report's proof.

KDIR ?= $(firstword $(wildcard /usr/src/linux-headers-*-amd64))
KBUILD_OUT := $(BUILD)/kbuild
KBUILD_LEGACY_OUT := $(BUILD)/kbuild-legacy
KBUILD_DRIVERS = $(DRIVER_FILES)
KBUILD_HDRS = $(wildcard $(addsuffix *.h,$(sort $(dir $(KBUILD_DRIVERS)))))

# The kbuild checks keep their result: build/kbuild*/summary.txt, written when
# a build passed, is a stamp remade only when an input changed — the files
# kbuild compiles, the recipe (this file), the headers tree (KDIR, with its
# Makefile and .config) and the tools kbuild runs (gcc, sparse; their
# versions in the key).  A warm `make test` shows the kept summary.
KBUILD_TOOLS_KEY = $(KDIR) $(shell gcc --version 2>&1 | head -n 1; sparse --version 2>&1)
kbuild_kdir_files = $(if $(KDIR),$(wildcard $(KDIR)/Makefile $(KDIR)/.config))

KBUILD_KEY := $(BUILD)/kbuild.key
$(eval $(call key_file_rule,$(KBUILD_KEY),$$(KBUILD_TOOLS_KEY) $$(KBUILD_DRIVERS) $$(KBUILD_HDRS)))

.PHONY: kbuild-check
kbuild-check: deps-check $(KBUILD_OUT)/summary.txt $(KBUILD_LEGACY_OUT)/summary.txt
	@cat $(KBUILD_OUT)/summary.txt $(KBUILD_LEGACY_OUT)/summary.txt

$(KBUILD_OUT)/summary.txt: $(KBUILD_KEY) $(KBUILD_DRIVERS) $(KBUILD_HDRS) mk/kbuild.mk \
		$(kbuild_kdir_files) | deps-check
	@test -n "$(KDIR)" || { echo "kbuild-check: no linux-headers-*-amd64 in /usr/src (make deps)"; exit 1; }
	@rm -rf $(KBUILD_OUT) && mkdir -p $(KBUILD_OUT)
	@test -n "$(KBUILD_DRIVERS)" || { echo "kbuild-check: no hack file includes a driver"; exit 1; }
	@cp -p $(KBUILD_DRIVERS) $(KBUILD_HDRS) $(KBUILD_OUT)/
	@echo "obj-m := $(notdir $(KBUILD_DRIVERS:.c=.o))" > $(KBUILD_OUT)/Kbuild
	@echo "kbuild-check: $(notdir $(KBUILD_DRIVERS)) against $(KDIR) (W=1 C=2)" > $@.tmp
	@$(MAKE) --no-print-directory -C $(KDIR) M=$(abspath $(KBUILD_OUT)) W=1 C=2 modules \
		> $(KBUILD_OUT)/build.log 2>&1; status=$$?; \
	warnings=$$(grep -E 'warning:|error:|sparse:' $(KBUILD_OUT)/build.log | grep -v 'Skipping BTF' || true); \
	if [ $$status != 0 ] || [ -n "$$warnings" ]; then \
		cat $@.tmp $(KBUILD_OUT)/build.log; echo "kbuild-check: FAILED"; exit 1; fi; \
	ls $(KBUILD_OUT)/*.ko | sed 's/^/kbuild-check: built /' >> $@.tmp; \
	echo "kbuild-check: clean (no warnings)" >> $@.tmp; \
	for d in $(KBUILD_DRIVERS); do \
		n=$$(basename $$d .c); src=$$(sed -n "s/^source_.*$$n.o := //p" $(KBUILD_OUT)/.$$n.o.cmd | head -n 1); \
		[ -n "$$src" ] && [ -f "$$src" ] && echo "$$(sha256sum < $$src | cut -c1-64)  $$d"; \
	done > $(KBUILD_OUT)/drivers.sha256
	@mv $@.tmp $@

# `make verbatim-check`: ev3_drivers/ holds genuine Linux only — no RTOS, simulator or
# hack identifiers, and no #ifdef for them (the hack files adapt the drivers instead).
VERBATIM_FORBIDDEN := TOPPERS|sil_[a-z]|host_sim|rtos|ER_UINT|cal_svc|prb_mem|EV3LX|__HOST__|\blx_[a-z]|_hack|kernel\.h"|t_stddef

VERBATIM_FILES = $(DRIVER_FILES) $(wildcard $(addsuffix *.h,$(sort $(dir $(DRIVER_FILES))))) \
	$(wildcard ev3_drivers/Kbuild)

.PHONY: verbatim-check
verbatim-check:
	@hits=$$(grep -nE '$(VERBATIM_FORBIDDEN)' $(VERBATIM_FILES) || true); \
	if [ -n "$$hits" ]; then echo "$$hits"; \
		echo "verbatim-check: a driver mentions the RTOS, the simulator or the hacks"; exit 1; fi; \
	echo "verbatim-check: $(words $(VERBATIM_FILES)) driver files ($(DRIVER_FILES) and their directories' headers) are RTOS- and simulator-free"

# `make kbuild-legacy-check` (also run by `make kbuild-check`): the users'
# modules of tests/legacy (2.6-era idiom, the conformance drivers) built as
# out-of-tree modules against the same headers, as their users would build
# them: with kbuild's default warnings (W and C unset), which for such code are
# not fatal; the build must succeed and its warnings are listed.  Then once
# more with W=1 and sparse (C=2), where LEGO's idiom legitimately warns — its
# non-static globals and functions without prototypes (sparse's "should it be
# static?", -Wmissing-prototypes) and plain pointers made from ioremap()'s
# __iomem cookie (sparse's "cast removes address space") — and nothing else
# may: any other warning there fails.  The project's own drivers are held to
# W=1 + sparse with no warning at all (kbuild-check above).
KBUILD_LEGACY_DRIVERS := $(wildcard tests/legacy/drivers/*.c)
KBUILD_LEGACY_IDIOM := was not declared\. Should it be static\?|no previous prototype for|cast removes address space .__iomem.

KBUILD_LEGACY_KEY := $(BUILD)/kbuild-legacy.key
$(eval $(call key_file_rule,$(KBUILD_LEGACY_KEY),$$(KBUILD_TOOLS_KEY) $$(KBUILD_LEGACY_DRIVERS)))

.PHONY: kbuild-legacy-check
kbuild-legacy-check: deps-check $(KBUILD_LEGACY_OUT)/summary.txt
	@cat $(KBUILD_LEGACY_OUT)/summary.txt

$(KBUILD_LEGACY_OUT)/summary.txt: $(KBUILD_LEGACY_KEY) $(KBUILD_LEGACY_DRIVERS) mk/kbuild.mk \
		$(kbuild_kdir_files) | deps-check
	@test -n "$(KDIR)" || { echo "kbuild-legacy-check: no linux-headers-*-amd64 in /usr/src (make deps)"; exit 1; }
	@rm -rf $(KBUILD_LEGACY_OUT) && mkdir -p $(KBUILD_LEGACY_OUT)/default $(KBUILD_LEGACY_OUT)/w1
	@for d in default w1; do \
		cp -p $(KBUILD_LEGACY_DRIVERS) $(KBUILD_LEGACY_OUT)/$$d/; \
		echo "obj-m := $(notdir $(KBUILD_LEGACY_DRIVERS:.c=.o))" > $(KBUILD_LEGACY_OUT)/$$d/Kbuild; \
	done
	@$(MAKE) --no-print-directory -C $(KDIR) M=$(abspath $(KBUILD_LEGACY_OUT))/default modules \
		> $(KBUILD_LEGACY_OUT)/default/build.log 2>&1 || { cat $(KBUILD_LEGACY_OUT)/default/build.log; \
		echo "kbuild-legacy-check: FAILED: the users' modules do not build under kbuild"; exit 1; }
	@n=$$(grep -c 'warning:' $(KBUILD_LEGACY_OUT)/default/build.log || true); \
	grep 'warning:' $(KBUILD_LEGACY_OUT)/default/build.log | sed 's/^/kbuild-legacy-check: (not fatal) /' > $@.tmp; \
	echo "kbuild-legacy-check: built $$(cd $(KBUILD_LEGACY_OUT)/default && ls *.ko | tr '\n' ' ')with kbuild's default warnings ($$n warnings)" >> $@.tmp
	@log=$(KBUILD_LEGACY_OUT)/w1/build.log; \
	$(MAKE) --no-print-directory -C $(KDIR) M=$(abspath $(KBUILD_LEGACY_OUT))/w1 W=1 C=2 modules > $$log 2>&1 \
		|| { cat $@.tmp $$log; echo "kbuild-legacy-check: FAILED: the users' modules do not build with W=1 C=2"; exit 1; }; \
	other=$$(grep -E 'warning:|error:' $$log | grep -vE "$(KBUILD_LEGACY_IDIOM)" | grep -v 'Skipping BTF' || true); \
	if [ -n "$$other" ]; then cat $@.tmp; echo "$$other"; \
		echo "kbuild-legacy-check: FAILED: W=1 C=2 warnings beyond the 2.6-era idiom"; exit 1; fi; \
	echo "kbuild-legacy-check: W=1 C=2: only the idiom's warnings —" \
		"$$(grep -c 'Should it be static' $$log) non-static globals (sparse)," \
		"$$(grep -c 'no previous prototype' $$log) functions without prototypes," \
		"$$(grep -c 'removes address space' $$log) __iomem casts to plain pointers (sparse)" >> $@.tmp
	@mv $@.tmp $@

TEST_SUITE_EXTRA += verbatim-check kbuild-check

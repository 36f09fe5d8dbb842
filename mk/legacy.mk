# Modules brought by users (tests/legacy): each module — a hack file that
# includes its driver verbatim — is compiled as kbuild compiles an external
# module (Linux headers, kbuild's code generation, kbuild's default warnings,
# not fatal) and linked as one relocatable object with a private namespace:
# compiled -fvisibility=hidden, `ld -r`, then every hidden symbol localized, so
# only EXPORT_SYMBOL*s and the hack's interface (declared visibility
# "default") stay global.  Two modules defining the same global names then
# link into one program, as two .ko files load into one kernel.

LEGACY_MODULES := $(patsubst tests/legacy/%_hack.c,%,$(wildcard tests/legacy/*_hack.c))

# kbuild's default warnings for C (Linux 6.1 top-level Makefile, W= unset).
KBUILD_WARN := -Wall -Wundef -Werror=strict-prototypes -Wno-trigraphs \
	-Werror=implicit-function-declaration -Werror=implicit-int -Werror=return-type \
	-Wno-format-security -Wno-pointer-sign -Wno-unused-but-set-variable \
	-Wno-unused-const-variable -Wno-dangling-pointer -Wvla -Wno-main \
	-Wno-address-of-packed-member -Wno-stringop-truncation -Wno-array-bounds

# (LD_<config>, OBJCOPY_<config>: mk/config.mk)

# $(1) = config
define legacy_module_rules
$(BUILD)/$(1)/legacy/%.mod.o: tests/legacy/%_hack.c $(BUILD)/$(1)/compile.key
	@mkdir -p $$(@D)
	$$(quiet) MOD $(1) $$@
	$(Q)$$(CC_$(1)) $$(call nostdinc_flags,$(1),$$<) -std=gnu11 $(LINUX_INC) $(LINUX_CODEGEN) -Itests/legacy $(KBUILD_WARN) \
		$$(CFLAGS_$(1)) $(KERNEL_DEFS) -fvisibility=hidden -MMD -MP -MT $$@ -MF $$(@:.mod.o=.d) -c $$< -o $$(@:.mod.o=.o)
	$(Q)$$(call module_link,$(1),$$@,$$(@:.mod.o=.o))

LEGACY_OBJS_$(1) := $$(patsubst %,$(BUILD)/$(1)/legacy/%.mod.o,$(LEGACY_MODULES))

$(BUILD)/$(1)/tests/legacy/%.t: $(BUILD)/$(1)/obj/tests/legacy/%.o \
		$$(LEGACY_OBJS_$(1)) $$(SUPPORT_OBJS_$(1)) $$(LIB_$(1))
	@mkdir -p $$(@D)
	$$(quiet) LD $(1) $$@
	$(Q)$$(CC_$(1)) $$(CFLAGS_$(1)) $$(LDFLAGS_$(1)) -o $$@ $$< $$(LEGACY_OBJS_$(1)) $$(SUPPORT_OBJS_$(1)) \
		-Wl,--start-group $$(LIB_$(1)) -Wl,--end-group -lm

-include $$(LEGACY_OBJS_$(1):.mod.o=.d)
endef
$(foreach c,$(HOST_CONFIGS) am1808,$(eval $(call legacy_module_rules,$(c))))

# On the AM1808 the modules are built and given their private namespaces too
# (no test runs there: host_sim is not on the brick).
TEST_SUITE_EXTRA_DEPS += $(LEGACY_OBJS_am1808)

# The layers the README draws, as the build enforces them (included by
# mk/config.mk; the checks are in mk/layer_checks.mk).
#
# Every source file belongs to the layer of its top directory (LAYER_OF) and is
# compiled with that layer's include directories only (INC_<layer>): its own
# public headers and those of the layers it may use.  `make layer-check` (in
# `make test`) then checks what the include path cannot: every #include line,
# resolved the way the compiler would (quotes: the file's directory first), and
# every link edge between the layers' objects (host and AM1808 libraries) must
# follow an edge of LAYER_EDGES.  Test programs, benches and ev3sim sit on top
# and may use everything they are given.

# Public header directories of each layer.
HDR_rtos_stub    := rtos_stub/include
HDR_linux_compat := linux_compat/include linux_compat/mach-davinci/include
HDR_ev3_drivers  := ev3_drivers
HDR_hacks        := hacks
HDR_api          := api
HDR_host_sim     := host_sim/include
HDR_ev3sim       := ev3sim/include
HDR_cfg          := cfg
HDR_examples     :=
HDR_tests        := tests/lib

# Which layers each layer may use (include or link).  hacks sees the drivers it
# includes verbatim; api uses the hacks' wrapper headers and its configuration
# includes the drivers' (ev3_drivers_cfg); drivers see linux_compat's Linux
# headers only (checked in mk/layer_check.sh); target code never sees host_sim
# or tests.  LAYER_PATH_<layer>: header directories on a layer's include path
# only for what the headers it may include include in turn (the wrapper
# headers' user-space ABI headers live with the drivers): a direct include
# from there is still a violation.
LAYER_EDGES_rtos_stub    :=
LAYER_EDGES_linux_compat := rtos_stub
LAYER_EDGES_ev3_drivers  := linux_compat
LAYER_EDGES_hacks        := ev3_drivers linux_compat rtos_stub
LAYER_EDGES_api          := hacks rtos_stub
LAYER_PATH_api           := ev3_drivers
LAYER_EDGES_host_sim     := rtos_stub
LAYER_EDGES_am1808       := api hacks linux_compat rtos_stub
LAYER_PATH_am1808        := ev3_drivers
LAYER_EDGES_ev3sim       := api hacks ev3_drivers linux_compat rtos_stub host_sim examples
LAYER_EDGES_cfg          :=
LAYER_EDGES_examples     := api rtos_stub
LAYER_EDGES_bench        := api hacks ev3_drivers linux_compat rtos_stub host_sim
LAYER_EDGES_tests        := api hacks ev3_drivers linux_compat rtos_stub host_sim ev3sim examples cfg

LAYERS := rtos_stub linux_compat ev3_drivers hacks api host_sim am1808 ev3sim cfg examples bench tests

# host_sim's own layers, lowest first (host_sim/src/<sublayer>/): an object
# may use only the symbols of its own sublayer and those below it, so no SoC
# model calls a board function and nothing below reaches up.
SUBLAYERS_host_sim := core soc ev3 harness bench

# The layer of a path: its top directory.
LAYER_OF = $(firstword $(subst /, ,$(1)))

# -I flags of a layer: its own headers, then those of the layers it may use
# (Linux headers come with LINUX_INC for the code in LINUX_DIRS).
layer_inc = $(addprefix -I,$(HDR_$(1)) $(foreach l,$(LAYER_EDGES_$(1)) $(LAYER_PATH_$(1)),$(if $(filter linux_compat,$(l)),,$(HDR_$(l)))))

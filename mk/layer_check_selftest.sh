#!/bin/bash
# layer_check_selftest.sh WORKDIR — layer_check.sh finds what it must: on a
# small tree of fake layers, each forbidden edge is reported and a clean tree
# passes.  Run by `make layer-check` before the real check.
set -u
here=$(cd "$(dirname "$0")" && pwd)
work=$1
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

export LAYERS="rtos_stub linux_compat ev3_drivers hacks api host_sim"
export HDR_rtos_stub=rtos_stub/include HDR_linux_compat=linux_compat/include HDR_ev3_drivers=ev3_drivers
export HDR_hacks=hacks HDR_api=api HDR_host_sim=host_sim/include
export LAYER_EDGES_rtos_stub="" LAYER_EDGES_linux_compat=rtos_stub LAYER_EDGES_ev3_drivers=linux_compat
export LAYER_EDGES_hacks="ev3_drivers linux_compat rtos_stub" LAYER_EDGES_api="hacks ev3_drivers rtos_stub"
export LAYER_EDGES_host_sim=rtos_stub SUBLAYERS_host_sim="core soc ev3"

mkdir -p rtos_stub/include linux_compat/include/linux linux_compat/include/linux_compat ev3_drivers \
	hacks api host_sim/include/host_sim host_sim/src/core host_sim/src/soc obj
echo '/* k */' > rtos_stub/include/kernel.h
echo '/* h */' > rtos_stub/include/rtos_host.h
echo '/* l */' > linux_compat/include/linux/list.h
echo '/* own */' > linux_compat/include/linux_compat/context.h
echo '/* b */' > host_sim/include/host_sim/board.h
echo '/* w */' > hacks/pwm_hack.h
printf '#include <linux/list.h>\nint d;\n' > ev3_drivers/d_x.c
printf '#include "d_x.c"\n#include "kernel.h"\n' > hacks/x_hack.c
printf '#include "pwm_hack.h"\n#include "kernel.h"\n' > api/motor.c
printf '#include "kernel.h"\nvoid lc(void);\nvoid lc(void) {}\n' > linux_compat/lc.c

status=0
expect() {  # expect PATTERN: the check fails and names PATTERN
	local out
	if out=$(bash "$here/layer_check.sh" obj 2>&1); then
		echo "layer-check selftest: no violation reported, expected: $1"; status=1
	elif ! grep -q -- "$1" <<<"$out"; then
		echo "layer-check selftest: expected '$1', got:"; echo "$out"; status=1
	fi
}
clean() {
	local out
	out=$(bash "$here/layer_check.sh" obj 2>&1) || { echo "layer-check selftest: clean tree fails:"; echo "$out"; status=1; }
}

clean
printf '#include "host_sim/board.h"\n' > api/bad.c
expect 'api/bad.c:1: api includes host_sim/include/host_sim/board.h'
rm api/bad.c
printf '#include <linux_compat/context.h>\n' > ev3_drivers/bad.h
expect 'ev3_drivers/bad.h:1: the driver includes linux_compat/include/linux_compat/context.h'
rm ev3_drivers/bad.h
printf '#include "../hacks/x_hack.c"\n' > api/bad.c
expect "another layer's source file"
rm api/bad.c
printf '#include "rtos_host.h"\n' > linux_compat/bad.c
expect 'target code includes the host kernel'
rm linux_compat/bad.c

mkdir -p obj/linux_compat obj/host_sim/src/core obj/host_sim/src/soc
printf 'int hs_map(void);\nint hs_map(void) { return 1; }\n' > host_sim/src/soc/map.c
printf 'int hs_map(void);\nint lx_io(void);\nint lx_io(void) { return hs_map(); }\n' > linux_compat/io.c
gcc -c host_sim/src/soc/map.c -o obj/host_sim/src/soc/map.o
gcc -c linux_compat/io.c -o obj/linux_compat/io.o
expect 'linux_compat/io.o uses hs_map of host_sim/src/soc/map.o'
rm obj/linux_compat/io.o
printf 'int hs_map(void);\nint hs_space(void);\nint hs_space(void) { return hs_map(); }\n' > host_sim/src/core/space.c
gcc -c host_sim/src/core/space.c -o obj/host_sim/src/core/space.o
expect "host_sim/src/core/space.o uses hs_map of host_sim/src/soc/map.o (host_sim's core may not use its soc)"
rm obj/host_sim/src/core/space.o
clean

[ "$status" = 0 ] && echo "layer-check selftest: every kind of forbidden edge is reported"
exit "$status"

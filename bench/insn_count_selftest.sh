#!/bin/bash
# insn_count_selftest.sh COUNTER — checks insn_count on a hand-made QEMU log:
# a measured call with a call into counted code that tail-calls a register
# access (excluded below it, counted as 1), a C library call, a block QEMU
# took back ("Stopped execution"), and a call outside the window (not counted).
set -u -o pipefail
counter=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

printf '%s\n' \
	"00001000 00000040 T caller	/src/bench/bench_arm.c:1" \
	"00001100 00000010 T bench_window_open	/src/bench/bench_arm.c:2" \
	"00001200 00000010 T bench_window_close	/src/bench/bench_arm.c:3" \
	"00002000 00000040 T ev3lx_motor_set_speed	/src/api/src/motor.c:1" \
	"00003000 00000020 T helper	/src/linux_compat/src/helper.c:1" \
	"00004000 00000020 T sil_host_write	/src/rtos_stub/src/host/sil_host.c:1" \
	"00005000 00000020 T hs_model	/src/host_sim/src/model.c:1" \
	"00006000 00000020 T memcpy" > "$dir/syms"

# block: address, instructions "mnemonic operands"...
block() {
	local addr=$1; shift
	echo "----------------"
	echo "IN: "
	for insn in "$@"; do
		printf '0x%08x:  e1a00000  %s\n' $((addr)) "$insn"
		addr=$((addr + 4))
	done
	echo
}
trace() { printf 'Trace 0: 0x7f0000000000 [00000480/%08x/00000000/00000200] \n' $(($1)); }
{
	block 0x1000 "mov r0, r1" "bl #0x2000";   trace 0x1000    # a call before the window: not counted
	block 0x2000 "mov r0, r0" "mov r1, r1" "bl #0x3000"; trace 0x2000
	block 0x3000 "mov r2, r2" "b #0x4000";    trace 0x3000
	block 0x4000 "bl #0x5000";                trace 0x4000
	block 0x5000 "add r0, r0, #1" "add r0, r0, #1" "add r0, r0, #1" "bx lr"; trace 0x5000
	block 0x4004 "bx lr";                     trace 0x4004
	block 0x200c "mov r0, r0" "bl #0x6000";   trace 0x200c
	block 0x6000 "ldr r3, [r1]" "str r3, [r0]" "bx lr"; trace 0x6000
	block 0x2014 "pop {r4, pc}";              trace 0x2014
	block 0x1008 "bl #0x1100";                trace 0x1008
	block 0x1100 "bx lr";                     trace 0x1100
	block 0x100c "mov r0, #60" "bl #0x2000";  trace 0x100c
	trace 0x2000; trace 0x3000; trace 0x4000; trace 0x5000; trace 0x4004; trace 0x200c
	trace 0x6000; trace 0x2014
	echo "Stopped execution of TB chain before 0x7f0000000000 [00002014] ev3lx_motor_set_speed"
	trace 0x2014
	block 0x1014 "bl #0x1200";                trace 0x1014
	block 0x1200 "bx lr";                     trace 0x1200
	block 0x1018 "mov r0, r0";                trace 0x1018
} > "$dir/log"

"$counter" -r /src "$dir/syms" -m ev3lx_motor_set_speed -w bench_window_open bench_window_close \
	< "$dir/log" > "$dir/out" || { echo "insn_count self-test: the counter failed"; exit 1; }
# 17 raw (3+2+1+4+1+2+3+1), 12 counted (3+2, the access as 1, 2+3+1); hs_model not counted
expect() {
	grep -qx "$1" "$dir/out" || { echo "insn_count self-test: no line '$1' in:"; cat "$dir/out"; exit 1; }
}
expect "call,ev3lx_motor_set_speed,1,17.0,17,17,12.0,12,12,12,12,12"
expect "class,ev3lx_motor_set_speed,api,6.0,6.0"
expect "class,ev3lx_motor_set_speed,linux_compat,2.0,2.0"
expect "class,ev3lx_motor_set_speed,access,2.0,1.0"
expect "class,ev3lx_motor_set_speed,sim,4.0,0.0"
expect "libc,ev3lx_motor_set_speed,ev3lx_motor_set_speed,3.0"
expect "log,23,43,17,1"
echo "insn_count self-test: ok"

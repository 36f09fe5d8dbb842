#!/bin/sh
# gdb_check.sh — `ev3sim run --debug` and the project's gdb script
# (tools/gdb/ev3lx-tasks.py), as docs/ev3sim.md's session uses them: the app
# is built at -O0 under a build of its own, gdb stops at a breakpoint in an
# app task and reads its variables, and `ev3lx-tasks` lists the app's tasks
# with their states (TAP; make ev3sim-gdb-check runs it with EV3SIM, the
# program, and ROOT, the source tree).
set -u
: "${EV3SIM:?}" "${ROOT:?}"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
n=0
failed=0

# ok STATUS NAME [FILE]: one TAP line; FILE shown on failure
ok() {
	n=$((n + 1))
	if [ "$1" = 0 ]; then
		echo "ok $n - $2"
	else
		echo "not ok $n - $2"
		failed=$((failed + 1))
		[ $# -gt 2 ] && sed 's/^/# /' "$3"
	fi
}

# has FILE PATTERN: FILE holds a line matching the extended regular expression
has() {
	grep -Eq "$2" "$1"
}

"$EV3SIM" run "$ROOT/examples/blink" --debug --seconds 1 --quiet > "$WORK/run.txt" 2> "$WORK/run.err"
ok $? "ev3sim run --debug builds and runs examples/blink" "$WORK/run.err"
line=$(grep '^ev3sim run: built at -O0 for gdb: ' "$WORK/run.err")
runner=$(printf '%s\n' "$line" | sed -n 's/.* --args \([^ ]*\) .*/\1/p')
case "$runner" in
*-debug/run_blink-*-debug) ok 0 "it names a runner of its own, under a -debug key ($runner)";;
*) ok 1 "it names a runner of its own, under a -debug key" "$WORK/run.err";;
esac
has "$WORK/run.txt" '^app=blink .* bugs=0 '
ok $? "the debug build's run ends with its summary" "$WORK/run.txt"

# the session of docs/ev3sim.md: a breakpoint in the blink handler's task, its
# second activation, a variable, the backtrace into the kernel, the task list
gdb -batch -nx -x "$ROOT/tools/gdb/ev3lx-tasks.py" -ex 'break blink_cyc' -ex run -ex continue \
	-ex 'print ticks' -ex 'info source' -ex 'bt 3' -ex 'ev3lx-tasks' --args "$runner" --seconds 1 --quiet \
	> "$WORK/gdb.txt" 2>&1
has "$WORK/gdb.txt" '^Breakpoint 1, blink_cyc \(exinf=0\) at .*app\.c:[0-9]+'
ok $? "gdb stops at the breakpoint in the app's handler task, at a line of app.c" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^Producer is .* -O0( -[^O][^ ]*)*\.$'
ok $? "app.c was compiled -O0 last (gdb's info source: its producer)" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^\$1 = 1$'
ok $? "at -O0 it reads the app's variable (ticks = 1 at the second period)" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^#2 .* task_entry \(\) at rtos_stub/src/host/task\.c:'
ok $? "the backtrace reaches the kernel's task entry" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^ev3lx tasks at 250\.[0-9]{6} ms of virtual time$'
ok $? "ev3lx-tasks says when (the second blink period, 250 ms)" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^ +1  MAIN_TASK +app +[0-9]+  waiting +wake-up \(slp_tsk\)$'
ok $? "MAIN_TASK waits in slp_tsk for BACK" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^ +2  BLINK_CYC +app +[0-9]+  running$'
ok $? "BLINK_CYC's task is the running one" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^ +3  REPORT_CYC +app +[0-9]+  waiting +wake-up \(slp_tsk\)$'
ok $? "REPORT_CYC's task waits for its period" "$WORK/gdb.txt"
has "$WORK/gdb.txt" '^ +[0-9]+  lx_worker +kernel +4  waiting +wake-up \(slp_tsk\)$' &&
	has "$WORK/gdb.txt" '^ +[0-9]+  ev3api LCD start +app +[0-9]+  waiting +delay \(dly_tsk\), with a timeout$'
ok $? "the platform's tasks too: linux_compat's worker in the kernel domain, a delay with its timeout" "$WORK/gdb.txt"

gdb -batch -nx -x "$ROOT/tools/gdb/ev3lx-tasks.py" -ex 'ev3lx-tasks' --args "$runner" > "$WORK/nogo.txt" 2>&1
has "$WORK/nogo.txt" '^ev3lx-tasks: the program is not running; run it and stop it'
ok $? "before the program runs, ev3lx-tasks says why it cannot list" "$WORK/nogo.txt"

echo "1..$n"
[ "$failed" = 0 ]

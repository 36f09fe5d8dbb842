#!/bin/sh
# adversarial_check.sh — bad input to ev3sim and its configurator, as a user
# brings it, each answered with a clear message and the right exit status,
# never a hang or a silent success (TAP; make adversarial-check runs it with
# EV3SIM, the program, ROOT, the source tree, and WORK, a scratch directory
# it empties).  The app paths make cannot hold, two apps of one name and
# parallel first runs are app_paths_check.sh's.
#
#   status 0 a good run; 1 a failed build or output; 2 a bad command line;
#   3 a stalled task; 4 a crash; 5 a stack overrun (docs/ev3sim.md)
set -u
: "${EV3SIM:?}" "${ROOT:?}" "${WORK:?}"
SAY="$ROOT/tests/ev3sim/apps/say"
n=0

# check WANT_STATUS TEXT NAME: the last run (status in $st, output in out.txt)
# ended with WANT_STATUS and said TEXT (a grep pattern)
check() {
	n=$((n + 1))
	if [ "$st" = "$1" ] && grep -q -- "$2" "$WORK/out.txt"; then
		echo "ok $n - $3 (status $st)"
	else
		echo "not ok $n - $3: status $st (want $1), looked for \"$2\" in:"
		sed 's/^/# /' "$WORK/out.txt" | tail -n 15
	fi
}

# run ARGS...: ev3sim with ARGS, at most 120 s of wall time
run() {
	timeout 120 "$EV3SIM" "$@" > "$WORK/out.txt" 2>&1
	st=$?
}

# bad_cfg NAME LINE: the say app with LINE added to its app.cfg's domain block
bad_cfg() {
	mkdir -p "$WORK/$1"
	cp "$SAY/app.c" "$SAY/app.h" "$WORK/$1/"
	sed "s|^DOMAIN(TDOM_APP) {|DOMAIN(TDOM_APP) {\n$2|" "$SAY/app.cfg" > "$WORK/$1/app.cfg"
}

echo "1..23"
rm -rf "$WORK" && mkdir -p "$WORK"

# -- the configurator refuses what TOPPERS's would, naming file and line
bad_cfg domian 'DOMIAN(TDOM_APP) { }'
run run "$WORK/domian" --seconds 1
check 1 "app.cfg:[0-9]*:[0-9]*: error: DOMIAN: unknown static API (did you mean DOMAIN?)" "a misspelt DOMIAN"
bad_cfg domain_case 'Domain(TDOM_APP);'
run run "$WORK/domain_case" --seconds 1
check 1 "app.cfg:[0-9]*:[0-9]*: error: Domain: unknown static API" "Domain( in the wrong case"
bad_cfg junk 'this is not a static API'
run run "$WORK/junk" --seconds 1
check 1 "app.cfg:[0-9]*:[0-9]*: error:" "a junk line"
mkdir -p "$WORK/bytes" && cp "$SAY/app.c" "$SAY/app.h" "$WORK/bytes/"
head -c 300 /dev/urandom > "$WORK/bytes/app.cfg"
printf '\001\377\000garbage\n' >> "$WORK/bytes/app.cfg"
run run "$WORK/bytes" --seconds 1
check 1 "app.cfg:[0-9]*:.*error" "random bytes for an app.cfg"
bad_cfg huge_stack 'CRE_TSK(HUGE_TASK, { TA_NULL, 0, main_task, MAIN_PRIORITY, 1024 * 1024 * 1024, NULL });'
run run "$WORK/huge_stack" --seconds 1
check 1 "CRE_TSK(HUGE_TASK): stksz out of range" "a 1 GiB stack"
bad_cfg one_name 'CRE_SEM(SAME_NAME, { TA_NULL, 0, 1 });\nCRE_FLG(SAME_NAME, { TA_NULL, 0 });'
run run "$WORK/one_name" --seconds 1
check 1 "SAME_NAME" "one name for a semaphore and an eventflag"

# -- the two kernel profiles: a configuration is one kernel's, an option is checked
bad_cfg mixed 'CRE_CYC(OLD_CYC, { TA_STA, 0, main_task, 100, 0 });\nCRE_CYC(NEW_CYC, { TA_STA, { TNFY_ACTTSK, MAIN_TASK }, 100000U, 0U });'
run run "$WORK/mixed" --seconds 1
check 1 "app.cfg:[0-9]*: error: CRE_CYC(NEW_CYC): the notification form .* is TOPPERS/HRP3's, but CRE_CYC(OLD_CYC) at .*app.cfg:[0-9]* is TOPPERS/HRP2's" \
	"HRP2's and HRP3's CRE_CYC in one app.cfg"
bad_cfg nfy 'CRE_CYC(SET_CYC, { TA_STA, { TNFY_SETFLG, MAIN_TASK }, 100000U, 0U });'
run run "$WORK/nfy" --seconds 1
check 1 "app.cfg:[0-9]*: error: CRE_CYC(SET_CYC): too few parameters for nfymode TNFY_SETFLG" "a notification short of a parameter"
run run "$ROOT/examples/notify" --kernel hrp2 --seconds 1
check 1 "is TOPPERS/HRP3's, but the app is built for the HRP2 profile (--kernel hrp2)" "an HRP3 app built as HRP2's"
run run "$SAY" --kernel hrp4 --seconds 1
check 2 "--kernel 'hrp4': expected hrp2, hrp3 or auto" "an unknown kernel profile"
mkdir -p "$WORK/asm" && cp "$SAY/app.c" "$SAY/app.h" "$SAY/app.cfg" "$WORK/asm/"
echo 'APPL_ASMOBJS += start.o' > "$WORK/asm/Makefile.inc"
run run "$WORK/asm" --seconds 1
check 1 "APPL_ASMOBJS (start.o): assembly sources are ARM code" "an app with assembly sources"

# -- an app that misbehaves ends the run with its own status, naming the task
for case in "stall 3 stall" "null 4 main_task" "recurse 5 stack.overflow:.task.MAIN_TASK" "big-locals 5 task.MAIN_TASK.used"; do
	set -- $case
	export EV3LX_MISBEHAVE="$1" EV3LX_STALL_MS=500
	run run "$ROOT/tests/ev3sim/apps/misbehave" --seconds 2
	check "$2" "$3" "an app that does $1"
done
unset EV3LX_MISBEHAVE EV3LX_STALL_MS

# -- an app's file calls reach the SD card's directory, not the host's
mkdir -p "$WORK/card"
cd "$WORK" || exit 1
run run "$ROOT/tests/ev3sim/apps/files" --sd "$WORK/card" --seconds 2
cd "$ROOT" || exit 1
n=$((n + 1))
if [ "$st" = 0 ] && [ -f "$WORK/card/ev3rt/files/log.txt" ] && [ ! -e "$WORK/ev3rt" ]; then
	echo "ok $n - fopen(\"/ev3rt/files/log.txt\") writes the card (--sd), not the current directory"
else
	echo "not ok $n - fopen on the card: status $st"; sed 's/^/# /' "$WORK/out.txt" | tail -n 10
fi

# -- every output error is an error; no output hangs the run
run motor --port A --speed 50 --seconds 1
check 0 "" "a good run (the reference)"
timeout 120 "$EV3SIM" motor --port A --speed 50 --seconds 1 > /dev/full 2> "$WORK/out.txt"
st=$?
check 1 "No space left on device" "standard output on a full disk"
mkfifo "$WORK/fifo"
run balance --seconds 1 --no-progress --csv "$WORK/fifo"
check 1 "a FIFO no process is reading" "a FIFO nobody reads as --csv"

# -- options: the limits the help gives
faults=""
for i in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16; do faults="$faults --fault gyro-noise:0.1"; done
run balance --seconds 1 --no-progress $faults
check 0 "result=" "16 faults, as the help promises"
run balance --seconds 1 --no-progress $faults --fault gyro-noise:0.1
check 2 "more than 16 faults" "a 17th fault"

# -- a blocked API call shows in the main job's summary, whichever task made it
run balance --seconds 10 --no-progress --fault unplug:2:3s:3s
n=$((n + 1))
blocked=$(tail -n 1 "$WORK/out.txt" | tr ' ' '\n' | sed -n 's/^api_blocked=//p')
if [ "$st" = 0 ] && [ "${blocked:-0}" -gt 0 ]; then
	echo "ok $n - the gyro unplugged for 3 s: api_blocked=$blocked"
else
	echo "not ok $n - the gyro unplugged for 3 s: status $st, api_blocked=${blocked:-none}"
fi

# -- the build: a make of a built tree leaves every configuration's compile
# key as it is (a key rewritten each time recompiled its whole
# configuration on every make: the profile-guided one did)
keys="build/host/compile.key build/host-pgo/compile.key build/host-prof/compile.key build/am1808/compile.key"
make -s --no-print-directory -C "$ROOT" $keys > "$WORK/out.txt" 2>&1
before=$(cd "$ROOT" && stat -c '%n %y' $keys)
sleep 1
make -s --no-print-directory -C "$ROOT" $keys >> "$WORK/out.txt" 2>&1
st=$?
after=$(cd "$ROOT" && stat -c '%n %y' $keys)
n=$((n + 1))
if [ "$st" = 0 ] && [ "$before" = "$after" ]; then
	echo "ok $n - a second make rewrites no configuration's compile key"
else
	echo "not ok $n - compile keys rewritten by a second make (status $st):"
	printf '%s\n%s\n' "$before" "$after" | sed 's/^/# /'
fi

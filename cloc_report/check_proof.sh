#!/usr/bin/env bash
# check_proof.sh — the report's compile-time proof rejects what it must: a driver
# record that differs from the tree, and a missing one, each make the report fail
# and name the build.  Runs the report on copies of one driver's records.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
drv=ev3_drivers/d_pwm.c
fail=0
run() {  # run EXPECTED-WORD: the report on $tmp/records must fail and print the word
	local log=$tmp/log
	if RECORDS_ROOT=$tmp/records BUILD_CONFIGS=host \
		bash cloc_report/reuse_report.sh "$tmp/out" "$drv" hacks/pwm_hack.c > "$log" 2>&1; then
		echo "not ok - the report accepted a $1 record"; fail=1
	elif grep -q "host build" "$log" && grep -q "host:$1" "$log"; then
		echo "ok - a $1 compile-time record fails the report (host:$1)"
	else
		echo "not ok - a $1 record: the report failed without naming it"; cat "$log"; fail=1
	fi
}
mkdir -p "$tmp/records/host/obj/hacks"
echo "$(printf '0%.0s' $(seq 64))  $drv" > "$tmp/records/host/obj/hacks/pwm_hack.drivers"
run DIFFERS
rm -f "$tmp/records/host/obj/hacks/pwm_hack.drivers"
run MISSING
sha256sum "$drv" > "$tmp/records/host/obj/hacks/pwm_hack.drivers"
if RECORDS_ROOT=$tmp/records BUILD_CONFIGS=host bash cloc_report/reuse_report.sh "$tmp/out" "$drv" hacks/pwm_hack.c \
	> "$tmp/log" 2>&1; then echo "ok - a matching record passes"
else echo "not ok - a matching record fails"; cat "$tmp/log"; fail=1; fi
exit $fail

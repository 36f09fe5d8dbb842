#!/usr/bin/env bash
# check_proof.sh — the report's compile-time proof rejects what it must: a driver
# record that differs from the tree, and a missing one, each make the report fail
# and name the build.  Runs the report on copies of one driver's records; and a
# users' module that differs from its pristine source, or has none recorded.
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
# The users' modules (tests/legacy): one whose source is not its pristine
# one, and one without a pristine record, each fail the whole report (run on
# the builds' own records, as make report does).
if [ -n "${LEGACY_PRISTINE:-}" ] && [ -f "$LEGACY_PRISTINE" ]; then
	legacy_drv=$(awk 'NR == 1 { print $2 }' "$LEGACY_PRISTINE")
	legacy_run() {  # legacy_run WHAT EXPECTED-TEXT: the report with $tmp/pristine must fail, saying it
		if LEGACY_PRISTINE=$tmp/pristine bash cloc_report/reuse_report.sh "$tmp/legacy-out" > "$tmp/log" 2>&1; then
			echo "not ok - the report accepted a users' module $1"; fail=1
		elif grep -q "$legacy_drv$2" "$tmp/log"; then
			echo "ok - a users' module $1 fails the report ($legacy_drv$2)"
		else
			echo "not ok - a users' module $1: the report failed without saying so"; cat "$tmp/log"; fail=1
		fi
	}
	awk -v f="$legacy_drv" '$2 == f { $1 = "0000000000000000000000000000000000000000000000000000000000000000" } { print $1 "  " $2 }' \
		"$LEGACY_PRISTINE" > "$tmp/pristine"
	legacy_run "edited since its pristine source" " differs from its pristine source"
	awk -v f="$legacy_drv" '$2 != f' "$LEGACY_PRISTINE" > "$tmp/pristine"
	legacy_run "without a pristine record" ": no pristine sha256 recorded"
fi
exit $fail

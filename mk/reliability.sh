#!/bin/bash
# reliability.sh EV3SIM — prints the figures docs/reliability.md gives, as
# markdown, from runs made now: the fault sweep (ev3sim balance for 60 s
# under each link fault, seeds 1-8, every run's status and summary) and the
# fuzz corpora's sizes (tests/fuzz/corpus), with the last campaign's
# executions if build/fuzz/report.txt has them (make fuzz).
set -euo pipefail
ev3sim=$1
faults="uart-bit-errors:0.001 uart-bit-errors:0.01 uart-bit-errors:0.05 uart-drop:0.05 uart-dup:0.05"
field() { printf '%s\n' "$2" | tr ' ' '\n' | sed -n "s/^$1=//p"; }

echo "### The fault sweep ($(date -u +%Y-%m-%d), \`make reliability\`)"
echo
echo "| fault | runs | status 0 | bug reports | upright | fell | seed 1: frames, check / size errors, resyncs, reconnects |"
echo "|---|---:|---:|---:|---:|---:|---|"
for f in $faults; do
	runs=0 ok=0 bugs=0 up=0 fell=0 first=
	for seed in 1 2 3 4 5 6 7 8; do
		runs=$((runs + 1))
		if line=$("$ev3sim" balance --seconds 60 --seed "$seed" --fault "$f" --no-progress 2>/dev/null | tail -n 1); then
			ok=$((ok + 1))
		fi
		bugs=$((bugs + $(field bugs "$line")))
		case "$(field result "$line")" in
		upright) up=$((up + 1));;
		fell) fell=$((fell + 1));;
		esac
		[ -n "$first" ] || first="$(field gyro_frames "$line") frames, $(field gyro_check_errors "$line") / $(field gyro_size_errors "$line"), $(field gyro_resyncs "$line"), $(field gyro_reconnects "$line")"
	done
	echo "| \`$f\` | $runs | $ok | $bugs | $up | $fell | $first |"
done
echo
echo "### The fuzz corpora (replayed by \`make test\` in every configuration)"
echo
echo "| harness | corpus inputs | last campaign (build/fuzz/report.txt) |"
echo "|---|---:|---|"
for d in tests/fuzz/corpus/*/; do
	n=$(basename "$d")
	campaign=$(sed -n "s/^$n //p" build/fuzz/report.txt 2>/dev/null || true)
	echo "| \`$n\` | $(ls "$d" | wc -l) | ${campaign:-not run here} |"
done

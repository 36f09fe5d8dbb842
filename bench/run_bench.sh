#!/bin/bash
# run_bench.sh MODE OUT BUILD — runs the benchmarks of `make bench` (MODE full)
# or `make bench-quick` (MODE quick), prints the table, writes OUT/bench.csv.
# docs/bench.md explains every figure.  Quick mode asserts only that every
# figure was produced (never a speed); both modes fail if a measured call
# returned an error or a measurement is missing.
#   BENCH_SINGLESTEP=1   count with qemu -singlestep (one instruction per logged
#                        block) instead of whole blocks: slower, same counts
set -u -o pipefail
mode=$1 out=$2 build=$3

case $mode in
full)  calls=10000 virtual_s=10  arm_calls=10000 tick_ms=200 brick=""      balance_s=20 ;;
quick) calls=200   virtual_s=0.5 arm_calls=200   tick_ms=20  brick="light" balance_s=1  ;;
*) echo "run_bench.sh: mode is full or quick" >&2; exit 2 ;;
esac

host_bench=$build/host/bench_host
counter=$build/host/insn_count
arm_bin=$build/arm926-test/bench/bench_arm
arm_prod_bin=$build/arm926-bench-prod/bench/bench_arm
shim=$build/host/bench/qemu_log_buffer.so
mkdir -p "$out"
rm -f "$out"/*.txt "$out"/*.csv "$out"/qemu.fifo

fail() { echo "bench: FAILED: $*" >&2; exit 1; }

# ---- the counter on a hand-made log first ----
bash "$(dirname "$0")/insn_count_selftest.sh" "$counter" >&2 || fail "insn_count self-test"

# ---- 1 and 3: the host ----
# The simulator's speed is measured on the programs users run: in the full run
# the profile-guided build (build/host-pgo, mk/pgo.mk), once its runs have
# matched the -O2 build's byte for byte (same_results); the -O2 build's speed
# is reported beside it.  The quick run, which asserts no speed, has the -O2
# build's figures stand for both, so that `make test` need not build the
# profile-guided one.
echo "bench ($mode): host: $calls calls each, host_sim for $virtual_s virtual s ..." >&2
"$host_bench" $calls $virtual_s > "$out/host_raw.txt" || fail "bench_host (see $out/host_raw.txt)"
grep -E '^call,' "$out/host_raw.txt" > "$out/host.txt"

# Appends to $out/sim_$2.txt the speed record of ev3sim balance, program $1
# (the paper's experiment: gyro boy with the 1 kHz gyro logger; 3 virtual s
# held for the calibration, then balance_s; CPU seconds of ev3sim, the least
# of 3 identical runs, as bench_host's rounds: preemption only adds).
balance_speed() {
	local ev3sim=$1 tag=$2 run
	echo "bench ($mode): $ev3sim balance for $((3 + balance_s)) virtual s, 3 runs ..." >&2
	: > "$out/balance_time_$tag.txt"
	for run in 1 2 3; do
		( TIMEFORMAT='%R %U %S'; time "$ev3sim" balance --seconds $balance_s --no-progress \
			> "$out/balance_run_$tag.txt" 2>&1 ) 2>> "$out/balance_time_$tag.txt" ||
			fail "ev3sim balance (see $out/balance_run_$tag.txt)"
		grep -q '^result=upright ' "$out/balance_run_$tag.txt" ||
			fail "ev3sim balance: the robot fell (see $out/balance_run_$tag.txt)"
	done
	awk -v v=$((3 + balance_s)) '{ cpu = $2 + $3; if (NR == 1 || cpu < best) { best = cpu; wall = $1 } }
		END { printf "speed,ev3sim_balance,%s,%.3f,%.3f,%.1f,%.1f\n", v, wall, best, v / wall, v / best }' \
		"$out/balance_time_$tag.txt" >> "$out/sim_$tag.txt"
}

# The same runs by ev3sim programs $1 and $2: a balancing run (a push, another
# seed: its summary but for the speed, the series and the trace) and the motor
# and sensor applications (their output but for the speed).
same_results() {
	local p n=0 f
	for p in "$1" "$2"; do
		n=$((n + 1))
		{ "$p" balance --seconds 3 --seed 5 --push 1s:0.2 --no-progress --csv "$out/same_$n.csv" \
			--trace "$out/same_$n.vcd" && "$p" motor --port C --speed -60 --seconds 1 &&
			"$p" sensors; } 2>&1 | sed 's/sim_speed=[^ ]*//' > "$out/same_$n.txt" ||
			fail "$p (see $out/same_$n.txt)"
	done
	for f in txt csv vcd; do
		cmp -s "$out/same_1.$f" "$out/same_2.$f" || return 1
	done
	rm -f "$out"/same_[12].*
}

grep '^speed,' "$out/host_raw.txt" > "$out/sim_o2.txt"
balance_speed "$build/host/ev3sim" o2
if [ "$mode" = full ]; then
	pgo=$build/host-pgo
	same_results "$build/host/ev3sim" "$pgo/ev3sim" ||
		fail "the profile-guided ev3sim computes other results than the -O2 build (see $out/same_*)"
	"$pgo/bench_host" 1 $virtual_s > "$out/host_raw_pgo.txt" || fail "$pgo/bench_host (see $out/host_raw_pgo.txt)"
	grep '^speed,' "$out/host_raw_pgo.txt" > "$out/sim_pgo.txt"
	balance_speed "$pgo/ev3sim" pgo
else
	cp "$out/sim_o2.txt" "$out/sim_pgo.txt"
fi
cat "$out/sim_pgo.txt" >> "$out/host.txt"
sed 's/^speed,\([^,]*\),/speed,\1_o2,/' "$out/sim_o2.txt" >> "$out/host.txt"

# ---- the AM1808 image: linux_compat and the RTOS glue in the gc'd firmware ----
bash "$(dirname "$0")/../am1808/size_report.sh" "$build/am1808" > "$out/size.md" || fail "size report"
sed -n 's/^linux_compat + rtos glue .text: \([0-9]*\) bytes in the library, \([0-9]*\) bytes in the image.*/image,linux_compat_glue,\2/p' \
	"$out/size.md" > "$out/image.txt"
grep -q '^image,linux_compat_glue,[0-9]' "$out/image.txt" || fail "no image size in $out/size.md"

# ---- 2: ARMv5 instruction counts, for two builds of the same library ----
#   arm.txt       the host-checked build (arm926-test: linux_compat's debugging
#                 checks on, the library the tests run)
#   arm_prod.txt  the production build (arm926-bench-prod: the checks off, as
#                 the AM1808 library is built)
# run_counted BINARY OUTPUT "FUNCTIONS" ARGS...: runs BINARY ARGS... under QEMU and
# counts the calls of FUNCTIONS made in its windows into OUTPUT.
run_counted() {
	local arm_bin=$1 result=$2 funcs=$3 run_log=${2%.txt}_run.txt
	local fifo=$out/qemu.fifo counter_pid arm_status measured=()
	shift 3
	for f in $funcs; do measured+=(-m "$f"); done
	mkfifo "$fifo"
	"$counter" -r "$(pwd)" "$arm_bin.syms" "${measured[@]}" \
		-w bench_window_open bench_window_close < "$fifo" > "$result" &
	counter_pid=$!
	"${preload[@]}" qemu-arm -cpu arm926 "${qemu_flags[@]}" -d $qemu_log -D "$fifo" \
		"$arm_bin.stripped" "$@" > "$run_log"
	arm_status=$?
	if [ $arm_status != 0 ]; then
		# the counter may still wait for a writer on the FIFO if QEMU never opened it
		kill $counter_pid 2>/dev/null
		wait $counter_pid 2>/dev/null
		rm -f "$fifo"
		fail "$arm_bin under qemu-arm exited with $arm_status (see $run_log)"
	fi
	wait $counter_pid || fail "insn_count"
	rm -f "$fifo"
}

# count_arm BINARY OUTPUT: the three measured calls of bench_arm.
count_arm() {
	local arm_bin=$1 run_log=${2%.txt}_run.txt
	echo "bench ($mode): ARMv5 ($(basename "$(dirname "$(dirname "$arm_bin")")")): $arm_calls calls each, $tick_ms ms of ticks under qemu-arm -cpu arm926 ..." >&2
	run_counted "$arm_bin" "$2" "ev3lx_motor_set_speed ev3lx_uart_sensor_get_raw lx_tick_isr" \
		$arm_calls $tick_ms $brick
	grep -q "^phase ev3lx_motor_set_speed $arm_calls 0$" "$run_log" &&
		grep -q "^phase ev3lx_uart_sensor_get_raw $arm_calls 0$" "$run_log" ||
		fail "$arm_bin: a measured call failed (see $run_log)"
}
qemu_log="in_asm,exec,nochain"
qemu_flags=()
[ "${BENCH_SINGLESTEP:-0}" = 1 ] && qemu_flags+=(-singlestep)
preload=()
[ -f "$shim" ] && preload=(env LD_PRELOAD="$shim")
count_arm "$arm_bin" "$out/arm.txt"
count_arm "$arm_prod_bin" "$out/arm_prod.txt"

# ---- the timer queues' scaling: the tick with 1, 16 and 256 armed hrtimers and
# timer_list timers, one of each due per period (bench/timers/bench_timers.c),
# production build ----
timers_bin=$build/arm926-bench-prod/bench/bench_timers
echo "bench ($mode): ARMv5 timer scaling: $tick_ms ms of ticks with 1, 16, 256 armed timers ..." >&2
: > "$out/timers.txt"
for n in 1 16 256; do
	run_counted "$timers_bin" "$out/timers_$n.txt" lx_tick_isr $n $tick_ms
	grep -q "^timers $n [1-9][0-9]* [1-9][0-9]*$" "$out/timers_${n}_run.txt" ||
		fail "bench_timers $n: the periodic timers did not run (see $out/timers_${n}_run.txt)"
	awk -F, -v n=$n '$1 == "call" && $2 == "lx_tick_isr" { print "timers," n "," $3 "," $7 "," $9 }' \
		"$out/timers_$n.txt" >> "$out/timers.txt"
done

# ---- what one due timer costs linux_compat: the same program with only the
# periodic hrtimer, only the timer_list timer, or neither; the ticks' linux_compat
# instructions minus the idle run's, over the runs of that timer; N = 1 and 256 ----
echo "bench ($mode): ARMv5 one due timer: $tick_ms ms of ticks with one periodic hrtimer, timer_list timer, neither ..." >&2
: > "$out/timer_costs.txt"
# tick_figures N KIND: "<ticks> <linux_compat instructions per tick> <hrtimer runs> <timer_list runs>"
tick_figures() {
	local base=$out/timers_$1_$2
	awk -F, '$1 == "call" && $2 == "lx_tick_isr" { t = $3 }
		$1 == "class" && $2 == "lx_tick_isr" && $3 == "linux_compat" { lc = $5 }
		END { printf "%s %s", t, lc + 0 }' "$base.txt"
	awk '$1 == "timers" { printf " %s %s\n", $3, $4 }' "${base}_run.txt"
}
# due_cost N KIND IDLE: the row "due,N,KIND,<linux_compat instructions per run of the KIND timer>"
due_cost() {
	local ticks lc hr tl runs
	read -r ticks lc hr tl < <(tick_figures $1 $2)
	[ $2 = hrtimer ] && runs=$hr || runs=$tl
	[ "${runs:-0}" -gt 0 ] || fail "bench_timers $1 $2: the $2 timer did not run"
	awk -v n=$1 -v k=$2 -v t=$ticks -v lc=$lc -v idle=$3 -v r=$runs \
		'BEGIN { printf "due,%d,%s,%.1f\n", n, k, (lc - idle) * t / r }'
}
for n in 1 256; do
	for kind in none hrtimer timer_list; do
		run_counted "$timers_bin" "$out/timers_${n}_$kind.txt" lx_tick_isr $n $tick_ms $kind
	done
	read -r _ idle _ _ < <(tick_figures $n none)
	{
		due_cost $n hrtimer $idle
		printf 'due,%d,idle,%.1f\n' $n $idle
		due_cost $n timer_list $idle
	} >> "$out/timer_costs.txt"
done

# ---- what the brick adds that the host kernel cannot count: on HRP2 each service
# call from a user-domain task is a trap (SWI entry, register save, function-code
# check, protection-domain switch, dispatch through the table, and the return with
# its dispatch check), and the tick is entered through the interrupt prologue and
# left through the epilogue.  Not measured (there is no HRP2 here): an estimate of
# the ARM926 exception path, HRP2_TRAP_MIN..MAX instructions each (docs/bench.md).
# The traps of a call are its kernel service calls in the production breakdown. ----
HRP2_TRAP_MIN=30 HRP2_TRAP_MAX=70
# (the host's functions: the extended service dispatcher and the kernel's _kernel_ entries)
hrp2_svcs=" rtos_host_cal_svc _kernel_prb_mem _kernel_sns_ctx _kernel_sns_loc _kernel_sns_dsp _kernel_sns_dpn _kernel_sns_ker _kernel_get_tid _kernel_get_utm _kernel_loc_cpu _kernel_unl_cpu _kernel_dis_dsp _kernel_ena_dsp "
awk -F, -v svcs="$hrp2_svcs" '$1 == "fn" && index(svcs, " " $3 " ") && $6 + 0 > 0 { n[$2]++ }
	END { for (k in n) print "traps," k "," n[k] }' "$out/arm_prod.txt" > "$out/traps.txt"

# ---- the CSV: section,measure,value,unit,paper,target,status ----
awk -F, -v calls=$calls -v arm_calls=$arm_calls -v mode=$mode -v trap_min=$HRP2_TRAP_MIN -v trap_max=$HRP2_TRAP_MAX '
function row(sec, name, v, unit, paper, target, status) {
	printf "%s,%s,%s,%s,%s,%s,%s\n", sec, name, v, unit, paper, target, status
}
function verdict(ok) { return ok ? "met" : "missed" }
# a target measurement shows cannot be met: the floor and why (docs/bench.md has the breakdown)
function floor_verdict(ok, why) { return ok ? "met" : "missed; " why " (docs/bench.md)" }
FILENAME ~ /host.txt$/ && $1 == "call" { havg[$2] = $4; hmax[$2] = $6; hn[$2] = $3; hslow[$2] = $7; herr[$2] = $8; hmed[$2] = $9; hp99[$2] = $10 }
FILENAME ~ /host.txt$/ && $1 == "speed" { spd[$2] = $6; cspd[$2] = $7; vs[$2] = $3; ws[$2] = $4 }
# arm.txt: the host-checked build (rows "<f> ..."); arm_prod.txt: the production build ("<f> production ...")
FILENAME ~ /\/arm(_prod)?\.txt$/ { b = FILENAME ~ /_prod\.txt$/ ? " production" : "" }
FILENAME ~ /\/arm(_prod)?\.txt$/ && $1 == "call" { k = $2 b; an[k] = $3; araw[k] = $4; arawmax[k] = $6; aeq[k] = $7; aeqmax[k] = $9; p50[k] = $10; p90[k] = $11; p99[k] = $12 }
FILENAME ~ /\/arm(_prod)?\.txt$/ && $1 == "log" { windows[b] = $5 }
FILENAME ~ /timers\.txt$/ { tavg[$2] = $4; tmax[$2] = $5 }
FILENAME ~ /timer_costs\.txt$/ { due[$2 " " $3] = $4 }
FILENAME ~ /image\.txt$/ { image[$2] = $3 }
FILENAME ~ /traps\.txt$/ { traps[$2] = $3 }
END {
	print "section,measure,value,unit,paper,target,status"
	s = "ev3lx_motor_set_speed"; r = "ev3lx_uart_sensor_get_raw"; w = "write_dev_null"
	row("host", s " avg", havg[s], "ns", 4540, "", "")
	row("host", s " max", hmax[s], "ns", 40000, "", "")
	row("host", s " median", hmed[s], "ns", "", "", "")
	row("host", s " p99", hp99[s], "ns", "", "", "")
	row("host", r " avg", havg[r], "ns", 5550, "", "")
	row("host", r " max", hmax[r], "ns", 33000, "", "")
	row("host", r " median", hmed[r], "ns", "", "", "")
	row("host", r " p99", hp99[r], "ns", "", "", "")
	row("host", "write() avg", havg[w], "ns", 596000, "", "")
	row("host", "write() max", hmax[w], "ns", 3424000, "", "")
	row("host", "write() median", hmed[w], "ns", "", "", "")
	row("host", "write() p99", hp99[w], "ns", "", "", "")
	rs = havg[s] > 0 ? havg[w] / havg[s] : 0
	rr = havg[r] > 0 ? havg[w] / havg[r] : 0
	# information only: on a fast host write() to /dev/null is the cheapest system call there is
	row("host", "write()/" s, sprintf("%.1f", rs), "x", sprintf("%.0f", 596 / 4.54), "", "")
	row("host", "write()/" r, sprintf("%.1f", rr), "x", sprintf("%.0f", 596 / 5.55), "", "")
	row("host", "write()/" s " medians", sprintf("%.1f", hmed[s] > 0 ? hmed[w] / hmed[s] : 0), "x", "", "", "")
	row("host", "write()/" r " medians", sprintf("%.1f", hmed[r] > 0 ? hmed[w] / hmed[r] : 0), "x", "", "", "")
	row("host", "clock_gettime pair", havg["clock_gettime_pair"], "ns", "", "", "")
	row("host", "calls", hn[s] + hn[r], "calls", "", "", "")
	row("host", "slow-path calls", hslow[s] + hslow[r], "calls", "", "", "")
	split("ev3lx_motor_set_speed:300 ev3lx_uart_sensor_get_raw:90 lx_tick_isr:300", t, " ")
	paper_cycles["ev3lx_motor_set_speed"] = 1362; paper_cycles["ev3lx_uart_sensor_get_raw"] = 1665
	# the floors of the production build, whose counts the targets are for
	floor_avg[r " production"] = "floor ~135: the checks the API promises"
	floor_avg["lx_tick_isr production"] = "floor above 300: the drivers\x27 own callbacks"
	floor_max["lx_tick_isr production"] = "cannot hold: the drivers\x27 periods put several callbacks on one tick"
	for (pass = 1; pass <= 2; pass++) {
		b = pass == 1 ? "" : " production"; sec = pass == 1 ? "arm" : "arm-prod"
		for (i = 1; i <= 3; i++) {
			split(t[i], kv, ":"); f = kv[1] b; lim = kv[2]
			name = (kv[1] == "lx_tick_isr" ? "tick" : kv[1]) b
			pc = kv[1] in paper_cycles ? paper_cycles[kv[1]] : ""
			row(sec, name " calls", an[f], "calls", "", "", "")
			row(sec, name " target-equivalent avg", aeq[f], "instructions", pc, "<=" lim,
			    f in floor_avg ? floor_verdict(aeq[f] <= lim, floor_avg[f]) : verdict(aeq[f] <= lim))
			row(sec, name " target-equivalent max", aeqmax[f], "instructions", "", "<=2*avg",
			    f in floor_max ? floor_verdict(aeqmax[f] <= 2 * aeq[f], floor_max[f]) : verdict(aeqmax[f] <= 2 * aeq[f]))
			row(sec, name " target-equivalent median", p50[f], "instructions", "", "", "")
			row(sec, name " target-equivalent p90", p90[f], "instructions", "", "", "")
			row(sec, name " target-equivalent p99", p99[f], "instructions", "", "", "")
			row(sec, name " raw avg", araw[f], "instructions", "", "", "")
			row(sec, name " raw max", arawmax[f], "instructions", "", "", "")
		}
		row(sec, "windows" b, windows[b], "windows", "", "", "")
		if (pass == 2) {
			for (i = 1; i <= 2; i++) {
				f = (i == 1 ? s : r)
				row(sec, f " production HRP2 traps", traps[f] + 0, "traps", "", "", "")
				row(sec, f " production HRP2 trap instructions", sprintf("%d-%d", (traps[f] + 0) * trap_min, (traps[f] + 0) * trap_max), "instructions (estimate)", "", "", "")
			}
			row(sec, "tick production HRP2 interrupt entry and exit", sprintf("%d-%d", trap_min, trap_max), "instructions (estimate)", "", "", "")
		}
	}
	r1 = tavg[1]; r256 = tavg[256]
	for (i = 1; i <= 3; i++) {
		nn = split("1 16 256", ns, " "); k = ns[i]
		row("timers", "tick with " k " armed timers avg", tavg[k], "instructions", "", "", "")
		row("timers", "tick with " k " armed timers max", tmax[k], "instructions", "", "", "")
	}
	ratio = r1 > 0 ? r256 / r1 : 0
	row("timers", "tick 256 / 1 armed timers", sprintf("%.2f", ratio), "x", "", "<=1.5", verdict(ratio <= 1.5))
	for (i = 1; i <= 2; i++) {
		k = i == 1 ? 1 : 256
		row("timers", "idle tick linux_compat with " k " armed", due[k " idle"], "instructions", "", "", "")
		row("timers", "due hrtimer linux_compat with " k " armed", due[k " hrtimer"], "instructions", "", "<=80",
		    floor_verdict(due[k " hrtimer"] <= 80, "floor ~200: 64-bit expiry and an O(log n) re-queue"))
		row("timers", "due timer_list linux_compat with " k " armed", due[k " timer_list"], "instructions", "", "<=60",
		    floor_verdict(due[k " timer_list"] <= 60, "floor ~200: 64-bit expiry and an O(log n) re-queue"))
	}
	row("sim", "host_sim devices (ev3_bench_full_brick)", spd["host_sim_devices"], "x real time", "", "",  "")
	row("sim", "host_sim devices per CPU second", cspd["host_sim_devices"], "x real time", "", ">=1500",
	    verdict(cspd["host_sim_devices"] >= 1500))
	row("sim", "full stack (drivers + 4 motors + 4 sensors)", spd["full_stack"], "x real time", "", "", "")
	row("sim", "full stack per CPU second", cspd["full_stack"], "x real time", "", ">=750",
	    verdict(cspd["full_stack"] >= 750))
	row("sim", "ev3sim balance (1 kHz logger)", spd["ev3sim_balance"], "x real time", "", "", "")
	row("sim", "ev3sim balance per CPU second", cspd["ev3sim_balance"], "x real time", "", ">=500",
	    verdict(cspd["ev3sim_balance"] >= 500))
	row("sim", "host_sim devices per CPU second (-O2 build)", cspd["host_sim_devices_o2"], "x real time", "", "", "")
	row("sim", "full stack per CPU second (-O2 build)", cspd["full_stack_o2"], "x real time", "", "", "")
	row("sim", "ev3sim balance per CPU second (-O2 build)", cspd["ev3sim_balance_o2"], "x real time", "", "", "")
	row("image", "linux_compat + RTOS glue text in the AM1808 image", image["linux_compat_glue"], "bytes", "",
	    "<=8192", floor_verdict(image["linux_compat_glue"] <= 8192, "floor ~30 KiB: the Linux API the eight drivers call"))
}' "$out/host.txt" "$out/arm.txt" "$out/arm_prod.txt" "$out/timers.txt" "$out/timer_costs.txt" "$out/image.txt" "$out/traps.txt" > "$out/bench.csv"
grep -E '^(class|fn|libc),' "$out/arm.txt" > "$out/breakdown.csv"
grep -E '^(class|fn|libc),' "$out/arm_prod.txt" > "$out/breakdown_prod.csv"

# ---- every figure present (both modes); the counts of calls as asked ----
awk -F, 'NR > 1 && $3 == "" { print "missing: " $1 " " $2; bad = 1 } END { exit bad }' "$out/bench.csv" ||
	fail "a figure is missing (see $out/bench.csv)"
check() { awk -F, -v m="$1" -v want="$2" '$2 == m { found = 1; if ($3 != want) { print m ": " $3 " (want " want ")"; exit 1 } } END { if (!found) exit 1 }' "$out/bench.csv" || fail "$1"; }
check "calls" $((2 * calls))
check "slow-path calls" 0
for b in "" " production"; do
	check "ev3lx_motor_set_speed$b calls" $arm_calls
	check "ev3lx_uart_sensor_get_raw$b calls" $arm_calls
	check "windows$b" 3
	awk -F, -v m="tick$b calls" '$2 == m && $3 + 0 < 1 { exit 1 }' "$out/bench.csv" || fail "no tick was counted$b"
done

# ---- the table ----
awk -F, -v mode=$mode -v calls=$calls -v arm_calls=$arm_calls -v tick_ms=$tick_ms -v brick="${brick:-full}" '
function v(name) { return val[name] }
function st(name) { return status[name] == "" ? "" : status[name] }
function arm_rows(key, label, paper, paper_ratio, limit,   a, mx) {
	a = v(key " target-equivalent avg"); mx = v(key " target-equivalent max")
	printf fmt, "  " label " avg / max", sprintf("%.0f / %.0f", a, mx), paper == "" ? "" : paper " avg", "<= " limit, st(key " target-equivalent avg")
	printf fmt, "    max / avg", sprintf("%.2f", a > 0 ? mx / a : 0), paper_ratio == "" ? "" : paper_ratio " (us max/avg)", "<= 2", st(key " target-equivalent max")
	printf fmt, "    median / p90 / p99", sprintf("%.0f / %.0f / %.0f", v(key " target-equivalent median"), v(key " target-equivalent p90"), v(key " target-equivalent p99")), "", "", ""
	printf fmt, "    raw (with the simulation) avg / max", sprintf("%.0f / %.0f", v(key " raw avg"), v(key " raw max")), "", "", ""
}
FILENAME ~ /bench.csv$/ && FNR > 1 { val[$2] = $3; status[$2] = $7 }
FILENAME ~ /breakdown(_prod)?\.csv$/ { k = $2 (FILENAME ~ /_prod\.csv$/ ? " production" : "") }
FILENAME ~ /breakdown(_prod)?\.csv$/ && $1 == "class" && $3 != "sim" { cls[k] = cls[k] sprintf(" %s %.0f", $3, $5) }
FILENAME ~ /breakdown(_prod)?\.csv$/ && $1 == "libc" && $4 >= 1 { lib[k] = lib[k] sprintf(" %s %.0f", $3, $4) }
FILENAME ~ /breakdown(_prod)?\.csv$/ && $1 == "fn" { nfn[k]++; fname[k, nfn[k]] = $3; fcls[k, nfn[k]] = $4; feq[k, nfn[k]] = $6 }
END {
	s = "ev3lx_motor_set_speed"; r = "ev3lx_uart_sensor_get_raw"
	printf "\n== ev3lx bench (%s: %d host calls each, %d ARMv5 calls each, %d ms of ticks, %s brick) ==\n", mode, calls, arm_calls, tick_ms, brick
	printf "Paper: EV3RT on the EV3 (AM1808, ARM926 at 300 MHz), and LEGO firmware Linux write().\n\n"
	fmt = "%-48s %-24s %-24s %-10s %s\n"
	printf fmt, "measure", "ev3lx", "paper", "target", "status"
	printf "1. host: from an application task on the simulated brick (x86-64, CLOCK_MONOTONIC, best of 3 rounds)\n"
	printf fmt, "  ev3lx_motor_set_speed avg / max", sprintf("%.0f / %.0f ns", v(s " avg"), v(s " max")), "4.54 / 40 us", "", ""
	printf fmt, "    median / p99", sprintf("%.0f / %.0f ns", v(s " median"), v(s " p99")), "", "", ""
	printf fmt, "  ev3lx_uart_sensor_get_raw avg / max", sprintf("%.0f / %.0f ns", v(r " avg"), v(r " max")), "5.55 / 33 us", "", ""
	printf fmt, "    median / p99", sprintf("%.0f / %.0f ns", v(r " median"), v(r " p99")), "", "", ""
	printf fmt, "  write() to /dev/null avg / max", sprintf("%.0f / %.0f ns", v("write() avg"), v("write() max")), "596 / 3424 us (brick)", "", ""
	printf fmt, "    median / p99", sprintf("%.0f / %.0f ns", v("write() median"), v("write() p99")), "", "", ""
	printf fmt, "  write() / ev3lx_motor_set_speed (avg; median)", sprintf("%sx; %sx", v("write()/" s), v("write()/" s " medians")), "131x", "", ""
	printf fmt, "  write() / ev3lx_uart_sensor_get_raw", sprintf("%sx; %sx", v("write()/" r), v("write()/" r " medians")), "107x", "", ""
	printf fmt, "  (clock_gettime pair, included above)", sprintf("%.0f ns", v("clock_gettime pair")), "", "", ""
	printf fmt, "  calls that took a slow path", v("slow-path calls"), "", "", ""
	printf "2. ARMv5 instructions per call under qemu-arm -cpu arm926 (target-equivalent; raw)\n"
	printf " host-checked build (LX_DEBUG_ATOMIC_SLEEP and LX_DEBUG_SPINLOCK on: the library the tests run)\n"
	arm_rows(s, s, "~1362 cycles", "8.8", 300)
	arm_rows(r, r, "~1665 cycles", "5.9", 90)
	arm_rows("tick", "200 us tick (lx_tick_isr)", "", "", 300)
	printf fmt, "    ticks counted", v("tick calls"), "", "", ""
	printf " production build (the checks off, as the AM1808 library is built)\n"
	arm_rows(s " production", s, "~1362 cycles", "8.8", 300)
	printf fmt, "    + on HRP2 (not counted): " v(s " production HRP2 traps") " traps", v(s " production HRP2 trap instructions") " (estimate)", "", "", ""
	arm_rows(r " production", r, "~1665 cycles", "5.9", 90)
	printf fmt, "    + on HRP2 (not counted): " v(r " production HRP2 traps") " traps", v(r " production HRP2 trap instructions") " (estimate)", "", "", ""
	arm_rows("tick production", "200 us tick (lx_tick_isr)", "", "", 300)
	printf fmt, "    + on HRP2 (not counted): interrupt entry/exit", v("tick production HRP2 interrupt entry and exit") " (estimate)", "", "", ""
	printf fmt, "    ticks counted", v("tick production calls"), "", "", ""
	printf "3. the timer queues: the 200 us tick with N armed hrtimers and N timer_list timers, one of each due (production)\n"
	printf fmt, "  N = 1 / 16 / 256: avg", sprintf("%.0f / %.0f / %.0f", v("tick with 1 armed timers avg"), v("tick with 16 armed timers avg"), v("tick with 256 armed timers avg")), "", "", ""
	printf fmt, "  N = 1 / 16 / 256: max", sprintf("%.0f / %.0f / %.0f", v("tick with 1 armed timers max"), v("tick with 16 armed timers max"), v("tick with 256 armed timers max")), "", "", ""
	printf fmt, "  256 / 1", v("tick 256 / 1 armed timers") "x", "", "<= 1.5x", st("tick 256 / 1 armed timers")
	for (i = 1; i <= 2; i++) {
		k = i == 1 ? 1 : 256
		printf fmt, "  one due hrtimer, " k " armed (linux_compat)", v("due hrtimer linux_compat with " k " armed"), "", "<= 80", st("due hrtimer linux_compat with " k " armed")
		printf fmt, "  one due timer_list timer, " k " armed", v("due timer_list linux_compat with " k " armed"), "", "<= 60", st("due timer_list linux_compat with " k " armed")
		printf fmt, "  idle tick, " k " armed", v("idle tick linux_compat with " k " armed"), "", "", ""
	}
	printf "4. host_sim speed (virtual seconds per CPU second of the process, profile-guided build; per wall second, and the -O2 build, in brackets)\n"
	printf fmt, "  devices only (ev3_bench_full_brick)", sprintf("%.0fx (%.0fx wall; -O2 %.0fx)", v("host_sim devices per CPU second"), v("host_sim devices (ev3_bench_full_brick)"), v("host_sim devices per CPU second (-O2 build)")), "", ">= 1500x", st("host_sim devices per CPU second")
	printf fmt, "  full stack: drivers, 4 motors, 4 sensors", sprintf("%.0fx (%.0fx wall; -O2 %.0fx)", v("full stack per CPU second"), v("full stack (drivers + 4 motors + 4 sensors)"), v("full stack per CPU second (-O2 build)")), "", ">= 750x", st("full stack per CPU second")
	printf fmt, "  ev3sim balance, 1 kHz logger", sprintf("%.0fx (%.0fx wall; -O2 %.0fx)", v("ev3sim balance per CPU second"), v("ev3sim balance (1 kHz logger)"), v("ev3sim balance per CPU second (-O2 build)")), "", ">= 500x", st("ev3sim balance per CPU second")
	printf "5. the AM1808 image (arm-none-eabi-gcc -Os, --gc-sections, every API function rooted)\n"
	printf fmt, "  linux_compat + RTOS glue .text", v("linux_compat + RTOS glue text in the AM1808 image") " bytes", "", "<= 8192", st("linux_compat + RTOS glue text in the AM1808 image")
	printf "\nWhere the ARMv5 instructions go (target-equivalent per call, by layer; top functions):\n"
	split("ev3lx_motor_set_speed ev3lx_uart_sensor_get_raw lx_tick_isr", m, " ")
	for (i = 1; i <= 6; i++) {
		f = m[i > 3 ? i - 3 : i] (i > 3 ? " production" : "")
		if (i == 1 || i == 4)
			printf " %s build\n", i == 1 ? "host-checked" : "production"
		printf "  %s:%s\n   ", f, cls[f]
		# the eight functions with the most counted instructions
		for (k = 1; k <= 8; k++) {
			best = 0; bi = 0
			for (j = 1; j <= nfn[f]; j++)
				if (!((f, j) in used) && feq[f, j] + 0 > best) { best = feq[f, j] + 0; bi = j }
			if (!bi) break
			used[f, bi] = 1
			printf " %s(%s) %.0f", fname[f, bi], fcls[f, bi], best
		}
		printf "\n"
		if (lib[f] != "")
			printf "    C library code on behalf of:%s\n", lib[f]
	}
	printf "\nWhy targets are missed, and what is counted: docs/bench.md.\n"
}' "$out/bench.csv" "$out/breakdown.csv" "$out/breakdown_prod.csv" | tee "$out/table.txt"
echo "bench ($mode): $out/bench.csv, $out/breakdown.csv, $out/breakdown_prod.csv, $out/table.txt"

# ---- the README's table is `make bench`'s (bench/readme_table.sh): its exact
# per-call counts must be this tree's.  Compared are the medians, exact
# integers: the count of the path nearly every call takes, the same in the
# quick run's 200 calls on the light brick as in the full run's 10 000.  An
# average is not: the rare call an interrupt lengthens or splits moves it by
# a fraction, and which call it hits varies from run to run (one full run
# counted one production set_speed of 4, another one host-checked set_speed
# of 506 among 513s), so a rounded average could differ by one between two
# runs of one tree (137 against 138).  A change of the path by one instruction
# moves the median by one and fails. ----
if [ "$mode" = quick ]; then
	stamp=$(grep -m1 '^<!-- bench medians: ' README.md || true)
	[ -n "$stamp" ] || fail "README.md has no table generated by make bench (its '<!-- bench medians: ' line) — run make bench-readme"
	stale=""
	for kv in "set_speed:ev3lx_motor_set_speed production" "get_raw:ev3lx_uart_sensor_get_raw production" \
		"set_speed_checked:ev3lx_motor_set_speed" "get_raw_checked:ev3lx_uart_sensor_get_raw"; do
		key=${kv%%:*} measure="${kv#*:} target-equivalent median"
		have=$(sed -n "s/.* $key=\([0-9]*\).*/\1/p" <<<"$stamp")
		now=$(awk -F, -v m="$measure" '$2 == m { print $3 }' "$out/bench.csv")
		[ -n "$have" ] && [ "$have" = "$now" ] || stale="$stale $key: README ${have:-none}, this tree $now;"
	done
	[ -z "$stale" ] || fail "README.md's benchmark table is stale (medians:$stale) — run make bench-readme"
	echo "bench (quick): README.md's table carries this tree's per-call counts (medians)"
fi

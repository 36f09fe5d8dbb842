#!/usr/bin/env bash
# quiet.sh — the quiet output of `make` and `make test` (make V=1 does not use
# it): every step's full output goes to a log file under build/logs/, the
# terminal gets one line per step, and a failing step its log's tail and path.
#
#   quiet.sh build LOG "CONFIGS" CMD...
#       runs CMD (a make of builds) with its output in LOG, then prints its
#       build summary (below) and, if it failed, LOG's tail.  Exit status: CMD's.
#   quiet.sh build-summary LOG "CONFIGS" [STATUS]
#       one line per configuration of CONFIGS and any other LOG names: what it
#       compiled and linked (the build lines "  CC  host  file" in LOG), or
#       that it was up to date (nothing built, if STATUS, the build's exit
#       status, is not 0).
#   quiet.sh step NAME LOG CMD...
#       runs CMD with its output in LOG; prints "ok NAME: <summary>".
#   quiet.sh shell FD LOG -c RECIPE_LINE
#       the suite's shell for one recipe line of a run (make's .SHELLFLAGS):
#       runs it with its output appended to LOG; if it fails, writes the
#       failure and LOG's tail to file descriptor FD (the terminal).
#   quiet.sh result NAME LOG
#       prints "ok NAME: <summary>" for a run whose recipe succeeded.
#   quiet.sh suite-end DIR STATUS "RUNS" "CONFIGS"
#       the end of `make test`'s output: the build summary of DIR/make.log
#       (the suite's make; DIR/make-arm926-tests.log, the ARMv5 tests' make
#       before it, is added to it), the runs that did not run because a
#       build they need failed, that build's errors, and the result, last.
#       STATUS: the make's exit status; a passing run left DIR/RUN.ok.
#
# The summary of a log: prove's totals ("164 test programs, 4097 tests passed")
# if it holds a prove run, the count of its TAP checks if it holds some, else
# its last non-empty line (shortened).
set -u -o pipefail

TAIL_LINES=30

# One line summing up log $1 of step $2 (a last line "$2: ..." loses that prefix).
summary() {
	local log=$1 name=${2:-} files tests last
	if grep -q '^Files=[0-9]*, Tests=[0-9]*' "$log" 2>/dev/null; then
		files=$(sed -n 's/^Files=\([0-9]*\), Tests=\([0-9]*\).*/\1/p' "$log" | tail -n 1)
		tests=$(sed -n 's/^Files=\([0-9]*\), Tests=\([0-9]*\).*/\2/p' "$log" | tail -n 1)
		echo "$files test programs, $tests tests passed"
		return
	fi
	# TAP checks (report-check): their count
	if grep -q '^ok ' "$log" && ! grep -q '^not ok' "$log"; then
		echo "$(grep -c '^ok ' "$log") checks passed"
		return
	fi
	last=$(grep -v '^[[:space:]]*$' "$log" 2>/dev/null | tail -n 1)
	[ -z "$name" ] || last=${last#"$name: "}
	[ ${#last} -le 110 ] || last="${last:0:107}..."
	echo "${last:-done}"
}

# Prints the failure of step $1 (exit status $2) with the tail of log $3
# (without prove's lines of passing test programs, "tests/x.t .... ok").
failure() {
	echo "FAILED $1 (exit status $2); the end of its log:"
	grep -v '\.\. ok$' "$3" | tail -n $TAIL_LINES | sed 's/^/  | /'
	echo "  full log: $3"
}

# The build summary of log $1 for configurations $2 (and any other the log
# names); $3 = 0 if the build succeeded (a configuration that built nothing
# was up to date).
build_summary() {
	awk -v configs="$2" -v idle="$([ "${3:-0}" = 0 ] && echo "up to date" || echo "nothing built")" '
		$1 ~ /^(CC|CFG|GEN|PROFILE)$/ { cc[$2]++; seen[$2] = 1 }
		$1 ~ /^(LD|AR|MOD|OBJCOPY)$/ { ld[$2]++; seen[$2] = 1 }
		END {
			n = split(configs, order, " ")
			for (i = 1; i <= n; i++) listed[order[i]] = 1
			for (c in seen) if (!(c in listed)) order[++n] = c
			for (i = 1; i <= n; i++) {
				c = order[i]
				if (cc[c] + ld[c]) printf "build %-16s %d compiled, %d linked\n", c, cc[c], ld[c]
				else printf "build %-16s %s\n", c, idle
			}
		}' "$1"
}

cmd=${1:-}
shift || true
case $cmd in
build)
	log=$1 configs=$2
	shift 2
	mkdir -p "$(dirname "$log")"
	"$@" > "$log" 2>&1
	status=$?
	build_summary "$log" "$configs" $status
	if [ $status != 0 ]; then
		failure build $status "$log"
		exit $status
	fi
	;;
build-summary)
	build_summary "$1" "$2" "${3:-0}"
	;;
step)
	name=$1 log=$2
	shift 2
	mkdir -p "$(dirname "$log")"
	"$@" > "$log" 2>&1
	status=$?
	if [ $status != 0 ]; then
		failure "$name" $status "$log"
		exit $status
	fi
	echo "ok $name: $(summary "$log" "$name")"
	;;
shell)
	fd=$1 log=$2
	[ "${3:-}" = -c ] || { echo "quiet.sh shell: usage: FD LOG -c LINE" >&2; exit 2; }
	mkdir -p "$(dirname "$log")"
	bash -c "$4" >> "$log" 2>&1
	status=$?
	if [ $status != 0 ]; then
		failure "$(basename "$log" .log)" $status "$log" >&"$fd"
	fi
	exit $status
	;;
result)
	echo "ok $1: $(summary "$2" "$1")  ($2)"
	;;
suite-end)
	dir=$1 status=$2 runs=$3 configs=$4
	make_log=$dir/make.log
	cat "$dir/make-arm926-tests.log" >> "$make_log" 2>/dev/null
	build_summary "$make_log" "$configs" $status
	passed=0 failed="" unrun=0
	for r in $runs; do
		if [ -f "$dir/$r.ok" ]; then
			passed=$((passed + 1))
		else
			failed="$failed $r"
			# a run whose recipe ran has its log (its failure is printed already)
			if [ ! -f "$dir/$r.log" ]; then
				echo "FAILED $r: not run (something it needs failed to build)"
				unrun=1
			fi
		fi
	done
	# make's "*** [FILE:LINE: TARGET] Error N" lines of targets other than the runs: builds
	build_errors=$(grep '\*\*\* \[' "$make_log" | while IFS= read -r line; do
		target=$(sed 's/.*\*\*\* \[\(.*\)\] .*/\1/; s/.*: //' <<<"$line")
		case " $runs " in *" ${target#suite-} "*) ;; *) echo "$line" ;; esac
	done)
	if [ $status != 0 ] && { [ $unrun = 1 ] || [ -z "$failed" ] || [ -n "$build_errors" ]; }; then
		echo "FAILED a build; its errors:"
		grep -E 'error:|Error [0-9]' "$make_log" | tail -n $TAIL_LINES | sed 's/^/  | /'
		echo "  full log: $make_log"
	fi
	total=$(echo $runs | wc -w)
	if [ $status = 0 ] && [ -z "$failed" ]; then
		echo "=== make test: all $passed runs passed (logs: $dir/) ==="
	else
		echo "=== make test: FAILED:${failed:- a build} ($passed of $total runs passed; logs: $dir/) ==="
		exit 1
	fi
	;;
*)
	echo "quiet.sh: unknown command '$cmd' (build, build-summary, step, shell, result, suite-end)" >&2
	exit 2
	;;
esac

#!/usr/bin/env bash
# check_totals.sh OUTDIR — the report's totals equal cloc's own SUM lines for the
# same file lists: the report adds nothing of its own to cloc's counts.
set -euo pipefail
out=$1
cloc_sum() {
	[ $# -gt 0 ] || { echo 0; return; }
	cloc --csv --quiet --skip-uniqueness "$@" | awk -F, '$2 == "SUM" { print $5 }'
}
fail=0
check() {  # check NAME REPORTED FILES...
	local name=$1 reported=$2; shift 2
	local expected; expected=$(cloc_sum "$@")
	expected=${expected:-0}
	if [ "$reported" = "$expected" ]; then echo "ok - $name: $reported code lines = cloc SUM"
	else echo "not ok - $name: report says $reported, cloc SUM says $expected"; fail=1; fi
}
csvv() { awk -F, -v k="$1" -v c="$2" '$1 == k { print $c }' "$out/reuse.csv"; }
# The same drivers as the report: what the hack files include (find_drivers.sh).
reused=(); glue=()
while read -r hack d; do
	m=$(basename "$d" .c); m=${m#d_}
	for f in "$d" "$(dirname "$d")/lms_$m.h"; do [ -f "$f" ] && reused+=("$f"); done
	case $hack in ${HACK_DIRS:-hacks}/*) ;; *) for f in "$hack" "${hack%.c}.h"; do [ -f "$f" ] && glue+=("$f"); done ;; esac
done < <(bash cloc_report/find_drivers.sh "${HACK_DIRS:-hacks}" "${DRIVER_DIRS:-ev3_drivers}")
while IFS= read -r f; do glue+=("$f"); done < <(find ${HACK_DIRS:-hacks} -type f \( -name '*.c' -o -name '*.h' \) 2>/dev/null | sort)
shim=(); while IFS= read -r f; do shim+=("$f"); done < <(find linux_compat rtos_stub/include rtos_stub/src -type f \( -name '*.c' -o -name '*.h' -o -name '*.S' \) 2>/dev/null | sort)
check "reused total" "$(csvv total 3)" "${reused[@]}"
check "written glue total" "$(csvv total 5)" "${glue[@]}"
check "shared shim" "$(csvv shared_shim 5)" "${shim[@]}"
slibs=(); while IFS= read -r f; do slibs+=("$f"); done < <(find api/library -type f \( -name '*.c' -o -name '*.cpp' -o -name '*.h' \) 2>/dev/null | sort)
check "SDK libraries" "$(csvv sdk_libraries 5)" "${slibs[@]}"
exit $fail

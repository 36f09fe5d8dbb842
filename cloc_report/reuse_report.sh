#!/usr/bin/env bash
# reuse_report.sh — reused versus written lines, counted by cloc.
#
#   reuse_report.sh OUTDIR                      every driver a hack file includes (find_drivers.sh)
#   reuse_report.sh OUTDIR REUSED GLUE [SHIM]   any port: dirs or files, space-separated
#
# Every number is a sum of cloc's own per-file "code" counts (--by-file, with
# --skip-uniqueness so identical files are not merged); nothing here counts
# lines itself.  The report also proves that every driver (every .c file in
# REUSED) was compiled unmodified: each build recorded, at compile time, the
# sha256 of every driver file its compiler read (record_driver_hashes.sh, and
# kbuild-check for kbuild); a record missing in any of BUILD_CONFIGS or a hash
# differing from the tree's is reported and makes the script exit 1.
# Environment: HACK_DIRS, DRIVER_DIRS (find_drivers.sh), BUILD_CONFIGS, RECORDS_ROOT
# (where the builds are, default build/).
#
# The users' modules (LEGACY_HACK_DIRS: tests/legacy and its genuine/ home,
# each hack including its module from drivers/) get a table of their own,
# without the ratios: each module's sha256 must be the one recorded for its
# pristine source in LEGACY_PRISTINE (sha256sum's format: the module as its
# author wrote it; a changed line makes the tree differ from it), and every
# build of LEGACY_CONFIGS must have compiled those bytes (the records beside
# the module objects, build/CONFIG/legacy/).
set -euo pipefail
out=$1; shift
mkdir -p "$out"

# Expands dirs into their C sources and headers; keeps files; drops what is missing.
expand() {
	local p
	for p in "$@"; do
		if [ -d "$p" ]; then find "$p" -type f \( -name '*.c' -o -name '*.cpp' -o -name '*.h' -o -name '*.S' \) | sort
		elif [ -f "$p" ]; then echo "$p"; fi
	done
}

# Sum of cloc's code lines over a file list (0 for an empty list).
cloc_code() {
	local files=("$@")
	[ ${#files[@]} -gt 0 ] || { echo 0; return; }
	cloc --by-file --csv --quiet --skip-uniqueness "${files[@]}" \
		| awk -F, '$1 != "language" && $1 != "SUM" && NF >= 5 { s += $5 } END { print s + 0 }'
}

pct() { awk -v w="$1" -v r="$2" 'BEGIN { if (r > 0) printf "%.1f", 100 * (1 - w / r); else printf "n/a" }'; }
ratio() { awk -v w="$1" -v r="$2" 'BEGIN { if (r > 0) printf "%.3f", w / r; else printf "n/a" }'; }

hash_of() { [ -n "$1" ] && [ -f "$1" ] && sha256sum "$1" | cut -c1-64 || echo "-"; }
configs=(${BUILD_CONFIGS:-host host-san arm926-test am1808 kbuild})
# The hash configuration $1 recorded at compile time for driver $2 ("-" if none),
# in the build's directory $3 (default obj: the library's hack files).
recorded_hash() {
	local recs=${RECORDS_ROOT:-build}/$1/${3:-obj}
	[ "$1" = kbuild ] && recs=${RECORDS_ROOT:-build}/kbuild/drivers.sha256
	[ -e "$recs" ] || { echo "-"; return; }
	{ grep -rh --include='*.drivers' --include='drivers.sha256' -E "  (\./)?$2\$" "$recs" 2>/dev/null || true; } |
		awk '{ print $1 }' | sort -u | paste -sd/ | sed 's/^$/-/'
}
proof_failures=0
# Checks driver $1 in every configuration: P_MOD (0, or n/a if unproven) and P_CELLS.
prove_unmodified() {
	local drv=$1 hack=${2:-} src c h cells="" bad=0
	src=$(hash_of "$drv")
	for c in "${configs[@]}"; do
		# a driver whose hack file is a test is not in the firmware library
		case $c:$hack in am1808:tests/*) continue ;; esac
		h=$(recorded_hash "$c" "$drv")
		if [ "$h" = "$src" ]; then cells+="$c:ok "
		elif [ "$h" = "-" ]; then cells+="$c:MISSING "; bad=1
			echo "report: $drv: no compile-time hash recorded by the $c build" >&2
		else cells+="$c:DIFFERS "; bad=1
			echo "report: $drv: the $c build compiled a different file (sha256 $h, tree $src)" >&2
		fi
	done
	[ $bad = 0 ] || proof_failures=$((proof_failures + 1))
	P_MOD=$([ $bad = 0 ] && echo 0 || echo n/a); P_CELLS=${cells% }
}

md="$out/reuse.md"; csv="$out/reuse.csv"
echo "module,reused_files,reused_code,modified_lines,glue_code,source_sha256,compiled_as" > "$csv"

if [ $# -ge 2 ]; then
	mapfile -t reused < <(expand $1)
	mapfile -t glue < <(expand $2)
	mapfile -t shim < <(expand ${3:-})
	modules=(custom)
else
	# one module per driver a hack file includes: its hack .c/.h are the glue
	mapfile -t pairs < <(bash cloc_report/find_drivers.sh "${HACK_DIRS:-hacks}" "${DRIVER_DIRS:-ev3_drivers}")
	modules=(); for p in "${pairs[@]}"; do modules+=("$p"); done
	mapfile -t shim < <(expand linux_compat rtos_stub/include rtos_stub/src)
fi
mapfile -t tests < <(expand tests)
# ev3lx's SDK libraries for apps (libcpp-ev3: EV3RT's C++ API written here)
mapfile -t slibs < <(expand api/library)

total_reused=0; total_glue=0; rows=(); module_glue=()
for m in "${modules[@]}"; do
	if [ "$m" = custom ]; then
		r_files=("${reused[@]}"); g_files=("${glue[@]}"); hack=${glue[0]:-}
		drivers=(); for f in "${reused[@]}"; do case $f in *.c) drivers+=("$f") ;; esac; done
	else
		hack=${m% *}; drv=${m#* }
		name=$(basename "$drv" .c); m=${name#d_}
		r_files=("$drv"); [ -f "$(dirname "$drv")/lms_$m.h" ] && r_files+=("$(dirname "$drv")/lms_$m.h")
		# the module's glue: the hack file and its header, and its RTOS side
		# (<m>_svc.c) with the header the two share (<m>_module.h)
		g_files=("$hack"); for g in "${hack%.c}.h" "${hack%_hack.c}_svc.c" "${hack%_hack.c}_module.h"; do
			[ -f "$g" ] && g_files+=("$g"); done
		drivers=("$drv")
		module_glue+=("${g_files[@]}")
	fi
	modified=0; src_h=""; proof=""
	for d in "${drivers[@]}"; do
		prove_unmodified "$d" "${hack:-}"
		[ "$P_MOD" = 0 ] || modified="n/a"
		src_h+="$(hash_of "$d" | cut -c1-16) "; proof+="$P_CELLS; "
	done
	src_h=${src_h% }; proof=${proof%; }
	rc=$(cloc_code "${r_files[@]}"); gc=$(cloc_code "${g_files[@]}")
	total_reused=$((total_reused + rc)); total_glue=$((total_glue + gc))
	rows+=("| $m | $rc | $modified | $gc | $(ratio "$gc" "$rc") | $(pct "$gc" "$rc") % | \`$src_h\` | $proof |")
	echo "$m,${#r_files[@]},$rc,$modified,$gc,$src_h,$proof" >> "$csv"
done

shim_code=$(cloc_code "${shim[@]}")
test_code=$(cloc_code "${tests[@]}")
slib_code=$(cloc_code "${slibs[@]}")
shared_glue=0
if [ "${modules[0]}" != custom ]; then
	mapfile -t shared_hacks < <(expand ${HACK_DIRS:-hacks} | grep -vxF -f <(printf '%s\n' "${module_glue[@]}") || true)
	shared_glue=$(cloc_code "${shared_hacks[@]}")
fi
written=$((total_glue + shared_glue))
written_shim=$((written + shim_code))
echo "total,,$total_reused,,$written,,," >> "$csv"
echo "shared_shim,,,,$shim_code,,," >> "$csv"
echo "tests,,,,$test_code,,," >> "$csv"
echo "sdk_libraries,,,,$slib_code,,," >> "$csv"

{
	echo "| module | reused (code lines) | modified lines | written glue | written/reused | coding saved | driver sha256 | compiled unmodified by |"
	echo "|---|---:|---:|---:|---:|---:|---|---|"
	printf '%s\n' "${rows[@]}"
	echo "| **total** | **$total_reused** | | **$written** | $(ratio "$written" "$total_reused") | $(pct "$written" "$total_reused") % | | |"
	echo
	echo "| counted once | code lines |"
	echo "|---|---:|"
	echo "| shared glue (hacks/ headers and helpers) | $shared_glue |"
	echo "| shared shim (linux_compat + rtos_stub) | $shim_code |"
	echo "| tests | $test_code |"
	echo "| SDK libraries for apps, written here (api/library: libcpp-ev3) | $slib_code |"
	echo
	echo "- Without the shared shim: wrote $written lines to reuse $total_reused — written/reused $(ratio "$written" "$total_reused"), $(pct "$written" "$total_reused") % of the coding saved."
	echo "- With the shared shim: wrote $written_shim lines — written/reused $(ratio "$written_shim" "$total_reused"), $(pct "$written_shim" "$total_reused") % saved."
	echo "- \"Coding saved\" = 1 − written/reused: the share of the reused code that did not have to be written."
} | tee "$md"

# The users' modules: pristine, and compiled unmodified by every configuration.
if [ -n "${LEGACY_HACK_DIRS:-}" ] && [ "${modules[0]}" != custom ]; then
	legacy_rows=()
	while read -r hack drv; do
		[ -n "$drv" ] || continue
		src=$(hash_of "$drv")
		pristine=$(awk -v f="$drv" '$2 == f { print $1 }' "${LEGACY_PRISTINE:-/dev/null}" 2>/dev/null | head -n 1)
		cells="" bad=0
		if [ -z "$pristine" ]; then
			cells+="pristine:MISSING "; bad=1
			echo "report: $drv: no pristine sha256 recorded in ${LEGACY_PRISTINE:-(none)}" >&2
		elif [ "$pristine" != "$src" ]; then
			cells+="pristine:DIFFERS "; bad=1
			echo "report: $drv differs from its pristine source (sha256 $src, pristine $pristine in $LEGACY_PRISTINE)" >&2
		else
			cells+="pristine:ok "
		fi
		for c in ${LEGACY_CONFIGS:-}; do
			h=$(recorded_hash "$c" "$drv" legacy)
			if [ "$h" = "$src" ]; then cells+="$c:ok "
			elif [ "$h" = "-" ]; then cells+="$c:MISSING "; bad=1
				echo "report: $drv: no compile-time hash recorded by the $c build" >&2
			else cells+="$c:DIFFERS "; bad=1
				echo "report: $drv: the $c build compiled a different file (sha256 $h, tree $src)" >&2
			fi
		done
		[ $bad = 0 ] || proof_failures=$((proof_failures + 1))
		name=$(basename "$drv" .c)
		legacy_rows+=("| $name | \`$drv\` | $(cloc_code "$drv") | $([ $bad = 0 ] && echo 0 || echo n/a) | \`$(echo "$src" | cut -c1-16)\` | ${cells% } |")
		echo "legacy:$name,1,$(cloc_code "$drv"),$([ $bad = 0 ] && echo 0 || echo n/a),,$(echo "$src" | cut -c1-16),${cells% }" >> "$csv"
	done < <(bash cloc_report/find_drivers.sh "$LEGACY_HACK_DIRS" "")
	{
		echo
		echo "Users' 2.6-era modules (tests/legacy: conformance modules run by the tests; not in the ratios):"
		echo
		echo "| module | source | code lines | modified lines | sha256 | pristine, and compiled unmodified by |"
		echo "|---|---|---:|---:|---|---|"
		printf '%s\n' "${legacy_rows[@]}"
	} | tee -a "$md"
fi
if [ $proof_failures -gt 0 ]; then
	echo "report: FAILED: $proof_failures driver(s) without a compile-time proof of 0 modified lines" >&2
	exit 1
fi

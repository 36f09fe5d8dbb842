#!/usr/bin/env bash
# reuse_report.sh — reused versus written lines, counted by cloc.
#
#   reuse_report.sh OUTDIR                      ev3lx's own modules (one per ev3_drivers/d_*.c)
#   reuse_report.sh OUTDIR REUSED GLUE [SHIM]   any port: dirs or files, space-separated
#
# Every number is a sum of cloc's own per-file "code" counts (--by-file, with
# --skip-uniqueness so identical files are not merged); nothing here counts
# lines itself.  For ev3lx's modules the report also proves that the driver
# files compiled by kbuild and by the RTOS/host builds are byte-identical to
# ev3_drivers/ (0 modified lines) by hashing the files named in each build's
# dependency files.
set -euo pipefail
out=$1; shift
mkdir -p "$out"

# Expands dirs into their C sources and headers; keeps files; drops what is missing.
expand() {
	local p
	for p in "$@"; do
		if [ -d "$p" ]; then find "$p" -type f \( -name '*.c' -o -name '*.h' -o -name '*.S' \) | sort
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

# Where a build compiled a source from, per its dependency file (first match).
dep_source() {   # dep_source DEPFILE BASENAME
	[ -f "$1" ] || return 0
	tr ' \\' '\n\n' < "$1" | grep -E "(^|/)$2\$" | grep -v '^$' | head -n 1
}
hash_of() { [ -n "$1" ] && [ -f "$1" ] && sha256sum "$1" | cut -c1-16 || echo "-"; }

md="$out/reuse.md"; csv="$out/reuse.csv"
echo "module,reused_files,reused_code,modified_lines,glue_code,source_sha256,kbuild_sha256,rtos_sha256" > "$csv"

if [ $# -ge 2 ]; then
	mapfile -t reused < <(expand $1)
	mapfile -t glue < <(expand $2)
	mapfile -t shim < <(expand ${3:-})
	modules=(custom)
else
	# one module per driver: ev3_drivers/d_<m>.c with hacks/<m>_hack.[ch]
	modules=(); for f in ev3_drivers/d_*.c; do m=${f#ev3_drivers/d_}; modules+=("${m%.c}"); done
	mapfile -t shim < <(expand linux_compat rtos_stub/include rtos_stub/src)
fi
mapfile -t tests < <(expand tests)

total_reused=0; total_glue=0; rows=()
for m in "${modules[@]}"; do
	if [ "$m" = custom ]; then
		r_files=("${reused[@]}"); g_files=("${glue[@]}")
		modified="n/a"; src_h="-"; kb_h="-"; rt_h="-"
	else
		drv=ev3_drivers/d_$m.c
		r_files=(); for f in "$drv" "ev3_drivers/lms_$m.h"; do [ -f "$f" ] && r_files+=("$f"); done
		g_files=(); for f in "hacks/${m}_hack.c" "hacks/${m}_hack.h"; do [ -f "$f" ] && g_files+=("$f"); done
		src_h=$(hash_of "$drv")
		kb_src=$(sed -n "s/^source_.*d_$m.o := //p" "build/kbuild/.d_$m.o.cmd" 2>/dev/null | head -n 1 || true)
		kb_h=$(hash_of "$kb_src")
		rt_src=$(dep_source "build/host/obj/hacks/${m}_hack.d" "d_$m.c" || true)
		rt_h=$(hash_of "$rt_src")
		# Modified lines: diff of the compiled copies against the tree (0 when identical).
		modified=0
		for built in "$kb_src" "$rt_src"; do
			[ -n "$built" ] && [ -f "$built" ] && [ -f "$drv" ] || continue
			n=$(diff "$drv" "$built" | grep -c '^[<>]' || true)
			modified=$((modified + n))
		done
	fi
	rc=$(cloc_code "${r_files[@]}"); gc=$(cloc_code "${g_files[@]}")
	total_reused=$((total_reused + rc)); total_glue=$((total_glue + gc))
	rows+=("| $m | $rc | $modified | $gc | $(ratio "$gc" "$rc") | $(pct "$gc" "$rc") % | \`$src_h\` | \`$kb_h\` | \`$rt_h\` |")
	echo "$m,${#r_files[@]},$rc,$modified,$gc,$src_h,$kb_h,$rt_h" >> "$csv"
done

shim_code=$(cloc_code "${shim[@]}")
test_code=$(cloc_code "${tests[@]}")
shared_glue=0
if [ "${modules[0]}" != custom ]; then
	per_module=$(IFS='|'; echo "${modules[*]}")
	mapfile -t shared_hacks < <(expand hacks | grep -vE "/($per_module)_hack\.[ch]\$" || true)
	shared_glue=$(cloc_code "${shared_hacks[@]}")
fi
written=$((total_glue + shared_glue))
written_shim=$((written + shim_code))
echo "total,,$total_reused,,$written,,," >> "$csv"
echo "shared_shim,,,,$shim_code,,," >> "$csv"
echo "tests,,,,$test_code,,," >> "$csv"

{
	echo "| module | reused (code lines) | modified lines | written glue | written/reused | coding saved | driver sha256 | kbuild copy | RTOS build |"
	echo "|---|---:|---:|---:|---:|---:|---|---|---|"
	printf '%s\n' "${rows[@]}"
	echo "| **total** | **$total_reused** | | **$written** | $(ratio "$written" "$total_reused") | $(pct "$written" "$total_reused") % | | | |"
	echo
	echo "| counted once | code lines |"
	echo "|---|---:|"
	echo "| shared glue (hacks/ headers and helpers) | $shared_glue |"
	echo "| shared shim (linux_compat + rtos_stub) | $shim_code |"
	echo "| tests | $test_code |"
	echo
	echo "- Without the shared shim: wrote $written lines to reuse $total_reused — written/reused $(ratio "$written" "$total_reused"), $(pct "$written" "$total_reused") % of the coding saved."
	echo "- With the shared shim: wrote $written_shim lines — written/reused $(ratio "$written_shim" "$total_reused"), $(pct "$written_shim" "$total_reused") % saved."
	echo "- \"Coding saved\" = 1 − written/reused: the share of the reused code that did not have to be written."
} | tee "$md"

#!/usr/bin/env bash
# record_driver_hashes.sh OBJ — run by the compile rule right after the compiler
# wrote OBJ and its dependency file OBJ.d: for every C source the compiler read
# besides the one it was given (the drivers a hack file #includes), records
# "sha256  path" in OBJ.drivers.  The report compares these compile-time hashes
# with the tree; nothing is recorded when no .c file was included.
set -euo pipefail
obj=$1
dep=${obj%.o}.d
out=${obj%.o}.drivers
rm -f "$out"
[ -f "$dep" ] || exit 0
# The first rule of the .d: "obj: src deps..."; the source is the first prerequisite.
mapfile -t files < <(sed -n '1,/[^\\]$/p' "$dep" | tr ' \\' '\n\n' | grep -v -e '^$' -e ':$')
[ ${#files[@]} -gt 1 ] || exit 0
for f in "${files[@]:1}"; do
	case $f in *.c) [ -f "$f" ] && sha256sum "$f" ;; esac
done > "$out.tmp"
if [ -s "$out.tmp" ]; then mv "$out.tmp" "$out"; else rm -f "$out.tmp"; fi

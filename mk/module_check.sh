#!/bin/bash
# module_check.sh NM LD LIB OUTDIR [LEGACY_MODULE ...]
# (LD: the linker with its options, one argument: "ld -m elf_i386")
# Checks the modules' private namespaces in one configuration: every module
# object in the library LIB (hacks/<name>_hack.c with its driver and
# hacks/<name>_svc.c, linked as <name>_hack.mod.o) defines no global symbol but
# its interface (<name>_hack_cfg, and the routines the library's static-API
# fragment names: hacks/hack_routines.h) and what its driver exports
# (EXPORT_SYMBOL*); and the
# users' modules given (tests/legacy, which define the same global names as
# one another) link together into one relocatable object.
set -euo pipefail
nm=$1 ld=$2 lib_name=$3 lib=$(realpath "$3") out=$4
shift 4
fail=0
mkdir -p "$out"
members=$(ar t "$lib" | grep '_hack\.mod\.o$' || true)
[ -n "$members" ] || { echo "module-check: $lib_name has no module objects"; exit 1; }
(cd "$out" && ar x "$lib" $members)
routines=$(sed -n 's/^HACK_SVC(\([a-z0-9_]*\));$/\1/p; s/^HACK_INTERFACE void \([a-z0-9_]*\)(.*$/\1/p' hacks/hack_routines.h)
count=0
for m in $members; do
	name=${m%_hack.mod.o}
	exported=$(grep -ho 'EXPORT_SYMBOL[A-Z_]*([A-Za-z_][A-Za-z0-9_]*' ev3_drivers/*.c 2>/dev/null | sed 's/.*(//' || true)
	while read -r sym; do
		sym=${sym#__odr_asan.}      # AddressSanitizer's ODR indicator of a global
		[ "$sym" = "${name}_hack_cfg" ] && continue
		grep -qx "$sym" <<<"$routines" && continue
		if grep -qx "$sym" <<<"$exported"; then continue; fi
		echo "module-check: $lib_name: module $name makes '$sym' global (neither its interface nor exported)"
		fail=1
	done < <("$nm" -g --defined-only "$out/$m" | awk 'NF == 3 { print $3 }')
	count=$((count + 1))
done
if [ $# -gt 0 ]; then
	# shellcheck disable=SC2086 # the linker's options are words of $ld
	if ! $ld -r -o "$out/users_modules.o" "$@" 2> "$out/users_modules.err"; then
		cat "$out/users_modules.err"
		echo "module-check: the users' modules do not link together: $*"
		fail=1
	fi
fi
[ $fail = 0 ] && echo "module-check: $lib_name: $count modules keep only their interface global; $# users' modules with the same global names link together"
exit $fail

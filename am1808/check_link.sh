#!/usr/bin/env bash
# check_link.sh BUILD_DIR — the AM1808 link check.
#  1. The provider defines exactly the functions the target headers declare, and
#     each is a symbol a real HRP2 firmware defines (am1808/hrp2_symbols.txt):
#     the kernel's _kernel_ names, never a user domain's plain ones.
#  2. libev3lx.a has no reference to host-only symbols (rtos_host_*, sil_host_*, hs_*).
#  3. The whole library (--whole-archive) links against the provider with zero
#     unresolved symbols.
set -euo pipefail
out=$1
cc=arm-none-eabi-gcc
nm=arm-none-eabi-nm

# 1. The API set: every non-inline function the target headers declare.
printf '#include "kernel.h"\n#include "sil.h"\n#include "t_syslog.h"\n#include "syssvc/syslog.h"\n' > "$out/api_decls.c"
$cc -std=c11 -Irtos_stub/include -DEV3LX_AM1808=1 -mcpu=arm926ej-s -marm \
	-aux-info "$out/api_decls.aux" -c "$out/api_decls.c" -o "$out/api_decls.o"
grep -E '^/\* rtos_stub/include/[a-z0-9_/]+\.h:[0-9]+:NC \*/ extern ' "$out/api_decls.aux" \
	| sed -E 's/.* ([A-Za-z_][A-Za-z0-9_]*) \(.*/\1/' | sort -u > "$out/api_symbols.all"
# calls the headers declare but bind to a name no library defines (EV3RT's that ev3lx
# does not provide: an app calling one fails to link, naming it) are nobody's to provide
$cc -E -Irtos_stub/include -DEV3LX_AM1808=1 "$out/api_decls.c" | tr '\n' ' ' \
	| grep -oE '[A-Za-z_][A-Za-z0-9_]* *\([^()]*\) *__asm__ *\( *"ev3lx_not_yet_supported__' \
	| sed -E 's/ *\(.*//' | sort -u > "$out/api_not_yet.txt"
comm -23 "$out/api_symbols.all" "$out/api_not_yet.txt" > "$out/api_symbols.txt"
$nm --defined-only -g "$out/hrp2_link_provider.o" | awk '{print $3}' | sort -u > "$out/provider_symbols.txt"
if ! diff -u "$out/api_symbols.txt" "$out/provider_symbols.txt" > "$out/provider_diff.txt"; then
	echo "link-check: the provider's symbols differ from the rtos_stub target API:"
	cat "$out/provider_diff.txt"
	exit 1
fi
grep -v '^#' am1808/hrp2_symbols.txt | sort -u > "$out/hrp2_symbols.txt"
foreign=$(comm -23 "$out/provider_symbols.txt" "$out/hrp2_symbols.txt")
if [ -n "$foreign" ]; then
	echo "link-check: the provider defines symbols no HRP2 firmware defines (am1808/hrp2_symbols.txt):"
	echo "$foreign"
	exit 1
fi
echo "link-check: provider defines exactly the $(wc -l < "$out/api_symbols.txt") functions rtos_stub declares, all HRP2's"

# 2. No host-only symbol anywhere in the target library.
leaks=$($nm -u "$out/libev3lx.a" 2>/dev/null | awk '{print $2}' | grep -E '^(rtos_host_|sil_host_|hs_)' | sort -u || true)
if [ -n "$leaks" ]; then
	echo "link-check: host-only symbols referenced by libev3lx.a:"; echo "$leaks"; exit 1
fi

# 3. Everything in the library, linked: zero unresolved symbols.
$cc -mcpu=arm926ej-s -marm -nostartfiles -T am1808/ev3lx.ld -specs=nano.specs \
	-o "$out/linkcheck.elf" "$out/startup.o" "$out/fw_main.o" "$out/hrp2_link_provider.o" \
	"$out/newlib_glue.o" "$out/fw_api_roots.o" \
	-Wl,--whole-archive "$out/libev3lx.a" -Wl,--no-whole-archive \
	-Wl,--start-group -lc_nano -lgcc -Wl,--end-group -Wl,--warn-common \
	2> "$out/linkcheck.log" || { cat "$out/linkcheck.log"; echo "link-check: FAILED"; exit 1; }
undef=$($nm -u "$out/linkcheck.elf" | wc -l)
if [ "$undef" != 0 ]; then
	$nm -u "$out/linkcheck.elf"; echo "link-check: $undef unresolved symbols"; exit 1
fi
objs=$(ar t "$out/libev3lx.a" | wc -l)
echo "link-check: libev3lx.a ($objs objects) links whole with 0 unresolved symbols"

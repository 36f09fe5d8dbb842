#!/bin/bash
# check_sections.sh LIB... — every allocated section of every object of the
# libraries is one an HRP2 firmware's memory configuration places: HRP2's
# standard sections (.text, .rodata, .rodata.str1.4, .data, .bss: the
# configurator's linker script for the ARM core, arch/arm_gcc/common/core.tf
# of ev3rt-git/ev3rt-hrp2, and EV3RT's generated ldscript.ld) and the sections
# the library's fragment cfg/ev3lx.cfg declares itself (ATA_SEC, ATT_SEC),
# and the two tables am1808/hrp2_sections.ld adds to the firmware's link.
# Anything else — .bss.x or .data.x of -fdata-sections, .text.x, a merged
# string or constant section — would be an orphan of that script or land in
# memory no domain owns: the check fails naming the object and the section.
set -euo pipefail
standard=".text .rodata .rodata.str1.4 .data .bss"
declared=$( { sed -n 's/^[[:space:]]*AT[AT]_SEC("\([^"]*\)".*/\1/p' cfg/ev3lx.cfg;
	sed -n 's/^[[:space:]]*\([a-z_]*\) ALIGN(4) : { KEEP.*/\1/p' am1808/hrp2_sections.ld; } | tr '\n' ' ')
fail=0 objects=0 sections=0
for lib in "$@"; do
	while read -r obj sec; do
		sections=$((sections + 1))
		case " $standard $declared " in *" $sec "*) continue ;; esac
		echo "section-check: $lib($obj): section $sec is placed by no HRP2 memory configuration (an orphan)"
		fail=1
	done < <(arm-none-eabi-objdump -h "$lib" | awk '
		/:[[:space:]]+file format/ { obj = $1; sub(/:$/, "", obj); next }
		/^ *[0-9]+ / { name = $2; next }
		/ALLOC/ { print obj, name }')
	objects=$((objects + $(arm-none-eabi-ar t "$lib" | wc -l)))
done
[ $fail = 0 ] && echo "section-check: $objects objects, $sections allocated sections, each HRP2's ($standard) or the fragment's ($declared)"
exit $fail

#!/usr/bin/env bash
# size_report.sh BUILD_DIR — text/data/bss per component of libev3lx.a.
# Each symbol is attributed to the source file it is defined in (nm -l, from the
# objects' debug info), so a hack object splits into the driver it includes and
# the hack's own glue.  .rodata counts as text, as arm-none-eabi-size does.
set -euo pipefail
out=$1
nm=arm-none-eabi-nm
component_of() {
	case "$1" in
	*rtos_stub/*)              echo "rtos glue" ;;
	*linux_compat/*)           echo "linux_compat" ;;
	*ev3_drivers/*.c*)        f=${1##*ev3_drivers/}; echo "driver ${f%%.c*}" ;;
	*hacks/*_hack.c*)         f=${1##*hacks/}; echo "hack ${f%%_hack.c*}" ;;
	*hacks/*_svc.c*)          f=${1##*hacks/}; echo "hack ${f%%_svc.c*}" ;;
	*hacks/*)                  echo "hacks (shared)" ;;
	*api/*)                    echo "api" ;;
	*newlib*|*libgcc*)         echo "libc + libgcc" ;;
	*)                         echo "other" ;;
	esac
}
declare -A text data bss itext
# one component per driver (ev3_drivers/*.c) and per hack (hacks/<m>_hack.c)
drivers=(); hacks=()
for f in ev3_drivers/*.c; do m=${f#ev3_drivers/}; drivers+=("driver ${m%.c}"); done
for f in hacks/*_hack.c; do m=${f#hacks/}; hacks+=("hack ${m%_hack.c}"); done
order=("rtos glue" "linux_compat" "${drivers[@]}" "${hacks[@]}" "hacks (shared)" "api" "libc + libgcc" "other")
for c in "${order[@]}"; do text[$c]=0; data[$c]=0; bss[$c]=0; itext[$c]=0; done

# attribute FILE FALLBACK_SOURCE ARRAY-PREFIX: adds each defined symbol's size to its component.
attribute() {
	local file=$1 src=$2 image=$3
	while read -r _addr size type _name where; do
		[ -n "${size:-}" ] || continue
		c=$(component_of "${where:-$src}")
		[ "$c" = other ] && [ -n "$src" ] && c=$(component_of "$src")
		[ "$c" = other ] && [ "$image" = 1 ] && [ -z "$where" ] && c="libc + libgcc"
		n=$((16#$size))
		if [ "$image" = 1 ]; then
			case $type in [TtRr]) itext[$c]=$(( ${itext[$c]} + n )) ;; esac
			continue
		fi
		case $type in
		[TtRr]) text[$c]=$(( ${text[$c]} + n )) ;;
		[Dd])   data[$c]=$(( ${data[$c]} + n )) ;;
		[BbCc]) bss[$c]=$(( ${bss[$c]} + n )) ;;
		esac
	done < <($nm -S -l --defined-only "$file" 2>/dev/null \
		| awk -v image="$image" 'NF>=4 && $3 ~ /^[A-Za-z]$/ && !(image && seen[$1]++) \
			{f=$5; sub(/:[0-9]+$/,"",f); print $1, $2, $3, $4, f}')
}

while read -r obj; do
	src=${obj#"$out"/obj/}; src=${src%.o}.c
	attribute "$obj" "$src" 0
done < <(find "$out/obj" -name '*.o' | sort)

# The firmware image after --gc-sections: what a real HRP2 firmware keeps.
[ -f "$out/ev3lx.elf" ] && attribute "$out/ev3lx.elf" "" 1

printf '| %-16s | %9s | %8s | %8s | %11s |\n' component "lib text" data bss "image text"
printf '|%s|%s|%s|%s|%s|\n' ------------------ ----------: ---------: ---------: ------------:
tt=0; td=0; tb=0; ti=0
for c in "${order[@]}"; do
	[ $(( ${text[$c]} + ${data[$c]} + ${bss[$c]} + ${itext[$c]} )) -gt 0 ] || continue
	printf '| %-16s | %9d | %8d | %8d | %11d |\n' "$c" "${text[$c]}" "${data[$c]}" "${bss[$c]}" "${itext[$c]}"
	tt=$((tt + ${text[$c]})); td=$((td + ${data[$c]})); tb=$((tb + ${bss[$c]})); ti=$((ti + ${itext[$c]}))
done
printf '| %-16s | %9d | %8d | %8d | %11d |\n' total "$tt" "$td" "$tb" "$ti"
shim=$(( ${text["rtos glue"]} + ${text[linux_compat]} ))
ishim=$(( ${itext["rtos glue"]} + ${itext[linux_compat]} ))
echo
echo "lib text = every function in libev3lx.a; image text = what the firmware keeps after --gc-sections"
echo "(rooted at ev3api_cfg — the drivers and their service calls — and at every API function, as an application using all of the API); .rodata counts as text."
echo "linux_compat + rtos glue .text: $shim bytes in the library, $ishim bytes in the image (target <= 8192 at -Os)"

#!/usr/bin/env bash
# size_report.sh BUILD_DIR — text/data/bss per component of libev3lx.a (issue 8).
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
	*ev3_drivers/d_pwm.c*)     echo "driver d_pwm" ;;
	*ev3_drivers/d_analog.c*)  echo "driver d_analog" ;;
	*ev3_drivers/d_uart.c*)    echo "driver d_uart" ;;
	*hacks/pwm_hack.c*)        echo "hack pwm" ;;
	*hacks/analog_hack.c*)     echo "hack analog" ;;
	*hacks/uart_hack.c*)       echo "hack uart" ;;
	*hacks/*)                  echo "hacks (shared)" ;;
	*api/*)                    echo "api" ;;
	*)                         echo "other" ;;
	esac
}
declare -A text data bss
order=("rtos glue" "linux_compat" "driver d_pwm" "driver d_analog" "driver d_uart" \
	"hack pwm" "hack analog" "hack uart" "hacks (shared)" "api" "other")
for c in "${order[@]}"; do text[$c]=0; data[$c]=0; bss[$c]=0; done
while read -r obj; do
	src=${obj#"$out"/obj/}; src=${src%.o}.c
	while read -r _addr size type _name file; do
		[ -n "${size:-}" ] || continue
		where=${file:-$src}
		c=$(component_of "$where")
		[ "$c" = other ] && c=$(component_of "$src")
		n=$((16#$size))
		case $type in
		[TtRr]) text[$c]=$(( ${text[$c]} + n )) ;;
		[Dd])   data[$c]=$(( ${data[$c]} + n )) ;;
		[BbCc]) bss[$c]=$(( ${bss[$c]} + n )) ;;
		esac
	done < <($nm -S -l --defined-only "$obj" 2>/dev/null | awk 'NF>=4 {f=$5; sub(/:[0-9]+$/,"",f); print $1, $2, $3, $4, f}')
done < <(find "$out/obj" -name '*.o' | sort)

printf '| %-16s | %8s | %8s | %8s |\n' component text data bss
printf '|%s|%s|%s|%s|\n' ------------------ ---------- ---------- ----------
tt=0; td=0; tb=0
for c in "${order[@]}"; do
	[ $(( ${text[$c]} + ${data[$c]} + ${bss[$c]} )) -gt 0 ] || continue
	printf '| %-16s | %8d | %8d | %8d |\n' "$c" "${text[$c]}" "${data[$c]}" "${bss[$c]}"
	tt=$((tt + ${text[$c]})); td=$((td + ${data[$c]})); tb=$((tb + ${bss[$c]}))
done
printf '| %-16s | %8d | %8d | %8d |\n' total "$tt" "$td" "$tb"
shim=$(( ${text["rtos glue"]} + ${text[linux_compat]} ))
echo
echo "linux_compat + rtos glue .text: $shim bytes (target <= 8192 at -Os)"

#!/bin/bash
# platform_syms.sh OBJ CPP... — prints the global names an EV3RT app may see
# in the platform object OBJ (the library, linked whole): every name OBJ
# defines that the app's headers name (ev3api.h and what it includes, the
# API's configuration table, ev3api_cfg.h, TOPPERS's serial and syslog
# headers, EV3RT's platform interface layer, in both kernel profiles), and
# $PLATFORM_KEEP (names the runner reaches).  CPP... preprocesses C with the
# app's include path.
set -euo pipefail
obj=$1; shift
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf '#include "%s"\n' ev3api.h ev3api_cfg.h syssvc/serial.h syssvc/syslog.h t_stdlib.h platform_interface_layer.h > "$tmp/app.c"
{ "$@" -E -DTOPPERS_CFG1_OUT "$tmp/app.c"; "$@" -E -DTOPPERS_CFG1_OUT -DEV3LX_KERNEL_HRP3 "$tmp/app.c"; } |
	grep -v '^#' | grep -oE '[A-Za-z_][A-Za-z0-9_]*' | sort -u > "$tmp/named"
nm -g --defined-only "$obj" | awk 'NF == 3 { print $3 }' | sort -u > "$tmp/defined"
# an app built in the HRP3 profile calls the kernel's HRP3 entry points,
# which kernel.h names in asm labels ("ev3lx_hrp3_" "tslp_tsk")
{ comm -12 "$tmp/named" "$tmp/defined"; grep '^ev3lx_hrp3_' "$tmp/defined" || true
  printf '%s\n' ${PLATFORM_KEEP:-}; } | sort -u

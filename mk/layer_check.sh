#!/bin/bash
# layer_check.sh OBJDIR... — checks that the code follows the layers of
# mk/layers.mk (which passes LAYERS, LAYER_EDGES_<layer> and HDR_<layer> in
# the environment):
#   1. every #include line of every source and header, resolved as the
#      compiler would (quotes: the including file's directory first, then the
#      layers' header directories), reaches the file's own layer or a layer
#      it may use; a driver reaches only linux_compat's Linux headers; target
#      code outside a host/ directory never names rtos_stub's host interface;
#      only hacks include another layer's .c file (the verbatim driver);
#   2. every undefined symbol of an object in OBJDIR (one per configuration)
#      that another layer's object defines is an edge the first layer may use;
#      inside host_sim, an object of host_sim/src/<sublayer>/ uses only its own
#      sublayer and those before it in SUBLAYERS_host_sim.
# Prints each violation and exits 1 if there is any.
set -u
export LC_ALL=C

fail=0
violation() { echo "layer-check: $*"; fail=1; }

layer_of() { echo "${1%%/*}"; }
may_use() {  # may_use FROM TO
	local edges="LAYER_EDGES_$1"
	[ "$1" = "$2" ] && return 0
	case " ${!edges:-} " in *" $2 "*) return 0 ;; esac
	return 1
}

hdr_dirs=()
for l in $LAYERS; do
	v="HDR_$l"
	for d in ${!v:-}; do hdr_dirs+=("$d"); done
done

# Normalizes a relative path ("a/b/../c" -> "a/c") into $norm.
normalize() {
	local IFS=/ part out=()
	for part in $1; do
		case $part in
		'' | .) ;;
		..) [ ${#out[@]} -gt 0 ] && unset 'out[${#out[@]}-1]' ;;
		*) out+=("$part") ;;
		esac
	done
	norm="${out[*]}"
}

# The file an #include names into $target, or "" for a system header.
declare -A found
resolve() {  # resolve INCLUDING_FILE NAME QUOTED
	local dir key
	target=""
	if [ "$3" = 1 ] && [ -f "${1%/*}/$2" ]; then
		normalize "${1%/*}/$2"
		target=$norm
		return
	fi
	key=$2
	if [ -n "${found[$key]+set}" ]; then
		target=${found[$key]}
		return
	fi
	for dir in "${hdr_dirs[@]}"; do
		if [ -f "$dir/$2" ]; then
			target="$dir/$2"
			break
		fi
	done
	found[$key]=$target
}

# ---- 1. include edges ----
nfiles=0
nincludes=0
for l in $LAYERS; do
	[ -d "$l" ] || continue
	while IFS= read -r f; do
		nfiles=$((nfiles + 1))
		while IFS=: read -r line text; do
			if [[ $text =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*([\<\"])([^\>\"]+)[\>\"] ]]; then
				name=${BASH_REMATCH[2]}
				quoted=0; [ "${BASH_REMATCH[1]}" = '"' ] && quoted=1
			else
				continue
			fi
			resolve "$f" "$name" "$quoted"
			[ -n "$target" ] || continue
			nincludes=$((nincludes + 1))
			to=${target%%/*}
			if ! may_use "$l" "$to"; then
				violation "$f:$line: $l includes $target ($to is not a layer $l may use)"
				continue
			fi
			if [ "$l" != "$to" ] && [[ $target == *.c ]] && ! { [ "$l" = hacks ] && [ "$to" = ev3_drivers ]; }; then
				violation "$f:$line: includes $target, another layer's source file"
			fi
			if [ "$l" = ev3_drivers ] && [ "$to" = linux_compat ] &&
			   ! [[ $target =~ ^linux_compat/(include/(linux|asm|asm-generic)|mach-davinci/include/mach)/ ]]; then
				violation "$f:$line: the driver includes $target, which is not a Linux header"
			fi
			if [ "$target" = rtos_stub/include/rtos_host.h ] && [[ $f != */host/* ]] &&
			   case " linux_compat ev3_drivers hacks api am1808 " in *" $l "*) true ;; *) false ;; esac; then
				violation "$f:$line: target code includes the host kernel's interface (rtos_host.h)"
			fi
		done < <(grep -n '^[[:space:]]*#[[:space:]]*include' "$f")
	done < <(find "$l" \( -name '*.c' -o -name '*.h' \) | sort)
done

# ---- 2. link edges ----
# The objects of OBJDIR whose sources still exist (OBJDIR/path/x.o, or an x.o.*.o made from
# it, comes from path/x.c, relative to the directory the check runs in), NUL-separated: an
# object an old build tree keeps of a moved or deleted file is no part of the build.
current_objects() {
	(cd "$1" && find . -name '*.o' -print0 | sort -z) |
		while IFS= read -r -d '' o; do
			src=${o#./}
			[ -f "${src%%.o*}.c" ] && printf '%s\0' "$o"
		done
}

nedges=0
for objdir in "$@"; do
	[ -d "$objdir" ] || { violation "no objects in $objdir (build first)"; continue; }
	defs=$(mktemp)
	undefs=$(mktemp)
	# "symbol layer object" lines, one nm run each over every object of the configuration
	(current_objects "$objdir" | (cd "$objdir" && xargs -0 -r nm -A --defined-only -g 2>/dev/null)) |
		awk '{ split($1, p, ":"); o = substr(p[1], 3); split(o, d, "/");
		       if (NF >= 3 && $(NF-1) !~ /^[wWvV]$/) print $NF, d[1], o }' > "$defs"
	(current_objects "$objdir" | (cd "$objdir" && xargs -0 -r nm -A -u 2>/dev/null)) |
		awk '{ split($1, p, ":"); o = substr(p[1], 3); split(o, d, "/"); print $NF, d[1], o }' > "$undefs"
	# symbol user-layer user-object defining-layer defining-object, one line per cross-layer use
	while read -r sym from user to def; do
		nedges=$((nedges + 1))
		may_use "$from" "$to" || violation "$user uses $sym of $def ($to is not a layer $from may use)"
	done < <(sort -k1,1 "$defs" | join -1 1 -2 1 -o 2.1,2.2,2.3,1.2,1.3 - <(sort -k1,1 "$undefs") |
		 awk '$2 != $4')
	# host_sim's sublayers: symbol user-object defining-object within host_sim
	while read -r sym user def; do
		u=${user#host_sim/src/}; u=${u%%/*}
		d=${def#host_sim/src/}; d=${d%%/*}
		[ "$u" = "$d" ] && continue
		nedges=$((nedges + 1))
		ui=-1; di=-1; i=0
		for s in ${SUBLAYERS_host_sim:-}; do
			[ "$s" = "$u" ] && ui=$i
			[ "$s" = "$d" ] && di=$i
			i=$((i + 1))
		done
		if [ "$ui" -lt 0 ] || [ "$di" -lt 0 ] || [ "$di" -gt "$ui" ]; then
			violation "$user uses $sym of $def (host_sim's $u may not use its $d)"
		fi
	done < <(sort -k1,1 "$defs" | join -1 1 -2 1 -o 2.1,2.3,1.3 - <(sort -k1,1 "$undefs") |
		 awk '$2 ~ /^host_sim\/src\// && $3 ~ /^host_sim\/src\//')
	rm -f "$defs" "$undefs"
done

if [ "$fail" = 0 ]; then
	echo "layer-check: $nincludes includes in $nfiles files and $nedges cross-layer symbol uses follow the layers"
fi
exit "$fail"

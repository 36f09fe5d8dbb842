#!/usr/bin/env bash
# find_drivers.sh "HACK_DIRS" "DRIVER_DIRS" — the drivers, found by what the hack
# files include: for every C file in HACK_DIRS and DRIVER_DIRS that #includes a
# ".c" file, prints "hack driver" (the driver resolved in the hack's directory,
# then in DRIVER_DIRS), one pair per line, sorted.  Any driver name will do.
set -euo pipefail
hack_dirs=$1; driver_dirs=$2
for dir in $hack_dirs $driver_dirs; do
	[ -d "$dir" ] || continue
	find "$dir" -maxdepth 1 -name '*.c' | sort | while IFS= read -r hack; do
		sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\.c\)".*/\1/p' "$hack" |
		while IFS= read -r inc; do
			for d in "$(dirname "$hack")" $driver_dirs; do
				if [ -f "$d/$inc" ]; then echo "$hack ${d#./}/$inc"; break; fi
			done
		done
	done
done | sort -u

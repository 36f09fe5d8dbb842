#!/bin/bash
# update_readme.sh README TABLE — replaces what README holds between the lines
# "<!-- bench-table:begin -->" and "<!-- bench-table:end -->" with TABLE.
set -euo pipefail
readme=$1 table=$2
grep -q '^<!-- bench-table:begin -->$' "$readme" && grep -q '^<!-- bench-table:end -->$' "$readme" ||
	{ echo "update_readme: $readme has no bench-table markers" >&2; exit 1; }
awk -v table="$table" '
/^<!-- bench-table:begin -->$/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
/^<!-- bench-table:end -->$/ { skip = 0 }
!skip' "$readme" > "$readme.tmp"
mv "$readme.tmp" "$readme"

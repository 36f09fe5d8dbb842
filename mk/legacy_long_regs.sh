#!/usr/bin/env bash
# legacy_long_regs.sh MODULE OBJ — the register pointers of a users' module
# (tests/legacy) that a 64-bit host cannot run: every variable or struct
# member of OBJ (its DWARF debug information) that points to a volatile
# `long` or `unsigned long`.  Such a pointer is how 2.6-era AM1808 drivers
# declare a register array indexed by register number (LEGO's lms2012
# d_analog: `volatile unsigned long *Spi0; Spi0[SPIGCR1] = ...`); on the
# ARM926, as on any ILP32 target, `long` is 4 bytes and p[n] is register n,
# at 4n; on an LP64 host it is 8 bytes, so p[n] is 8n bytes on, another
# register, with an access twice a register's width — an address that is
# already wrong when the instruction runs, which no trap can repair.  Prints
# one line per such pointer (nothing if there is none):
#   MODULE: NAME is a volatile (unsigned) long pointer: ...
set -euo pipefail
module=$1 obj=$2
readelf --debug-dump=info "$obj" 2>/dev/null | awk -v module="$module" '
	# a DIE: " <depth><offset>: Abbrev Number: N (DW_TAG_x)"
	/^ *<[0-9]+><[0-9a-f]+>: Abbrev Number: [0-9]+ \(DW_TAG_/ {
		match($0, /><[0-9a-f]+>/); cur = substr($0, RSTART + 2, RLENGTH - 3)
		match($0, /\(DW_TAG_[a-z_]+\)/); tag[cur] = substr($0, RSTART + 8, RLENGTH - 9)
		order[++n] = cur
		next
	}
	/^ *<[0-9a-f]+> +DW_AT_name / {
		v = $0; sub(/.*DW_AT_name *: */, "", v); sub(/^\(.*\): /, "", v); name[cur] = v; next
	}
	/^ *<[0-9a-f]+> +DW_AT_type / {
		v = $0; sub(/.*<0x/, "", v); sub(/>.*/, "", v); type[cur] = v; next
	}
	# the type a chain of typedefs and qualifiers stands for; volatile_seen set if one was volatile
	function strip(t) {
		while (t != "" && (tag[t] == "typedef" || tag[t] == "const_type" || tag[t] == "volatile_type")) {
			if (tag[t] == "volatile_type") volatile_seen = 1
			t = type[t]
		}
		return t
	}
	END {
		for (i = 1; i <= n; i++) {
			d = order[i]
			if ((tag[d] != "variable" && tag[d] != "member") || !(d in type) || name[d] == "") continue
			volatile_seen = 0
			p = strip(type[d])
			if (tag[p] != "pointer_type" || !(p in type)) continue
			volatile_seen = 0
			b = strip(type[p])
			if (!volatile_seen || tag[b] != "base_type") continue
			if (name[b] != "long unsigned int" && name[b] != "long int") continue
			printf "%s: %s is a pointer to volatile %s, 8 bytes on this 64-bit host and 4 on the ARM926: " \
				"%s[n] is 8n bytes on, not register n at 4n (a wrong register address, with an 8-byte access); " \
				"the module runs in host32 and arm926-test\n", module, name[d], name[b] == "long int" ? "long" : "unsigned long", name[d]
		}
	}' | sort -u

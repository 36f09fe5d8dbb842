#!/bin/sh
# app_paths_check.sh — `ev3sim run APP_DIR` on app directories whose paths
# make cannot hold, two directories of one name, four first runs of one app
# at once, and runs that cannot execute (TAP; make ev3sim-app-path-check runs
# it with EV3SIM, the program, and WORK, a scratch directory it empties).
set -u
: "${EV3SIM:?}" "${WORK:?}"
SAY=$(cd "$(dirname "$0")/apps/say" && pwd)
n=0
failed=0

# ok CONDITION-STATUS NAME: one TAP line; the output of the last run on failure
ok() {
	n=$((n + 1))
	if [ "$1" = 0 ]; then
		echo "ok $n - $2"
	else
		echo "not ok $n - $2"
		failed=$((failed + 1))
		sed 's/^/# /' "$WORK/out.txt"
	fi
}

# copy_say DIR [TEXT]: the say app in DIR, logging TEXT
copy_say() {
	mkdir -p "$1"
	cp "$SAY/app.c" "$SAY/app.cfg" "$SAY/app.h" "$1/"
	if [ $# -gt 1 ]; then
		sed "s|^#define SAY_WHAT .*|#define SAY_WHAT \"$2\"|" "$SAY/app.h" > "$1/app.h"
	fi
}

# run DIR: ev3sim run DIR for a virtual second, output in out.txt
run() {
	"$EV3SIM" run "$1" --seconds 1 > "$WORK/out.txt" 2>&1
}

# said TEXT: the last run logged "say: TEXT" and ended with a clean summary
said() {
	grep -q "NOTICE: say: $1\$" "$WORK/out.txt" &&
		tail -n 1 "$WORK/out.txt" | grep -q " warnings=0 errors=0 bugs=0 "
}

echo "1..15"
root=$(dirname "$(dirname "$(dirname "$EV3SIM")")")
rm -rf "$WORK" "$root"/build/host/ev3rt/run_x__info_INJECTED_y-* "$root"/build/host/ev3rt/run_it_s_my_app___really_-* \
	"$root"/build/host/ev3rt/run_pathcheck_* "$root"/build/host/ev3rt/run_uses_lib-* \
	"$root"/build/host/ev3rt/run_uses_libcpp-* "$root"/build/host/ev3rt/run_uses_own_libcpp-*
mkdir -p "$WORK"

dir="$WORK/x\$(info INJECTED)y"
copy_say "$dir"
run "$dir"
ok $? "a directory named x\$(info INJECTED)y builds and runs"
! grep -qx INJECTED "$WORK/out.txt" && said original
ok $? "make does not expand its name"
tail -n 1 "$WORK/out.txt" | grep -q "^app=x__info_INJECTED_y "
ok $? "the summary names it x__info_INJECTED_y"

dir="$WORK/it's my app; (really)"
copy_say "$dir" "spaces"
run "$dir" && said spaces
ok $? "a path with spaces, a quote, a semicolon and parentheses builds and runs"

# an SDK library, greet, in a directory whose path make cannot hold either
lib="$WORK/sdk \$(libs)"
mkdir -p "$lib/greet/src" "$lib/greet/include"
printf 'THIS_LIB_NAME := greet\nTHIS_LIB_OBJS := greet.o\ninclude $(EV3RT_SDK_LIB_DIR)/../Makefile.slib\n' \
	> "$lib/greet/Makefile"
printf 'const char *greeting(void);\n' > "$lib/greet/include/greet.h"
printf '#include "greet.h"\nconst char *greeting(void) { return "from greet"; }\n' > "$lib/greet/src/greet.c"
dir="$WORK/uses lib"
copy_say "$dir"
sed 's|^#define SAY_WHAT .*|#include "greet.h"\n#define SAY_WHAT greeting()|' "$SAY/app.h" > "$dir/app.h"
printf 'include $(EV3RT_SDK_LIB_DIR)/greet/Makefile\n' > "$dir/Makefile.inc"
"$EV3SIM" run "$dir" --lib-dir "$lib" --seconds 1 > "$WORK/out.txt" 2>&1 && said "from greet"
ok $? "--lib-dir with a space and a '\$' in its path"

# ev3lx's own SDK libraries (api/library: libcpp-ev3) need no --lib-dir, and
# --lib-dir's are seen beside them: a C++ app on libcpp-ev3's Clock and greet
dir="$WORK/uses libcpp"
mkdir -p "$dir"
cp "$SAY/app.cfg" "$dir/"
printf '#ifdef __cplusplus\nextern "C" {\n#endif\n#include "ev3api.h"\n#include "target_test.h"\n#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)\n#ifndef TOPPERS_MACRO_ONLY\nextern void main_task(intptr_t exinf);\nextern const char *greeting(void);\n#endif\n#ifdef __cplusplus\n}\n#endif\n' \
	> "$dir/app.h"
printf '#include "app.h"\n#include "Clock.h"\nvoid main_task(intptr_t exinf)\n{\n\tev3api::Clock clock;\n\n\tclock.sleep(250);\n\tsyslog(LOG_NOTICE, "say: %%s after %%u ms", greeting(), (unsigned)clock.now());\n}\n' \
	> "$dir/app.cpp"
printf 'SRCLANG := c++\ninclude $(EV3RT_SDK_LIB_DIR)/greet/Makefile\ninclude $(EV3RT_SDK_LIB_DIR)/libcpp-ev3/Makefile\n' > "$dir/Makefile.inc"
"$EV3SIM" run "$dir" --lib-dir "$lib" --seconds 1 > "$WORK/out.txt" 2>&1 && said "from greet after 250 ms"
ok $? "ev3lx's libcpp-ev3 is there without --lib-dir, and --lib-dir's greet beside it"

# a --lib-dir library named like one of ev3lx's replaces it
lib2="$WORK/sdk2"
mkdir -p "$lib2/libcpp-ev3/src" "$lib2/libcpp-ev3/include"
printf 'THIS_LIB_NAME := libcpp-ev3\nTHIS_LIB_OBJS := mine.o\ninclude $(EV3RT_SDK_LIB_DIR)/../Makefile.slib\n' \
	> "$lib2/libcpp-ev3/Makefile"
printf 'const char *greeting(void);\n' > "$lib2/libcpp-ev3/include/greet.h"
printf '#include "greet.h"\nconst char *greeting(void) { return "from the given libcpp-ev3"; }\n' \
	> "$lib2/libcpp-ev3/src/mine.c"
dir="$WORK/uses own libcpp"
copy_say "$dir"
sed 's|^#define SAY_WHAT .*|#include "greet.h"\n#define SAY_WHAT greeting()|' "$SAY/app.h" > "$dir/app.h"
printf 'include $(EV3RT_SDK_LIB_DIR)/libcpp-ev3/Makefile\n' > "$dir/Makefile.inc"
"$EV3SIM" run "$dir" --lib-dir "$lib2" --seconds 1 > "$WORK/out.txt" 2>&1 && said "from the given libcpp-ev3"
ok $? "a --lib-dir library of the name of one of ev3lx's replaces it"

copy_say "$WORK/a/pathcheck_twin" "from a"
copy_say "$WORK/b/pathcheck_twin" "from b"
run "$WORK/a/pathcheck_twin" && said "from a"
ok $? "a/pathcheck_twin runs its own app"
run "$WORK/b/pathcheck_twin" && said "from b"
ok $? "b/pathcheck_twin, of the same name, runs its own app"
run "$WORK/a/pathcheck_twin" && said "from a"
ok $? "and a/pathcheck_twin still its own"

copy_say "$WORK/pathcheck_par"
for i in 1 2 3 4; do
	( "$EV3SIM" run "$WORK/pathcheck_par" --seconds 1 > "$WORK/par$i.txt" 2>&1; echo $? > "$WORK/par$i.rc" ) &
done
wait
status=0
for i in 1 2 3 4; do
	[ "$(cat "$WORK/par$i.rc")" = 0 ] && grep -q "NOTICE: say: original\$" "$WORK/par$i.txt" || status=1
done
cat "$WORK"/par?.txt > "$WORK/out.txt"
ok $status "four first runs of one app at once all build (one at a time) and run"

copy_say "$WORK/pathcheck_noexec"
run "$WORK/pathcheck_noexec"
runner=$(ls -d "$root"/build/host/ev3rt/run_pathcheck_noexec-*/run_pathcheck_noexec-* 2>/dev/null | grep -v '\.o$' | head -n 1)
[ -n "$runner" ] && chmod a-x "$runner"
run "$WORK/pathcheck_noexec"
status=$?
[ $status = 1 ] && grep -q "^ev3sim run: cannot execute $runner: Permission denied\$" "$WORK/out.txt"
ok $? "a runner that cannot be executed is reported with the reason and its path"
[ -n "$runner" ] && chmod a+x "$runner"

PATH=/nonexistent "$EV3SIM" run "$WORK/pathcheck_noexec" --seconds 1 > "$WORK/out.txt" 2>&1
status=$?
[ $status = 1 ] && grep -q "^ev3sim run: building .*/pathcheck_noexec failed: cannot execute make: No such file or directory\$" "$WORK/out.txt"
ok $? "make missing from PATH is reported with the reason"

make -s -C "$root" --no-print-directory 'APP=/tmp/x$(info INJECTED)y' ev3rt-app > "$WORK/out.txt" 2>&1
status=$?
[ $status != 0 ] && ! grep -qx INJECTED "$WORK/out.txt" && grep -q "make would expand its '\\$'" "$WORK/out.txt"
ok $? "make ev3rt-app refuses an APP with a '\$'"
make -s -C "$root" --no-print-directory "APP=$WORK/it's my app" ev3rt-app > "$WORK/out.txt" 2>&1
status=$?
[ $status != 0 ] && grep -q "make splits a path at spaces" "$WORK/out.txt"
ok $? "and one with a space"

[ $failed = 0 ]

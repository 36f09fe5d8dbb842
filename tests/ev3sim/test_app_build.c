/*
 * test_app_build.c — the names `ev3sim run` gives an app directory
 * (app_build.h): its name for make and the summary keeps only bytes make and
 * a key=value line can hold, and its build directory's key tells apart two
 * directories of one name.
 */
#include <string.h>
#include "tap.h"
#include "ev3sim/app_build.h"

int main(void)
{
	char name[128], key[128], other[128];

	tap_plan(9);
	ev3sim_app_name("/home/me/robots/linetrace", name, sizeof(name));
	is_str(name, "linetrace", "a plain name is kept");
	ev3sim_app_name("/tmp/x$(info INJECTED)y", name, sizeof(name));
	is_str(name, "x__info_INJECTED_y", "'$', '(', ')' and spaces become '_'");
	ev3sim_app_name("/tmp/it's my app; (really)", name, sizeof(name));
	is_str(name, "it_s_my_app___really_", "quotes, ';' and spaces too");
	ev3sim_app_name("/", name, sizeof(name));
	is_str(name, "app", "the root directory is \"app\"");
	ev3sim_app_name("/tmp/\xc3\xa9t\xc3\xa9-v1.2", name, sizeof(name));
	is_str(name, "__t__-v1.2", "non-ASCII bytes become '_', '-' and '.' stay");
	ev3sim_app_name("/tmp/aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa", name,
			sizeof(name));
	is_int((int)strlen(name), 64, "a long name is cut at 64 bytes");

	ev3sim_app_key("/home/me/a/robot", key, sizeof(key));
	ev3sim_app_key("/home/me/b/robot", other, sizeof(other));
	ok(strncmp(key, "run_robot-", 10) == 0 && strlen(key) == 10 + 16, "the key is run_NAME-HASH (%s)", key);
	ok(strcmp(key, other) != 0, "two directories named robot have different keys");
	ev3sim_app_key("/home/me/a/robot", other, sizeof(other));
	is_str(key, other, "one directory always has the same key");
	return tap_done();
}

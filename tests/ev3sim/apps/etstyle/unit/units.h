/*
 * units.h — a counting unit; u1 .. u9 are defined in unit/u1.cpp ..
 * unit/u9.cpp, one object (one module) each.
 */
#pragma once

/* Every unit registers with one registry, reached through an inline
 * function's static, as ET Robocon apps' singletons are: each unit's
 * module has its own copy of that static, and the link keeps one. */
class Registry {
public:
	static Registry &instance()
	{
		static Registry registry;
		return registry;
	}
	int units = 0;
};

class Unit {
public:
	explicit Unit(int start) : count(start) { Registry::instance().units++; }
	/* One step: the count after it. */
	int step() { return ++count; }
private:
	int count;
};

extern Unit u1, u2, u3, u4, u5, u6, u7, u8, u9;

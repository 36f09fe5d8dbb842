/*
 * units.h — a counting unit; u1 .. u9 are defined in unit/u1.cpp ..
 * unit/u9.cpp, one object (one module) each.
 */
#pragma once

class Unit {
public:
	explicit Unit(int start) : count(start) {}
	/* One step: the count after it. */
	int step() { return ++count; }
private:
	int count;
};

extern Unit u1, u2, u3, u4, u5, u6, u7, u8, u9;

/* u1.cpp — unit 1, starting at 10. */
#include "units.h"

Unit u1(10);

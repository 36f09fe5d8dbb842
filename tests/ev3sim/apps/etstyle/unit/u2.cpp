/* u2.cpp — unit 2, starting at 20. */
#include "units.h"

Unit u2(20);

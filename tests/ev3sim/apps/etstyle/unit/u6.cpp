/* u6.cpp — unit 6, starting at 60. */
#include "units.h"

Unit u6(60);

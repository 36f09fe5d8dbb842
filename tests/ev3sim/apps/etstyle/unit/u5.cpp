/* u5.cpp — unit 5, starting at 50. */
#include "units.h"

Unit u5(50);

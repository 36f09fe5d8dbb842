/* u7.cpp — unit 7, starting at 70. */
#include "units.h"

Unit u7(70);

/* u4.cpp — unit 4, starting at 40. */
#include "units.h"

Unit u4(40);

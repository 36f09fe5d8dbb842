/* u8.cpp — unit 8, starting at 80. */
#include "units.h"

Unit u8(80);

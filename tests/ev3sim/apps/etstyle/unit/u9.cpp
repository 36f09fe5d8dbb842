/* u9.cpp — unit 9, starting at 90. */
#include "units.h"

Unit u9(90);

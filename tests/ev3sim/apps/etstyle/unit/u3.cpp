/* u3.cpp — unit 3, starting at 30. */
#include "units.h"

Unit u3(30);

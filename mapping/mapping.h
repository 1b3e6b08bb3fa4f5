#pragma once
// Front door of the mapping layer.  So far: exact polygon Booleans for known space.
#include "mapping/polygon_set.h"

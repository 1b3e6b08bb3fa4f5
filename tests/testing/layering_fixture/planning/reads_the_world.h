#pragma once
// A deliberate layering violation (tests/CMakeLists.txt, layering_detects_planning_to_sim): a planning header
// that reaches into the simulator, as a navigator casting rays on the true world would.
#include "sim/raycast.h"

#pragma once
// A deliberate layering violation (tests/CMakeLists.txt, layering_detects_internal_includes): the harness
// reaching into the planning layer's internal rules instead of its navigators.
#include "planning/internal/progress.h"

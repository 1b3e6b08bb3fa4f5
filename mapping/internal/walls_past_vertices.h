#pragma once
// Walls drawn past a map vertex: where the map holds a wall a-b and a wall a-c that passes within a tolerance
// of b (two walls out of one corner, a few degrees apart) and ends more than twice the tolerance past it, the
// longer one, a-c, is not drawn in what the planners see.  Such a pair comes from a vertex c detected past a
// wall's end b seen edge-on: a-c then runs along the true wall a-b and on across the opening beyond b,
// closing it; where b-c is a wall as well, a-c only repeats it.
#include "mapping/internal/map_core.h"

namespace toponav::mapping::internal {

// 'ms' without the walls that pass within 'tolerance' (world units) of a mapped vertex joined by a map wall to
// one of their ends.
MapState WithoutWallsPastVertices(const MapCore& m, const MapState& ms, double tolerance);

}  // namespace toponav::mapping::internal

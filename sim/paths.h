#pragma once
// Paths through a world's true free space, for scripted drives (contact sheets, map building demos).
#include <vector>

#include "core/world.h"

namespace toponav::sim {

// A shortest 8-connected grid path (cell size 'cell') from 'from' to 'to' that keeps at least 'clearance' from
// walls and clutter, as a polyline with collinear grid steps merged.  Empty if no such path exists.
std::vector<core::Vec2> FreePath(const core::World& world, const core::Vec2& from, const core::Vec2& to,
                                 double clearance, double cell = 2.0);

// A drive that visits the whole free space: from 'from', repeatedly to the nearest (by path length) not yet
// visited point of a grid with the given spacing that keeps 'clearance'; the polyline of the whole tour.
std::vector<core::Vec2> CoverageTour(const core::World& world, const core::Vec2& from, double spacing,
                                     double clearance, double cell = 2.0);

// 'count' poses evenly spaced by arc length along 'path' (endpoints included), yaw along the path.
std::vector<core::Pose2> PosesAlong(const std::vector<core::Vec2>& path, int count);

}  // namespace toponav::sim

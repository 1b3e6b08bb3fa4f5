#pragma once
// A closed world that its map has sealed off.  A generated labyrinth's bounds are its outline's box, so its free
// space reaches every side of them.  A search whose known space stops short of a side has a wall in its map that
// cuts part of the world off (most often a false one across a corridor seen from afar), however explored the map
// looks: there the agent looks for the wall (planning::SuspectInspector) instead of ending the search.
#include <optional>
#include <vector>

#include "core/geometry.h"

namespace toponav::planning {

// The point nearest 'agent' on the nearest side of 'region' that no point of 'known' (outer rings) comes within
// 'reach' of; nullopt when known space reaches all four sides (or there is none).
std::optional<core::Vec2> UnreachedSide(const std::vector<core::Polygon>& known, const core::Aabb2& region,
                                        double reach, const core::Vec2& agent);

}  // namespace toponav::planning

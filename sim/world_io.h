#pragma once
// world.json: the world file format, written by `toponav world` and read by every command that takes
// --world FILE.  The format is documented in README.md ("World files").
#include <string>

#include "core/world.h"

namespace toponav::sim {

// Serialises deterministically: the same world gives the same bytes.
std::string WorldToJson(const core::World& world);
// Parses and validates (ValidateWorld); 'source' names the file in errors.  Throws core::DataError on an
// unknown or missing key (nested keys too), a wrong type, or a world ValidateWorld rejects.
core::World WorldFromJson(const std::string& text, const std::string& source);

void SaveWorld(const core::World& world, const std::string& path);
core::World LoadWorld(const std::string& path);

// What a world must satisfy so that no later stage (ray casting, Box2D motion, rendering, path grids, the
// map) can fail on it: coordinates finite and within kMaxCoordinate; polygons simple, with consecutive points
// at least kMinVertexSpacing apart and no angle sharper than kMinVertexAngle; obstacles inside the boundary
// and apart; bounds holding the map, start and goal, at most kMaxWorldSize across; start, goal and clutter
// in free space.
constexpr double kMaxCoordinate = 1e5;
constexpr double kMaxWorldSize = 1500.0;
constexpr double kMinVertexSpacing = 0.1;
constexpr double kMinVertexAngle = 0.01;  // radians
constexpr double kMaxClutterSize = 100.0;

// The checks of WorldFromJson, for worlds built in code.  Throws core::DataError naming 'source'.
void ValidateWorld(const core::World& world, const std::string& source);

}  // namespace toponav::sim

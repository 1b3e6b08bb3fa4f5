#pragma once
// world.json: the world file format, written by `toponav world` and read by every command that takes
// --world FILE.  The format is documented in README.md ("World files").
#include <string>

#include "core/world.h"

namespace toponav::sim {

// Serialises deterministically: the same world gives the same bytes.
std::string WorldToJson(const core::World& world);
// Parses and validates; 'source' names the file in errors.  Throws core::DataError on a missing key, a wrong
// type, a NaN/inf coordinate, a ring with fewer than 3 points, a self-intersecting ring, or a start outside
// free space.
core::World WorldFromJson(const std::string& text, const std::string& source);

void SaveWorld(const core::World& world, const std::string& path);
core::World LoadWorld(const std::string& path);

// The geometric checks of WorldFromJson, for worlds built in code.  Throws core::DataError naming 'source'.
void ValidateWorld(const core::World& world, const std::string& source);

}  // namespace toponav::sim

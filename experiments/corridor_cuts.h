#pragma once
// Whether a map wall closes a corridor: the world's true free space on a raster, as a disc of the agent's
// radius can travel it, split into regions; a wall that raises the number of regions of some size cuts a way
// through (a wall across a corridor or a doorway), while a wall a little off its place, or one jutting into a
// corridor from a false vertex, leaves the disc its way round.
#include <vector>

#include "core/geometry.h"
#include "core/world.h"

namespace toponav::experiments {

class FreeSpaceRegions {
 public:
  // 'radius': the disc that travels (world units); 'cell': the raster's side.
  FreeSpaceRegions(const core::World& world, double radius, double cell = 0.5);
  // The regions of at least 'min_area' (square world units) the disc reaches with the extra walls in place.
  int Count(const std::vector<core::Segment2>& walls, double min_area) const;
  // True when the wall raises the count of regions of at least 'min_area'.
  bool Cuts(const core::Segment2& wall, double min_area) const;

 private:
  core::Vec2 Center(int col, int row) const;
  double radius_, cell_;
  core::Vec2 origin_;
  int cols_ = 0, rows_ = 0;
  std::vector<char> free_;  // row-major: the disc's centre may be here
};

}  // namespace toponav::experiments

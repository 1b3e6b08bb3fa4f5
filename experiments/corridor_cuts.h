#pragma once
// Whether a map wall closes a corridor: the world's true free space on a raster, as a disc of the agent's
// radius can travel it, split into regions; a wall that raises the number of regions of some size cuts a way
// through (a wall across a corridor or a doorway), while a wall a little off its place, or one jutting into a
// corridor from a false vertex, leaves the disc its way round.
#include <vector>

#include "core/geometry.h"
#include "core/world.h"
#include "planning/raster.h"

namespace toponav::experiments {

class FreeSpaceRegions {
 public:
  // 'radius': the disc that travels (world units); regions count from 'min_area' (square world units);
  // 'cell': the raster's side.
  FreeSpaceRegions(const core::World& world, double radius, double min_area, double cell = 0.5);
  // The regions the disc reaches with the extra walls in place.
  int Count(const std::vector<core::Segment2>& walls) const;
  // True when the wall raises the count.
  bool Cuts(const core::Segment2& wall) const { return Count({wall}) > regions_; }

 private:
  double radius_;
  size_t min_cells_;
  planning::Raster raster_;
  std::vector<char> free_;  // the disc's centre may be here
  int regions_ = 0;         // without extra walls
};

}  // namespace toponav::experiments

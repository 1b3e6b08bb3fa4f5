#include "experiments/corridor_cuts.h"

#include <cmath>

#include "core/error.h"

namespace toponav::experiments {

FreeSpaceRegions::FreeSpaceRegions(const core::World& world, double radius, double min_area, double cell)
    : radius_(radius), min_cells_(size_t(std::ceil(min_area / (cell * cell)))) {
  TOPONAV_CHECK(cell > 0 && radius >= 0, "free-space raster with cell " << cell << ", radius " << radius);
  raster_ = planning::Raster::Covering(world.bounds, cell);
  free_.assign(raster_.size(), 0);
  for (int c = 0; c < int(raster_.size()); ++c)
    free_[size_t(c)] = core::SignedDistance(world, raster_.Center(c), false) > radius;
  regions_ = Count({});
}

int FreeSpaceRegions::Count(const std::vector<core::Segment2>& walls) const {
  std::vector<char> open = free_;
  for (const auto& w : walls)  // the disc's centre cannot come nearer a wall than its radius
    for (int c : planning::CellsNear(raster_, {w.a, w.b}, radius_)) open[size_t(c)] = 0;
  int regions = 0;
  for (int start = 0; start < int(open.size()); ++start) {
    if (!open[size_t(start)]) continue;
    const std::vector<double> reach = planning::CellDistances(raster_, open, {start});
    size_t cells = 0;
    for (size_t c = 0; c < reach.size(); ++c)
      if (std::isfinite(reach[c])) open[c] = 0, ++cells;
    regions += cells >= min_cells_;
  }
  return regions;
}

}  // namespace toponav::experiments

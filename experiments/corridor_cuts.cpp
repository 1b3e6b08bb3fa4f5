#include "experiments/corridor_cuts.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace toponav::experiments {

FreeSpaceRegions::FreeSpaceRegions(const core::World& world, double radius, double cell)
    : radius_(radius), cell_(cell), origin_(world.bounds.min) {
  TOPONAV_CHECK(cell > 0 && radius >= 0, "free-space raster with cell " << cell << ", radius " << radius);
  cols_ = int(std::ceil(world.bounds.width() / cell));
  rows_ = int(std::ceil((world.bounds.max.y - world.bounds.min.y) / cell));
  free_.assign(size_t(cols_) * size_t(rows_), 0);
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < cols_; ++c) free_[size_t(r) * size_t(cols_) + size_t(c)] = core::SignedDistance(world, Center(c, r), false) > radius;
}

core::Vec2 FreeSpaceRegions::Center(int col, int row) const {
  return {origin_.x + (col + 0.5) * cell_, origin_.y + (row + 0.5) * cell_};
}

int FreeSpaceRegions::Count(const std::vector<core::Segment2>& walls, double min_area) const {
  std::vector<char> open = free_;
  for (const auto& w : walls) {  // the disc's centre cannot come nearer a wall than its radius
    const int c0 = std::max(0, int(std::floor((std::min(w.a.x, w.b.x) - radius_ - origin_.x) / cell_)));
    const int c1 = std::min(cols_ - 1, int(std::floor((std::max(w.a.x, w.b.x) + radius_ - origin_.x) / cell_)));
    const int r0 = std::max(0, int(std::floor((std::min(w.a.y, w.b.y) - radius_ - origin_.y) / cell_)));
    const int r1 = std::min(rows_ - 1, int(std::floor((std::max(w.a.y, w.b.y) + radius_ - origin_.y) / cell_)));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        if (core::DistanceToSegment(Center(c, r), w) <= radius_) open[size_t(r) * size_t(cols_) + size_t(c)] = 0;
  }
  const size_t min_cells = size_t(std::ceil(min_area / (cell_ * cell_)));
  int regions = 0;
  std::vector<size_t> stack;
  for (size_t start = 0; start < open.size(); ++start) {
    if (!open[start]) continue;
    open[start] = 0;
    stack.assign(1, start);
    size_t cells = 0;
    while (!stack.empty()) {  // 4-connected flood fill
      const size_t i = stack.back();
      stack.pop_back();
      ++cells;
      const int r = int(i / size_t(cols_)), c = int(i % size_t(cols_));
      const int dr[4] = {1, -1, 0, 0}, dc[4] = {0, 0, 1, -1};
      for (int k = 0; k < 4; ++k) {
        const int rr = r + dr[k], cc = c + dc[k];
        if (rr < 0 || rr >= rows_ || cc < 0 || cc >= cols_) continue;
        const size_t j = size_t(rr) * size_t(cols_) + size_t(cc);
        if (open[j]) open[j] = 0, stack.push_back(j);
      }
    }
    regions += cells >= min_cells;
  }
  return regions;
}

bool FreeSpaceRegions::Cuts(const core::Segment2& wall, double min_area) const {
  return Count({wall}, min_area) > Count({}, min_area);
}

}  // namespace toponav::experiments

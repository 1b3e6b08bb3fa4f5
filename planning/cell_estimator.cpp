#include "planning/cell_estimator.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "core/error.h"
#include "core/range_bearing_grid.h"
#include "planning/subgoal_grid.h"

namespace toponav::planning {

using core::Vec2;

namespace {

// The world cell (of side 'cell') holding p, as one key.
uint64_t PlaceKey(const Vec2& p, double cell) {
  const auto x = int64_t(std::floor(p.x / cell)), y = int64_t(std::floor(p.y / cell));
  return (uint64_t(uint32_t(int32_t(x))) << 32) | uint64_t(uint32_t(int32_t(y)));
}

}  // namespace

void CellAveragingEstimator::Observe(const core::Observation& z) {
  if (z.subgoal.empty()) return;
  const core::SubgoalCells& g = z.subgoal;
  if (g.rows <= 0 || g.cols <= 0 || !(g.max_range > 0) || g.values.size() != size_t(g.rows) * size_t(g.cols))
    throw core::DataError("<observation>", "its subgoal cells' count does not match its rows and columns");
  pending_.push_back({z.pose, g});
  while (int(pending_.size()) > max_pending_) pending_.pop_front();
  ++observed_;
}

void CellAveragingEstimator::Accumulate(const Seen& s, const SubgoalGrid& grid) {
  const core::RangeBearingGrid rb{s.cells.rows, s.cells.cols, s.cells.max_range};
  std::unordered_set<uint64_t> done;  // a place counts once per observation
  for (size_t f = 0; f < grid.num_frontiers(); ++f)
    for (int c : grid.cells(f)) {
      const Vec2 p = grid.raster().Center(c);
      const double range = core::Distance(p, s.pose.position());
      if (range >= rb.max_range || !grid.SightClear(s.pose.position(), p)) continue;
      const uint64_t key = PlaceKey(p, grid.raster().cell);
      if (!done.insert(key).second) continue;
      const int row = rb.RangeRow(range);
      const int col = rb.BearingCol(core::WrapAngle(std::atan2(p.y - s.pose.y, p.x - s.pose.x) - s.pose.yaw));
      Sum& sum = sums_[key];
      const core::SubgoalCell& cell = s.cells.at(row, col);
      sum.ps += cell.ps;
      sum.delta_success += cell.delta_success;
      sum.exploration += cell.exploration;
      ++sum.count;
    }
}

std::vector<SubgoalProperties> CellAveragingEstimator::Estimate(const SubgoalGrid& grid,
                                                                const OrderingProblem& distances) {
  for (const Seen& s : pending_) Accumulate(s, grid);
  pending_.clear();
  const size_t n = distances.properties.size();
  std::vector<SubgoalProperties> out(n);
  seen_.assign(n, 0);
  for (size_t f = 0; f < n; ++f) {
    Sum total;
    for (int c : grid.cells(f)) {
      const auto it = sums_.find(PlaceKey(grid.raster().Center(c), grid.raster().cell));
      if (it == sums_.end()) continue;
      total.ps += it->second.ps;
      total.delta_success += it->second.delta_success;
      total.exploration += it->second.exploration;
      total.count += it->second.count;
    }
    if (total.count == 0) continue;
    seen_[f] = 1;
    out[f] = calibration_.Apply(
        {total.ps / total.count, total.delta_success / total.count, total.exploration / total.count});
  }
  return out;
}

}  // namespace toponav::planning

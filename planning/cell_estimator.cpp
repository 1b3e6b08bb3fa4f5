#include "planning/cell_estimator.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/range_bearing_grid.h"
#include "planning/subgoal_grid.h"

namespace toponav::planning {

using core::Vec2;

namespace {

int Channel(const core::CellGrid& g, const std::string& name) {
  const auto it = std::find(g.channels.begin(), g.channels.end(), name);
  if (it == g.channels.end()) throw core::DataError("<observation>", "its cell grid has no channel '" + name + "'");
  return int(it - g.channels.begin());
}

}  // namespace

void CellAveragingEstimator::Observe(const core::Observation& z) {
  if (z.cells.empty()) return;
  const core::CellGrid& g = z.cells;
  if (g.rows <= 0 || g.cols <= 0 || !(g.max_range > 0) ||
      g.values.size() != size_t(g.rows) * size_t(g.cols) * g.channels.size())
    throw core::DataError("<observation>", "its cell grid's size does not match its rows, columns and channels");
  seen_.push_back({z.pose, g, Channel(g, "ps"), Channel(g, "delta_success"), Channel(g, "exploration")});
  while (int(seen_.size()) > history_) seen_.pop_front();
}

std::vector<SubgoalProperties> CellAveragingEstimator::Estimate(const SubgoalGrid& grid, const OrderingProblem& distances) {
  const size_t n = distances.properties.size();
  std::vector<SubgoalProperties> out(n);
  for (size_t f = 0; f < n; ++f) {
    double ps = 0, ds = 0, re = 0;
    int count = 0;
    for (const Seen& s : seen_) {
      const core::RangeBearingGrid rb{s.cells.rows, s.cells.cols, s.cells.max_range};
      for (int c : grid.cells(f)) {
        const Vec2 p = grid.raster().Center(c);
        const double range = core::Distance(p, s.pose.position());
        if (range >= rb.max_range || !grid.SightClear(s.pose.position(), p)) continue;
        const int row = rb.RangeRow(range);
        const int col = rb.BearingCol(core::WrapAngle(std::atan2(p.y - s.pose.y, p.x - s.pose.x) - s.pose.yaw));
        ps += s.cells.at(row, col, s.ps);
        ds += s.cells.at(row, col, s.delta_success);
        re += s.cells.at(row, col, s.exploration);
        ++count;
      }
    }
    if (count > 0) out[f] = {ps / count, ds / count, re / count};
  }
  return out;
}

}  // namespace toponav::planning

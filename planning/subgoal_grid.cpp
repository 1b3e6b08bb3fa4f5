#include "planning/subgoal_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace toponav::planning {

using core::Vec2;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double MinOver(const std::vector<double>& dist, const std::vector<int>& cells) {
  double best = kInf;
  for (int c : cells) best = std::min(best, dist[size_t(c)]);
  return best;
}

core::Aabb2 ViewBox(const mapping::MapView& view, const Vec2& agent, const Vec2& goal) {
  core::Aabb2 box{agent, agent};
  box = core::Bounds(std::vector<Vec2>{goal}, box);
  for (const auto& p : view.known_space) box = core::Bounds(p.outer, box);
  return box;
}

// The true way through a frontier (to one of its goal-connected cells 'seeds' through seen free space, then
// to the goal through unseen free space) less the optimistic one (d_robot + d_goal); where the agent cannot
// reach those cells through seen free space (a map error), the way beyond the frontier less d_goal.
double SuccessDelta(const std::vector<int>& seeds, const std::vector<double>& robot, const std::vector<double>& to_goal,
                    double robot_cost, double goal_cost) {
  if (!std::isfinite(goal_cost)) return 0.0;
  double through = kInf;
  for (int c : seeds) through = std::min(through, robot[size_t(c)] + to_goal[size_t(c)]);
  if (std::isfinite(through) && std::isfinite(robot_cost)) return std::max(0.0, through - robot_cost - goal_cost);
  return std::max(0.0, MinOver(to_goal, seeds) - goal_cost);
}

}  // namespace

SubgoalGrid::SubgoalGrid(const mapping::MapView& view, const std::vector<const mapping::Frontier*>& frontiers,
                         const Vec2& agent, const Vec2& goal, double cell, const std::optional<core::Aabb2>& region,
                         double margin) {
  raster_ =
      region ? Raster::Covering(*region, cell, 2 * cell) : Raster::Covering(ViewBox(view, agent, goal), cell, margin);
  known_ = FillPolygons(raster_, view.known_space);
  unknown_open_.assign(raster_.size(), 0);
  for (size_t i = 0; i < known_.size(); ++i) unknown_open_[i] = !known_[i];
  // Map walls block (thick enough that no 8-connected step slips between two of their cells).
  near_walls_.assign(raster_.size(), 0);
  on_walls_.assign(raster_.size(), 0);
  for (const auto& w : view.walls) {
    for (int c : CellsNear(raster_, {w.pa, w.pb}, 0.75 * cell)) unknown_open_[size_t(c)] = 0, on_walls_[size_t(c)] = 1;
    for (int c : CellsNear(raster_, {w.pa, w.pb}, kWallShadow)) near_walls_[size_t(c)] = 1;
  }
  for (const mapping::Frontier* f : frontiers) {
    std::vector<int> mine;
    for (int c : CellsNear(raster_, f->points, 1.5 * cell))
      if (unknown_open_[size_t(c)]) mine.push_back(c);
    cells_.push_back(std::move(mine));
  }
  agent_ = raster_.CellOf(agent);
  goal_ = raster_.CellOf(goal);
}

bool SubgoalGrid::SightClear(const Vec2& a, const Vec2& b) const {
  const double length = core::Distance(a, b);
  const int steps = std::max(1, int(std::ceil(length / (0.5 * raster_.cell))));
  const int from = raster_.CellOf(a), to = raster_.CellOf(b);
  for (int k = 1; k < steps; ++k) {
    const int c = raster_.CellOf(a + (b - a) * (double(k) / steps));
    if (c >= 0 && c != from && c != to && on_walls_[size_t(c)]) return false;
  }
  return true;
}

bool SubgoalGrid::goal_known() const { return goal_ >= 0 && known_[size_t(goal_)]; }

std::vector<char> SubgoalGrid::ThroughKnown() const {
  std::vector<char> through_known = known_;
  for (const auto& cells : cells_)
    for (int c : cells) through_known[size_t(c)] = 1;
  if (agent_ >= 0) through_known[size_t(agent_)] = 1;
  return through_known;
}

OrderingProblem SubgoalGrid::Distances() const {
  const size_t n = cells_.size();
  OrderingProblem p;
  p.properties.resize(n);
  // Each search stops once the frontier cells it is asked about are settled.
  const std::vector<char> through_known = ThroughKnown();
  std::vector<int> all;
  for (const auto& cells : cells_) all.insert(all.end(), cells.begin(), cells.end());
  const std::vector<double> from_agent = CellDistances(raster_, through_known, {agent_}, &all);
  std::vector<char> open = unknown_open_;
  if (goal_ >= 0) open[size_t(goal_)] = 1;
  const std::vector<double> from_goal = CellDistances(raster_, open, {goal_}, &all);
  for (size_t f = 0; f < n; ++f) {
    p.robot_cost.push_back(MinOver(from_agent, cells_[f]));
    p.goal_cost.push_back(MinOver(from_goal, cells_[f]));
  }
  p.between.assign(n, std::vector<double>(n, 0.0));
  std::vector<int> after;  // the cells of frontiers f + 1 .. n - 1
  for (size_t g = n; g-- > 1;) {
    const size_t f = g - 1;
    after.insert(after.end(), cells_[g].begin(), cells_[g].end());
    const std::vector<double> from_f = CellDistances(raster_, through_known, cells_[f], &after);
    for (size_t h = g; h < n; ++h) p.between[f][h] = p.between[h][f] = MinOver(from_f, cells_[h]);
  }
  return p;
}

TrueFreeSpace::TrueFreeSpace(const core::World& world, double cell, double clearance) {
  raster_ = Raster::Covering(world.bounds, cell, 2 * cell);
  free_.assign(raster_.size(), 0);
  for (int c = 0; c < int(raster_.size()); ++c)
    free_[size_t(c)] = core::SignedDistance(world, raster_.Center(c), false) > clearance;
}

std::vector<char> TrueFreeSpace::On(const Raster& raster) const {
  std::vector<char> out(raster.size(), 0);
  for (int c = 0; c < int(raster.size()); ++c) {
    const int mine = raster_.CellOf(raster.Center(c));
    out[size_t(c)] = mine >= 0 && free_[size_t(mine)];
  }
  return out;
}

std::vector<SubgoalProperties> TrueSubgoalProperties(const SubgoalGrid& grid, const TrueFreeSpace& truth,
                                                     const OrderingProblem& distances) {
  const Raster& r = grid.raster();
  const std::vector<char> free = truth.On(r);
  std::vector<char> unseen(r.size(), 0);  // free in the true world, not known yet, not in a wall's shadow
  for (size_t i = 0; i < unseen.size(); ++i) unseen[i] = free[i] && !grid.known()[i] && !grid.near_walls()[i];
  // Each frontier's seeds: its cells on the unseen side.  to_goal and robot are read there only.
  std::vector<std::vector<int>> seeds(distances.properties.size());
  std::vector<int> all_seeds;
  for (size_t f = 0; f < seeds.size(); ++f)
    for (int c : grid.cells(f))
      if (unseen[size_t(c)]) seeds[f].push_back(c), all_seeds.push_back(c);
  const std::vector<double> to_goal = CellDistances(r, unseen, {grid.goal_cell()}, &all_seeds);
  std::vector<char> free_or_agent = free;
  if (grid.agent_cell() >= 0) free_or_agent[size_t(grid.agent_cell())] = 1;
  std::vector<char> seen_free = grid.ThroughKnown();  // the way to a frontier cell, in the true world
  for (size_t i = 0; i < seen_free.size(); ++i) seen_free[i] = seen_free[i] && free_or_agent[i];
  const std::vector<double> robot = CellDistances(r, seen_free, {grid.agent_cell()}, &all_seeds);
  const std::vector<double> from_agent = CellDistances(r, free_or_agent, {grid.agent_cell()});
  std::vector<SubgoalProperties> out;
  for (size_t f = 0; f < distances.properties.size(); ++f) {
    SubgoalProperties s{0.0, 0.0, 0.0};
    if (std::isfinite(MinOver(to_goal, seeds[f]))) {
      s.ps = 1.0;
      s.delta_success = SuccessDelta(seeds[f], robot, to_goal, distances.robot_cost[f], distances.goal_cost[f]);
    } else if (!seeds[f].empty()) {
      // The unseen region behind the frontier: how deep the agent would walk in and back out.
      const std::vector<double> region = CellDistances(r, unseen, seeds[f]);
      double lo = kInf, hi = -kInf;
      for (size_t c = 0; c < region.size(); ++c)
        if (std::isfinite(region[c]) && std::isfinite(from_agent[c]))
          lo = std::min(lo, from_agent[c]), hi = std::max(hi, from_agent[c]);
      if (hi >= lo) s.exploration = 2 * (hi - lo);
    }
    out.push_back(s);
  }
  return out;
}

SubgoalLabelGrid RasterizeSubgoalLabels(const SubgoalGrid& grid, const std::vector<SubgoalProperties>& properties,
                                        const core::Pose2& pose, const core::RangeBearingGrid& rb,
                                        const std::function<bool(const Vec2&)>& visible) {
  SubgoalLabelGrid out;
  out.grid = rb;
  out.mask.assign(rb.size(), 0);
  out.ps.assign(rb.size(), 0.0f);
  out.delta_success.assign(rb.size(), 0.0f);
  out.exploration.assign(rb.size(), 0.0f);
  for (size_t f = 0; f < properties.size(); ++f)
    for (int c : grid.cells(f)) {
      const Vec2 p = grid.raster().Center(c);
      const double range = core::Distance(p, pose.position());
      if (range >= rb.max_range || !visible(p)) continue;
      const double bearing = core::WrapAngle(std::atan2(p.y - pose.y, p.x - pose.x) - pose.yaw);
      const size_t i = rb.Index(rb.RangeRow(range), rb.BearingCol(bearing));
      out.mask[i] = 1;
      out.ps[i] = float(properties[f].ps);
      out.delta_success[i] = float(properties[f].delta_success);
      out.exploration[i] = float(properties[f].exploration);
    }
  return out;
}

OrderingProblem ProblemWithoutDistances(size_t frontiers) {
  OrderingProblem none;
  none.properties.resize(frontiers);
  none.robot_cost.assign(frontiers, 0.0);
  none.goal_cost.assign(frontiers, 0.0);
  none.between.assign(frontiers, std::vector<double>(frontiers, 0.0));
  return none;
}

}  // namespace toponav::planning

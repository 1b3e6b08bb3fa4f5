#pragma once
// The grid side of Learned Subgoal Planning (lsp.md §1.3, §2.1), on a raster of the map view: each
// frontier's cells (the unknown cells along it), the three distance tables the expected cost needs, and the
// frontiers' true properties (the labels, and the oracle's estimates) from the true world.
//
// Why a raster and not the polygons: the questions are geodesic distances through regions that are
// differences of polygon sets (unknown space minus map walls; true free space minus known space) and the
// farthest point of such a region, which a Dijkstra on cells answers directly; at 1 unit a cell a 14-wide
// maze corridor is 14 cells, and a maze is ~20 000 cells (a few milliseconds a question).
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/range_bearing_grid.h"
#include "core/subgoal_labels.h"
#include "core/world.h"
#include "mapping/mapping.h"
#include "planning/raster.h"
#include "planning/subgoal_ordering.h"

namespace toponav::planning {

// The map view rasterized: known space, map walls, and the cells of the frontiers asked about.
class SubgoalGrid {
 public:
  // 'region': the area the agent's world lies in (none: the view's extent, the agent and the goal, grown by
  // 'margin').  'frontiers' are the ones asked about, in order.
  SubgoalGrid(const mapping::MapView& view, const std::vector<const mapping::Frontier*>& frontiers,
              const core::Vec2& agent, const core::Vec2& goal, double cell, const std::optional<core::Aabb2>& region,
              double margin = 30.0);

  const Raster& raster() const { return raster_; }
  const std::vector<char>& known() const { return known_; }
  const std::vector<int>& cells(size_t f) const { return cells_[f]; }  // frontier f's unknown cells
  size_t num_frontiers() const { return cells_.size(); }
  bool goal_known() const;  // the goal's cell is in known space

  // d_robot (through known space and frontier cells), d_goal (the optimistic distance: through space that is
  // not known, map walls blocking) and D between frontiers (through known space): the minimum over each
  // frontier's cells; infinity where unreachable.
  OrderingProblem Distances() const;

  // Known space, the frontiers' cells and the agent's cell: where d_robot and D run.
  std::vector<char> ThroughKnown() const;

  int agent_cell() const { return agent_; }
  int goal_cell() const { return goal_; }
  // Not known and not on a map wall (the optimistic planner's unknown space).
  const std::vector<char>& unknown_open() const { return unknown_open_; }
  // Within kWallShadow of a map wall: behind a mapped wall the true world's free space reaches a little past
  // the map's (vertex estimates are off by a unit or so), and that strip must not join unseen regions.
  const std::vector<char>& near_walls() const { return near_walls_; }
  static constexpr double kWallShadow = 2.5;
  // No map wall crosses the segment a-b (sampled every half cell on the raster's wall cells).
  bool SightClear(const core::Vec2& a, const core::Vec2& b) const;

 private:
  Raster raster_;
  std::vector<char> known_, unknown_open_, near_walls_, on_walls_;
  std::vector<std::vector<int>> cells_;
  int agent_ = -1, goal_ = -1;
};

// The true world's free space on a raster (cells whose centres are at least 'clearance' from every wall and
// clutter-free), computed once per world.
class TrueFreeSpace {
 public:
  TrueFreeSpace(const core::World& world, double cell, double clearance);
  // Free cells of 'raster' (which must share this raster's cell size and grid alignment).
  std::vector<char> On(const Raster& raster) const;

 private:
  Raster raster_;
  std::vector<char> free_;
};

// The ordering problem of 'frontiers' frontiers with no distance tables (all zero): enough when the goal is
// at the agent (a search's training data), since no frontier leads to it -- the true properties read how many
// frontiers there are, and costs toward a goal only where one does.  It spares a Dijkstra per frontier.
OrderingProblem ProblemWithoutDistances(size_t frontiers);

// The true properties of each frontier of 'grid' (lsp.md §2.1): Ps = 1 when the goal can be reached through
// the frontier's unseen-but-free side, with delta_success = (the true way: the agent to a frontier cell from
// which unseen free space leads to the goal, then that way) - (d_robot + d_goal), so that d_robot + d_goal +
// delta_success is the true cost even where the frontier's nearest cells lie beyond a true wall from its
// goal-connected ones; else Ps = 0 with exploration = 2 (farthest - nearest) robot distance over the unseen
// free region behind it (a round trip to its deepest point).  A frontier with no unseen free space behind it,
// or whose region the robot cannot reach, gets Ps = 0 and exploration 0 (nothing to find there).
std::vector<SubgoalProperties> TrueSubgoalProperties(const SubgoalGrid& grid, const TrueFreeSpace& truth,
                                                     const OrderingProblem& distances);

// Frontier properties on the sensor's range-bearing grid (lsp.md §2.6): the labels the subgoal network
// learns.  Each cell of each frontier within range that 'visible' accepts (a world point: seen from the pose)
// marks its grid cell with the frontier's properties; a later frontier overwrites an earlier one.
using core::SubgoalLabelGrid;
SubgoalLabelGrid RasterizeSubgoalLabels(const SubgoalGrid& grid, const std::vector<SubgoalProperties>& properties,
                                        const core::Pose2& pose, const core::RangeBearingGrid& rb,
                                        const std::function<bool(const core::Vec2&)>& visible);

}  // namespace toponav::planning

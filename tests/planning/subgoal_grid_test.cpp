#include "planning/subgoal_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "planning/raster.h"
#include "tests/planning/dead_end_view.h"
#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

TEST(Raster, FillsPolygonsMinusHolesByCellCentre) {
  const Raster r = Raster::Covering({{0, 0}, {10, 10}}, 1.0);
  core::Polygon square{::toponav::testing::Rect(0, 0, 10, 10), {{{3, 3}, {3, 7}, {7, 7}, {7, 3}}}};
  const std::vector<char> in = FillPolygons(r, {square});
  int count = 0;
  for (char c : in) count += c != 0;
  EXPECT_EQ(count, 100 - 16);
  EXPECT_TRUE(in[size_t(r.CellOf({0.5, 0.5}))]);
  EXPECT_FALSE(in[size_t(r.CellOf({5, 5}))]) << "inside the hole";
  EXPECT_EQ(r.CellOf({-0.1, 5}), -1);
}

TEST(Raster, DistancesGoAroundBlockedCellsWithoutCuttingCorners) {
  const Raster r = Raster::Covering({{0, 0}, {10, 10}}, 1.0);
  std::vector<char> open(r.size(), 1);
  for (int y = 0; y < 9; ++y) open[size_t(r.Index(5, y))] = 0;  // a wall from the bottom up to y 9
  const std::vector<double> d = CellDistances(r, open, {r.CellOf({0.5, 0.5})});
  const double to_right = d[size_t(r.CellOf({9.5, 0.5}))];
  EXPECT_GT(to_right, 16.0) << "around the wall's top, not through it";
  EXPECT_LT(to_right, 24.0) << "octile steps, no corner cutting: a little over the Euclidean 20.1";
  open[size_t(r.Index(5, 9))] = 0;
  EXPECT_TRUE(std::isinf(CellDistances(r, open, {r.CellOf({0.5, 0.5})})[size_t(r.CellOf({9.5, 0.5}))]));
  const std::vector<int> near = CellsNear(r, {{0, 5}, {10, 5}}, 0.5);
  EXPECT_EQ(near.size(), 20u) << "the two rows of cells the line runs between";
}

TEST(Raster, ASearchAskedAboutSomeCellsStopsOnceTheyAreSettledWithTheirDistancesExact) {
  const Raster r = Raster::Covering({{0, 0}, {10, 10}}, 1.0);
  std::vector<char> open(r.size(), 1);
  for (int y = 0; y < 9; ++y) open[size_t(r.Index(5, y))] = 0;
  const int from = r.CellOf({0.5, 0.5}), near = r.CellOf({2.5, 1.5}), beyond = r.CellOf({9.5, 0.5});
  const std::vector<double> full = CellDistances(r, open, {from});
  const std::vector<int> asked{near, r.CellOf({1.5, 3.5})};
  const std::vector<double> early = CellDistances(r, open, {from}, &asked);
  for (int c : asked) EXPECT_EQ(early[size_t(c)], full[size_t(c)]);
  EXPECT_TRUE(std::isinf(early[size_t(beyond)])) << "the search stopped before the far side of the wall";
  // A cell no way reaches: the search runs to its end, every distance exact.
  std::vector<char> walled = open;
  walled[size_t(r.Index(5, 9))] = 0;
  const std::vector<int> unreachable{beyond};
  EXPECT_EQ(CellDistances(r, walled, {from}, &unreachable), CellDistances(r, walled, {from}));
}

// (Not copyable in spirit: 'frontiers' points into 'view'.)
struct Seen {
  mapping::MapView view = testing::DeadEndSeenFromStart();
  std::vector<const mapping::Frontier*> frontiers = testing::FrontiersOf(view);
};

TEST(SubgoalGrid, DistancesRunThroughKnownSpaceToFrontiersAndThroughUnknownSpaceToTheGoal) {
  const Seen s;
  const core::World w = ::toponav::testing::DeadEndMaze();
  const SubgoalGrid grid(s.view, s.frontiers, w.start.position(), w.goal, 1.0, w.bounds);
  EXPECT_FALSE(grid.goal_known());
  const OrderingProblem d = grid.Distances();
  EXPECT_NEAR(d.robot_cost[0], 29.0, 2.5);   // (7, 7) to x = 36
  EXPECT_NEAR(d.robot_cost[1], 53.0, 2.5);   // (7, 7) to y = 60
  EXPECT_NEAR(d.goal_cost[0], 91.0, 3.0);    // x = 36 straight to (127, 7) through unknown space
  EXPECT_NEAR(d.goal_cost[1], 53 * std::sqrt(2.0) + 60, 4.0);  // octile distance from (14, 60) to (127, 7)
  EXPECT_NEAR(d.between[0][1], d.between[1][0], 1e-9);
  EXPECT_GT(d.between[0][1], 40.0);
}

TEST(SubgoalGrid, DistancesEqualThoseOfSearchesRunToTheEnd) {
  const Seen s;
  const core::World w = ::toponav::testing::DeadEndMaze();
  const SubgoalGrid grid(s.view, s.frontiers, w.start.position(), w.goal, 1.0, w.bounds);
  ASSERT_EQ(grid.num_frontiers(), 2u);
  const auto min_over = [&](const std::vector<double>& d, size_t f) {
    double m = std::numeric_limits<double>::infinity();
    for (int c : grid.cells(f)) m = std::min(m, d[size_t(c)]);
    return m;
  };
  const Raster& r = grid.raster();
  const std::vector<double> robot = CellDistances(r, grid.ThroughKnown(), {grid.agent_cell()});
  std::vector<char> open = grid.unknown_open();
  open[size_t(grid.goal_cell())] = 1;
  const std::vector<double> goal = CellDistances(r, open, {grid.goal_cell()});
  const OrderingProblem d = grid.Distances();
  for (size_t f = 0; f < 2; ++f) {
    EXPECT_EQ(d.robot_cost[f], min_over(robot, f));
    EXPECT_EQ(d.goal_cost[f], min_over(goal, f));
  }
  EXPECT_EQ(d.between[0][1], min_over(CellDistances(r, grid.ThroughKnown(), grid.cells(0)), 1));
  EXPECT_TRUE(std::isfinite(d.between[0][1]));
}

TEST(SubgoalGrid, TrueLabelsMarkTheWayToTheGoalAndPriceTheDeadEnd) {
  const Seen s;
  const core::World w = ::toponav::testing::DeadEndMaze();
  const SubgoalGrid grid(s.view, s.frontiers, w.start.position(), w.goal, 1.0, w.bounds);
  const OrderingProblem d = grid.Distances();
  const std::vector<SubgoalProperties> p = TrueSubgoalProperties(grid, TrueFreeSpace(w, 1.0, 1.0), d);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].ps, 0.0) << "the bottom corridor ends in the dead end";
  // In and out of the dead end: from x 36 to its far end near (43, 39) and back, about 2 x 40.
  EXPECT_GT(p[0].exploration, 50.0);
  EXPECT_LT(p[0].exploration, 110.0);
  EXPECT_EQ(p[1].ps, 1.0) << "the stem leads to the goal";
  // The true way (up, along the top, down the right branch) is longer than the straight optimistic one.
  EXPECT_GT(p[1].delta_success, 30.0);
  EXPECT_LT(p[1].delta_success, 90.0);
  EXPECT_EQ(p[1].exploration, 0.0);
}

TEST(SubgoalGrid, TheSuccessCostCountsTheWalkAlongAFrontierToItsPartThatLeadsToTheGoal) {
  // Known: the maze's left strip, x 0-14 from the bottom to the top.  One frontier along x = 14: its bottom
  // end opens into the corridor towards the dead end (nearest the agent), its top end into the top corridor
  // (the way to the goal), and between them lies the true wall.
  const core::World w = ::toponav::testing::DeadEndMaze();
  mapping::MapView v;
  const Vec2 a{0, 0}, b{14, 0}, c{14, 74}, e{0, 74};
  v.known_space.push_back({{a, b, c, e}, {}});
  v.walls.push_back({0, 1, a, b, 0.9});
  v.walls.push_back({2, 3, c, e, 0.9});
  v.walls.push_back({3, 0, e, a, 0.9});
  v.frontiers.push_back({1, {b, c}, (b + c) * 0.5, 74.0});
  const std::vector<const mapping::Frontier*> frontiers = testing::FrontiersOf(v);
  const SubgoalGrid grid(v, frontiers, w.start.position(), w.goal, 1.0, w.bounds);
  const OrderingProblem d = grid.Distances();
  EXPECT_LT(d.robot_cost[0], 10.0) << "the frontier's nearest cells: beside the agent";
  const TrueFreeSpace truth(w, 1.0, 1.0);
  const std::vector<SubgoalProperties> p = TrueSubgoalProperties(grid, truth, d);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].ps, 1.0);
  const Raster& r = grid.raster();
  const double shortest = CellDistances(r, truth.On(r), {grid.agent_cell()})[size_t(grid.goal_cell())];
  EXPECT_NEAR(d.robot_cost[0] + d.goal_cost[0] + p[0].delta_success, shortest, 4.0)
      << "d_robot + d_goal + delta_success: the true way, up the strip and along the top";
}

TEST(SubgoalGrid, LabelsLandInTheRangeBearingCellsOfTheFrontiersTheAgentSees) {
  const Seen s;
  const core::World w = ::toponav::testing::DeadEndMaze();
  const SubgoalGrid grid(s.view, s.frontiers, w.start.position(), w.goal, 1.0, w.bounds);
  const std::vector<SubgoalProperties> p{{0.0, 0.0, 80.0}, {1.0, 40.0, 0.0}};
  const core::Pose2 pose{7, 7, core::kPi / 2};  // facing up the stem: the stem's top lies straight ahead
  const core::RangeBearingGrid rb;
  const SubgoalLabelGrid all = RasterizeSubgoalLabels(grid, p, pose, rb, [](const Vec2&) { return true; });
  // The stem's top (y 60-61.5, about 54 ahead): Ps 1 around bearing 0 (column 64), row of range ~54.
  const size_t ahead = rb.Index(rb.RangeRow(54.5), rb.BearingCol(0.0));
  EXPECT_EQ(all.mask[ahead], 1);
  EXPECT_FLOAT_EQ(all.ps[ahead], 1.0f);
  EXPECT_FLOAT_EQ(all.delta_success[ahead], 40.0f);
  // The dead end's frontier (x 36-37.5, y 0-14) lies to the agent's right, about 30 away: Ps 0, exploration 80.
  const double bearing = core::WrapAngle(std::atan2(7.0 - 7.0, 36.5 - 7.0) - pose.yaw);
  const size_t right = rb.Index(rb.RangeRow(29.5), rb.BearingCol(bearing));
  EXPECT_EQ(all.mask[right], 1);
  EXPECT_FLOAT_EQ(all.ps[right], 0.0f);
  EXPECT_FLOAT_EQ(all.exploration[right], 80.0f);
  int marked = 0;
  for (uint8_t m : all.mask) marked += m;
  EXPECT_GT(marked, 10);
  // Cells the agent does not see are left out.
  const SubgoalLabelGrid seen = RasterizeSubgoalLabels(grid, p, pose, rb, [](const Vec2& q) { return q.y > 30; });
  EXPECT_EQ(seen.mask[ahead], 1);
  EXPECT_EQ(seen.mask[right], 0);
}

}  // namespace
}  // namespace toponav::planning

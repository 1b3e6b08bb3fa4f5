#include "planning/cell_estimator.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "planning/subgoal_grid.h"
#include "tests/planning/dead_end_view.h"
#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

// The dead-end maze seen from its start, and its frontier grid (1-unit cells) with the grid's distances.
struct Scene {
  mapping::MapView view = testing::DeadEndSeenFromStart();
  std::vector<const mapping::Frontier*> frontiers = testing::FrontiersOf(view);
  core::World world = ::toponav::testing::DeadEndMaze();
  SubgoalGrid grid{view, frontiers, world.start.position(), world.goal, 1.0, world.bounds};
  OrderingProblem d = grid.Distances();
};

// An observation at 'pose' whose grid says Ps 'ahead' within 0.6 rad of straight ahead and 'elsewhere' in
// the other cells, success cost 10 and exploration cost 'explore' everywhere.
core::Observation Observed(const core::Pose2& pose, float ahead, float elsewhere, float explore) {
  core::Observation z;
  z.pose = pose;
  z.subgoal.rows = 32;
  z.subgoal.cols = 128;
  z.subgoal.max_range = 100;
  for (int r = 0; r < 32; ++r)
    for (int b = 0; b < 128; ++b)
      z.subgoal.values.push_back({std::abs(core::ColumnToBearing(b, 128)) < 0.6 ? ahead : elsewhere, 10.0f, explore});
  return z;
}

TEST(CellAveragingEstimator, AveragesEachFrontiersCellsOverTheObservationsThatSeeIt) {
  const Scene s;
  const SubgoalGrid& grid = s.grid;
  const OrderingProblem& d = s.d;
  CellAveragingEstimator e;
  EXPECT_EQ(e.Estimate(grid, d)[1].ps, 1.0) << "nothing seen yet: the optimistic default";
  const core::Pose2 up{7, 7, core::kPi / 2};  // the stem's top ahead, the dead end to the right
  e.Observe(Observed(up, 0.9f, 0.1f, 50.0f));
  auto p = e.Estimate(grid, d);
  EXPECT_NEAR(p[1].ps, 0.9, 1e-6);
  EXPECT_NEAR(p[0].ps, 0.1, 1e-6);
  EXPECT_NEAR(p[0].exploration, 50.0, 1e-6);
  EXPECT_NEAR(p[0].delta_success, 10.0, 1e-6);
  e.Observe(Observed(up, 0.5f, 0.3f, 30.0f));
  p = e.Estimate(grid, d);
  EXPECT_NEAR(p[1].ps, 0.7, 1e-6) << "the two observations averaged";
  EXPECT_NEAR(p[0].exploration, 40.0, 1e-6);
  // From inside the bottom corridor the stem's top is behind the wall x = 14: that observation only counts
  // for the dead end.
  e.Observe(Observed({25, 7, 0.0}, 0.0f, 0.0f, 30.0f));
  p = e.Estimate(grid, d);
  EXPECT_NEAR(p[1].ps, 0.7, 1e-6);
  EXPECT_LT(p[0].ps, 0.2);
  EXPECT_EQ(e.observations(), 3u);
}

TEST(CellAveragingEstimator, ACalibratedEstimatorMapsThePsOfSeenFrontiersAndLeavesUnseenOnesOptimistic) {
  const Scene s;
  const SubgoalGrid& grid = s.grid;
  const OrderingProblem& d = s.d;
  SubgoalCalibration c;
  c.ps.knots = {{0.0, 0.0}, {0.5, 0.2}, {1.0, 1.0}};
  CellAveragingEstimator e(10, c);
  auto p = e.Estimate(grid, d);
  EXPECT_EQ(p[1].ps, 1.0) << "nothing seen yet: the optimistic default, not mapped";
  EXPECT_EQ(p[1].exploration, 0.0);
  EXPECT_EQ(e.seen(), std::vector<char>(p.size(), 0));
  e.Observe(Observed({7, 7, core::kPi / 2}, 0.75f, 0.25f, 50.0f));
  p = e.Estimate(grid, d);
  EXPECT_NEAR(p[1].ps, 0.6, 1e-6) << "0.75 halfway between the knots at 0.5 (0.2) and 1 (1)";
  EXPECT_NEAR(p[0].ps, 0.1, 1e-6);
  EXPECT_NEAR(p[0].exploration, 50.0, 1e-6) << "the costs as the network gives them";
  EXPECT_NEAR(p[0].delta_success, 10.0, 1e-6);
  EXPECT_EQ(e.seen(), std::vector<char>(p.size(), 1));
}

TEST(CellAveragingEstimator, KeepsObservationsWithSubgoalCellsAndRefusesCellsThatDoNotFillTheirGrid) {
  CellAveragingEstimator e;
  e.Observe(core::Observation{});  // no cells (the noisy sensor): ignored
  EXPECT_EQ(e.observations(), 0u);
  core::Observation z = Observed({7, 7, 0.0}, 0.5f, 0.5f, 1.0f);
  for (int i = 0; i < 3; ++i) e.Observe(z);
  EXPECT_EQ(e.observations(), 3u);
  z.subgoal.values.pop_back();
  EXPECT_THROW(e.Observe(z), core::DataError);
  z = Observed({7, 7, 0.0}, 0.5f, 0.5f, 1.0f);
  z.subgoal.rows = 0;
  EXPECT_THROW(e.Observe(z), core::DataError);
}

TEST(CellAveragingEstimator, AnEstimateSettlesAsObservationsAccumulate) {
  const Scene s;
  const SubgoalGrid& grid = s.grid;
  const OrderingProblem& d = s.d;
  const core::Pose2 up{7, 7, core::kPi / 2};
  CellAveragingEstimator e(4);
  for (int i = 0; i < 9; ++i) {
    e.Observe(Observed(up, 0.9f, 0.1f, 50.0f));
    e.Estimate(grid, d);
  }
  e.Observe(Observed(up, 0.1f, 0.1f, 50.0f));
  EXPECT_NEAR(e.Estimate(grid, d)[1].ps, 0.82, 1e-6) << "one odd view among ten moves it a tenth of the way";
  // Observations between two estimates all count (up to 'pending', the latest ones).
  for (int i = 0; i < 6; ++i) e.Observe(Observed(up, 0.1f, 0.1f, 50.0f));
  EXPECT_NEAR(e.Estimate(grid, d)[1].ps, (8.1 + 0.1 + 4 * 0.1) / 14, 1e-6);
  // The same place under another frontier grid (the map's frontier grew a little): the sums stay.
  mapping::MapView grown = s.view;
  grown.frontiers[1].id = 9;
  const SubgoalGrid regrid(grown, testing::FrontiersOf(grown), s.world.start.position(), s.world.goal, 1.0,
                           s.world.bounds);
  EXPECT_NEAR(e.Estimate(regrid, regrid.Distances())[1].ps, (8.1 + 0.1 + 4 * 0.1) / 14, 1e-6);
}

}  // namespace
}  // namespace toponav::planning

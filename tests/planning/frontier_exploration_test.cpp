#include "planning/frontier_exploration.h"

#include <gtest/gtest.h>

#include "tests/planning/dead_end_view.h"
#include "tests/planning/open_square_view.h"
#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

TEST(FrontierExploration, TheOracleFindsMoreBehindTheWayOnThanBehindTheDeadEnd) {
  const mapping::MapView view = testing::DeadEndSeenFromStart();
  const core::World w = ::toponav::testing::DeadEndMaze();
  const auto oracle = CreateOracleEstimator(w, 1.0, 1.0);
  std::vector<FrontierTarget> targets{testing::Target(1, {30, 7}), testing::Target(2, {7, 55})};
  EstimateExploration(view, w.start.position(), 1.0, w.bounds, *oracle, &targets);
  // Frontier 1 opens on the dead end (in and out, about 2 x 40); frontier 2 on the rest of the maze, the goal's
  // side included: with the goal where the agent stands no frontier leads to it, so both are priced.
  EXPECT_GT(targets[0].exploration, 50.0);
  EXPECT_LT(targets[0].exploration, 110.0);
  EXPECT_GT(targets[1].exploration, 1.5 * targets[0].exploration);
}

TEST(FrontierExploration, ALookoutWithoutAFrontierLeavesEveryEstimateAtZero) {
  const mapping::MapView view = testing::DeadEndSeenFromStart();
  const core::World w = ::toponav::testing::DeadEndMaze();
  const auto oracle = CreateOracleEstimator(w, 1.0, 1.0);
  std::vector<FrontierTarget> targets{testing::Target(1, {30, 7}), testing::Target(99, {7, 30})};
  targets[0].exploration = 5.0;
  EstimateExploration(view, w.start.position(), 1.0, w.bounds, *oracle, &targets);
  EXPECT_EQ(targets[0].exploration, 0.0);
  EXPECT_EQ(targets[1].exploration, 0.0);
}

}  // namespace
}  // namespace toponav::planning

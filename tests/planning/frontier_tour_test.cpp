#include "planning/frontier_tour.h"

#include <gtest/gtest.h>

#include "planning/planner.h"
#include "tests/planning/open_square_view.h"

namespace toponav::planning {
namespace {

using core::Vec2;
using testing::OpenSquare;
using testing::Target;

// Frontiers in a row: one 6 to the west, four 5, 10, 15 and 20 to the east.  The nearest (east, 5) leaves the
// western one for last: 20 + 26 = 46; the west first costs 6 + 26 = 32.
std::vector<FrontierTarget> RowOfFrontiers() {
  return {Target(1, {44, 50}), Target(2, {55, 50}), Target(3, {60, 50}), Target(4, {65, 50}), Target(5, {70, 50})};
}

TEST(FrontierTour, TheAgentGoesFirstWhereTheShortestTourThroughAllFrontiersStarts) {
  const mapping::MapView view = OpenSquare();
  const VisibilityGraph g(view, {}, false);
  const Vec2 agent{50, 50};
  EXPECT_EQ(ChooseNearestFrontier(g, RowOfFrontiers(), agent).frontier_id, 2);
  const FrontierChoice tour = ChooseTourFrontier(g, RowOfFrontiers(), agent);
  ASSERT_EQ(tour.status, PlanStatus::kFound);
  EXPECT_EQ(tour.frontier_id, 1);
  EXPECT_NEAR(tour.path.cost, 6.0, 1e-9);
  // From 62 the eastern end first (3 + 5, then 26 back west) beats the western half first (18 + 26).
  EXPECT_EQ(ChooseTourFrontier(g, RowOfFrontiers(), {62, 50}).frontier_id, 4);
}

TEST(FrontierTour, NothingToExploreWithoutTargetsAndNoPathWhenNoneIsReachable) {
  mapping::MapView view = OpenSquare();
  const VisibilityGraph open(view, {}, false);
  EXPECT_EQ(ChooseTourFrontier(open, {}, {50, 50}).status, PlanStatus::kNothingToExplore);
  // A box of walls round the agent.
  AddWalls(&view, {{40, 40}, {60, 40}, {60, 60}, {40, 60}}, true);
  const VisibilityGraph boxed(view, {}, false);
  EXPECT_EQ(ChooseTourFrontier(boxed, {Target(1, {80, 80})}, {50, 50}).status, PlanStatus::kNoPath);
}

TEST(FrontierTour, ManyFrontiersTourTheNearestOnes) {
  const mapping::MapView view = OpenSquare();
  const VisibilityGraph g(view, {}, false);
  std::vector<FrontierTarget> targets;
  for (int k = 0; k < 3 * kMaxTourFrontiers; ++k) targets.push_back(Target(k, {10.0 + 2.0 * k, 20.0}));
  const FrontierChoice c = ChooseTourFrontier(g, targets, {9, 20});
  ASSERT_EQ(c.status, PlanStatus::kFound);
  EXPECT_EQ(c.frontier_id, 0);  // the row's near end: the tour runs along it
}

TEST(FrontierTour, TheSearchPlannerForOneAgentTours) {
  EXPECT_EQ(CreateSearchPlanner(1)->name(), "nearest_frontier");
  EXPECT_EQ(CreateSearchPlanner(1, true)->name(), "frontier_tour");
  EXPECT_EQ(CreateSearchPlanner(3, true)->name(), "team_frontiers");
}

}  // namespace
}  // namespace toponav::planning

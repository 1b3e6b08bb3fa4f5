#include "planning/goal_navigator.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/planning/dead_end_view.h"
#include "tests/planning/one_agent_step.h"
#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

// The goal navigator in the dead-end maze (testing::DeadEndMaze), planning on a hand-made map: no simulator,
// no sensor, no motion linked.
struct Scene {
  core::World world = ::toponav::testing::DeadEndMaze();
  mapping::MapView view = testing::DeadEndSeenFromStart();
  std::vector<std::vector<Vec2>> trails{{}};
  std::vector<core::Observation> observations{1};

  GoalNavigatorSetup Setup(GoalPlanner planner) const {
    GoalNavigatorSetup s;
    s.planner = planner;
    s.goal = world.goal;
    s.region = world.bounds;
    s.planning.frontier_row_gap = 10.0;  // below the 14-wide openings
    if (NeedsTrueWorld(planner)) s.truth = &world;
    return s;
  }
  // One step of 'navigator' with the agent at 'at' (its trail so far: 'trails'); the ways it planned.
  bool Step(GoalNavigator& navigator, const Vec2& at, std::vector<std::vector<Vec2>>* ways) {
    NavigatorInput in;
    in.step_length = 1.8;
    in.view = &view;
    in.poses = {{at.x, at.y, 0.0}};
    observations[0].pose = in.poses[0];
    in.observations = &observations;
    in.trails = &trails;
    ways->assign(1, {});
    return navigator.Plan(in, ways);
  }
};

TEST(GoalNavigator, PlansOnAHandMadeMapViewWithNoSimulatorLinked) {
  Scene s;
  const Vec2 start = s.world.start.position();
  GoalNavigator optimistic(s.Setup(GoalPlanner::kOptimistic));
  std::vector<Vec2> decided;
  optimistic.on_decision = [&](const NavigationDecision& d) { decided = d.way; };
  std::vector<std::vector<Vec2>> ways;
  ASSERT_TRUE(s.Step(optimistic, start, &ways));
  ASSERT_FALSE(ways[0].empty());
  ASSERT_GE(decided.size(), 2u);
  EXPECT_EQ(decided.front(), start) << "the decision's way starts where the agent stands";
  EXPECT_EQ(decided[1], ways[0].front()) << "and the agent follows it";
  EXPECT_LT(ways[0].front().y, 20.0) << "optimistic: along the bottom corridor, into the dead end";
  EXPECT_TRUE(optimistic.estimates().empty());

  GoalNavigator oracle(s.Setup(GoalPlanner::kOracle));
  ASSERT_TRUE(s.Step(oracle, start, &ways));
  ASSERT_FALSE(ways[0].empty());
  EXPECT_GT(ways[0].front().y, 20.0) << "the oracle heads up the stem";
  EXPECT_EQ(oracle.estimates().size(), 2u) << "both frontiers estimated";

  GoalNavigator lsp(s.Setup(GoalPlanner::kLsp));
  ASSERT_TRUE(s.Step(lsp, start, &ways));
  ASSERT_FALSE(ways[0].empty());
  EXPECT_LT(ways[0].front().y, 20.0) << "no subgoal estimates seen: every frontier optimistic";
}

TEST(GoalNavigator, TheOracleAndKnownRefuseToRunWithoutTheTrueWorldAndTheOthersRefuseIt) {
  const Scene s;
  for (const GoalPlanner p : {GoalPlanner::kOracle, GoalPlanner::kKnown}) {
    GoalNavigatorSetup setup = s.Setup(p);
    setup.truth = nullptr;
    try {
      GoalNavigator navigator(setup);
      ADD_FAILURE() << ToString(p) << " ran without its privileged input";
    } catch (const core::ConfigError& e) {
      EXPECT_EQ(e.key(), "planner");
      EXPECT_EQ(e.value(), ToString(p));
    }
  }
  for (const GoalPlanner p : {GoalPlanner::kOptimistic, GoalPlanner::kLsp}) {
    GoalNavigatorSetup setup = s.Setup(p);
    setup.truth = &s.world;
    EXPECT_THROW(GoalNavigator{setup}, core::ConfigError) << ToString(p) << " plans from the sensors only";
  }
}

TEST(GoalNavigator, EndsAtTheGoalAndWhenHeldInPlaceForTheStuckWindow) {
  Scene s;
  GoalNavigator at_goal(s.Setup(GoalPlanner::kOptimistic));
  std::vector<std::vector<Vec2>> ways;
  EXPECT_FALSE(s.Step(at_goal, s.world.goal + Vec2{3, 0}, &ways));
  EXPECT_EQ(at_goal.end_reason(), "goal");

  GoalNavigatorSetup setup = s.Setup(GoalPlanner::kOptimistic);
  setup.navigation.stuck_window = 5;
  GoalNavigator held(setup);
  const Vec2 start = s.world.start.position();
  s.trails[0].assign(5, start);
  EXPECT_TRUE(s.Step(held, start + Vec2{20, 0}, &ways)) << "moved away: not held";
  EXPECT_EQ(held.end_reason(), "step_cap") << "not ended";
  EXPECT_FALSE(s.Step(held, start, &ways));
  EXPECT_EQ(held.end_reason(), "stuck");
}

TEST(GoalNavigator, AHeldAgentPlansWithTheRangeRingsScansAndWithoutARingTheOptionIsAnError) {
  Scene s;
  GoalNavigatorSetup setup = s.Setup(GoalPlanner::kOptimistic);
  setup.navigation.scan_when_held = 3;
  const Vec2 start = s.world.start.position();
  s.trails[0] = {start, start, start};
  std::vector<std::vector<Vec2>> ways;
  GoalNavigator blind(setup);
  try {
    s.Step(blind, start, &ways);
    ADD_FAILURE() << "held without a range ring's scans";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "navigation.scan_when_held");
  }
  // A ring whose rays all hit 4 units away: the agent stands in a closed round room.
  core::RangeScan scan;
  scan.max_range = 12;
  scan.ranges.assign(360, 4.0);
  s.observations[0].scan = scan;
  GoalNavigator ringed(setup);
  ASSERT_TRUE(s.Step(ringed, start, &ways));
  EXPECT_EQ(ringed.counts().scan_steps, 1);
  ASSERT_FALSE(ringed.scan_walls().empty());
  for (const core::Segment2& w : ringed.scan_walls()) {
    EXPECT_NEAR(core::Distance(w.a, start), 4.0, 0.05) << "the walls the ring's hits show, round the agent";
    EXPECT_NEAR(core::Distance(w.b, start), 4.0, 0.05);
  }
}

// A corridor 100 long and 14 wide, all of it known, its side walls in the map (p 0.95) and a false wall across
// it at x = 50 (p 0.7): the only way to the goal crosses the false wall.
mapping::MapView CorridorWithAFalseWall() {
  mapping::MapView v;
  const std::vector<Vec2> corners{{0, 0}, {100, 0}, {100, 14}, {0, 14}, {50, 0}, {50, 14}};
  for (size_t i = 0; i < corners.size(); ++i) v.vertices.push_back({int(i), corners[i], {}, 9});
  for (auto [i, j] : {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 0}})
    v.walls.push_back({i, j, corners[size_t(i)], corners[size_t(j)], 0.95});
  v.walls.push_back({4, 5, corners[4], corners[5], 0.7});
  v.known_space.push_back({::toponav::testing::Rect(0, 0, 100, 14), {}});
  return v;
}

// Walks the agent along the navigator's ways on a map that stays as it is (each step 'step' along the way)
// until the navigator ends the task or 'max_steps' pass; the steps taken.
int WalkOnFixedMap(GoalNavigator& navigator, const mapping::MapView& view, Vec2 at, double step, int max_steps) {
  std::vector<std::vector<Vec2>> trails{{at}};
  const std::vector<core::Observation> observations(1);
  for (int k = 0; k < max_steps; ++k) {
    NavigatorInput in;
    in.step = k;
    in.step_length = step;
    in.view = &view;
    in.poses = {{at.x, at.y, 0.0}};
    in.observations = &observations;
    in.trails = &trails;
    std::vector<std::vector<Vec2>> ways(1);
    if (!navigator.Plan(in, &ways)) return k;
    const Vec2 before = at;
    if (!ways[0].empty()) {
      const Vec2 d = ways[0].front() - at;
      at = at + d * std::min(1.0, step / std::max(core::Norm(d), 1e-9));
    }
    core::Rng rng{static_cast<uint64_t>(k)};
    const StepResponse r = navigator.AfterStep(in, 0, {{at.x, at.y, 0.0}, core::Distance(before, at), false}, rng);
    if (r.nudge) at = at + *r.nudge;
    trails[0].push_back(at);
  }
  return max_steps;
}

TEST(GoalNavigator, WithACrossingPriceAGoalAFalseWallCutsOffIsReachedThroughTheLeastCertainWallWithNoRecovery) {
  const mapping::MapView view = CorridorWithAFalseWall();
  GoalNavigatorSetup s;
  s.goal = {95, 7};
  s.region = {{0, 0}, {100, 14}};
  s.planning.wall_crossing_cost = 30.0;  // the false wall: 70; each side wall: 570
  GoalNavigator navigator(s);
  const int steps = WalkOnFixedMap(navigator, view, {5, 7}, 1.8, 200);
  EXPECT_EQ(navigator.end_reason(), "goal") << "after " << steps << " steps";
  EXPECT_LE(steps, 52) << "straight down the corridor: 85 units at 1.8 a step";
  EXPECT_EQ(navigator.counts().recovery_steps, 0);
  EXPECT_EQ(navigator.counts().nudges, 0);

  s.planning.wall_crossing_cost = 0.0;  // walls never crossed: the map seals the goal off
  GoalNavigator sealed(s);
  WalkOnFixedMap(sealed, view, {5, 7}, 1.8, 200);
  EXPECT_GT(sealed.counts().recovery_steps, 0) << "no way: the recovery ran";
}

// Two lanes to the goal either side of a certain divider, each crossed by a false wall: the way takes the less
// certain one, and keeps it when the map makes that wall a little more certain than the other next step.
TEST(GoalNavigator, TheWayKeepsToTheWallItCrossedLastUnlessAnotherBecomesMuchCheaper) {
  mapping::MapView view;
  const std::vector<Vec2> corners{{50, 0}, {50, 20}, {50, 40}};
  for (size_t i = 0; i < corners.size(); ++i) view.vertices.push_back({int(i), corners[i], {}, 9});
  view.walls.push_back({0, 1, corners[0], corners[1], 0.70});  // lane A (y < 20)
  view.walls.push_back({1, 2, corners[1], corners[2], 0.72});  // lane B (y > 20)
  view.known_space.push_back({::toponav::testing::Rect(0, 0, 100, 40), {}});
  AddFreeStandingWall(&view, {{20, 20}, {80, 20}});  // the divider
  GoalNavigatorSetup s;
  s.goal = {90, 20};
  s.region = {{0, 0}, {100, 40}};
  s.planning.wall_crossing_cost = 10.0;
  const testing::OneAgentStep at_start(view, {10, 20});
  const NavigatorInput& in = at_start.input;
  const auto lane_of_crossing = [&](GoalNavigator& navigator) {
    std::vector<Vec2> way;
    navigator.on_decision = [&](const NavigationDecision& d) { way = d.way; };
    std::vector<std::vector<Vec2>> ways(1);
    EXPECT_TRUE(navigator.Plan(in, &ways));
    for (size_t i = 1; i < way.size(); ++i)
      if ((way[i - 1].x - 50) * (way[i].x - 50) <= 0) return 0.5 * (way[i - 1].y + way[i].y) < 20 ? 'A' : 'B';
    return '?';
  };
  GoalNavigator navigator(s);
  EXPECT_EQ(lane_of_crossing(navigator), 'A');
  view.walls[0].probability = 0.73;  // now a little more certain than B's
  EXPECT_EQ(lane_of_crossing(navigator), 'A') << "committed: the wall crossed last costs half its odds";
  GoalNavigator fresh(s);
  EXPECT_EQ(lane_of_crossing(fresh), 'B') << "without a way before, the cheaper crossing";
  view.walls[0].probability = 0.9;  // odds 9, halved 4.5: B's 2.6 wins
  EXPECT_EQ(lane_of_crossing(navigator), 'B');
}

TEST(LongestHold, CountsTheMostConsecutivePositionsWithinTheSpanOfEachOther) {
  EXPECT_EQ(LongestHold({}, 3.0), 0);
  EXPECT_EQ(LongestHold({{0, 0}}, 3.0), 1);
  std::vector<core::Vec2> trail;
  for (int i = 0; i < 5; ++i) trail.push_back({2.0 * i, 0});  // walking: two steps at most within 3
  for (int i = 0; i < 7; ++i) trail.push_back({9.0 + (i % 2), 0.5 * (i % 3)});  // then held near (9.5, 0.5)
  for (int i = 1; i < 4; ++i) trail.push_back({10.0 + 4.0 * i, 0});  // and on again
  EXPECT_EQ(LongestHold(trail, 3.0), 8) << "(8, 0) before the hold, and the hold";
  EXPECT_EQ(LongestHold(trail, 1.0), 2);
  // (-1, 0) lies too far from (2, 0), the window's second entry, not from its first.
  EXPECT_EQ(LongestHold({{0, 0}, {2, 0}, {1, 0}, {-1, 0}, {0, 0}}, 2.0), 3);
}

}  // namespace
}  // namespace toponav::planning

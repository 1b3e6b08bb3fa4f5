#include "experiments/navigation_trial.h"

#include <gtest/gtest.h>

#include "core/geometry.h"
#include "sim/worlds.h"

namespace toponav::experiments {
namespace {

core::World SmallMaze(uint64_t seed) {
  sim::GuidedMazeOptions o;
  o.cells_x = 3;
  o.cells_y = 3;
  return sim::GenerateGuidedMaze(o, seed);
}

TEST(NavigationTrial, OptimisticPlannerReachesTheGoalOfASmallMaze) {
  const Config cfg;
  for (uint64_t seed : {7, 8}) {
    const core::World w = SmallMaze(seed);
    const NavigationResult r = RunNavigationTrial(w, cfg, {}, seed);
    EXPECT_TRUE(r.reached) << "seed " << seed << ": " << r.end_reason << " after " << r.steps << " steps";
    EXPECT_EQ(r.end_reason, "goal");
    EXPECT_EQ(r.planner, "optimistic");
    ASSERT_FALSE(r.path.empty());
    EXPECT_LE(core::Distance(r.path.back(), w.goal), cfg.navigation.goal_radius + 1e-9);
    EXPECT_GE(r.distance, core::Distance(w.start.position(), w.goal) - cfg.navigation.goal_radius);
  }
}

TEST(NavigationTrial, StepCapEndsATrialShortOfTheGoal) {
  const core::World w = SmallMaze(7);
  NavigationTrialOptions o;
  o.max_steps = 3;
  const Config cfg;
  const NavigationResult r = RunNavigationTrial(w, cfg, o, 7);
  EXPECT_FALSE(r.reached);
  EXPECT_EQ(r.end_reason, "step_cap");
  EXPECT_EQ(r.steps, 3);
  EXPECT_GT(r.distance, 0.0);
}

TEST(NavigationTrial, AnAgentThatCannotGetAwayIsStuck) {
  const core::World w = SmallMaze(7);
  Config cfg;
  cfg.navigation.stuck_window = 4;
  cfg.navigation.stuck_span = 1000.0;  // every window counts as huddled
  const NavigationResult r = RunNavigationTrial(w, cfg, {}, 7);
  EXPECT_EQ(r.end_reason, "stuck");
  EXPECT_EQ(r.steps, 4);
}

}  // namespace
}  // namespace toponav::experiments

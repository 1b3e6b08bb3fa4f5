#include "experiments/agent_loop.h"

#include <gtest/gtest.h>

#include <limits>

#include "tests/testing/worlds.h"

namespace toponav::experiments {
namespace {

// Walks every agent east for 'steps' steps, then ends the run; records what it saw.
class WalkEast : public planning::Navigator {
 public:
  explicit WalkEast(int steps) : steps_(steps) {}
  bool Plan(const planning::NavigatorInput& state, std::vector<std::vector<core::Vec2>>* paths) override {
    observations.push_back(state.view->num_observations);
    max_steps = state.max_steps;
    this_step.push_back(state.observations ? int(state.observations->size()) : -1);
    if (state.step >= steps_) return false;
    for (size_t a = 0; a < paths->size(); ++a) (*paths)[a] = {state.poses[a].position() + core::Vec2{10, 0}};
    return true;
  }
  planning::StepResponse AfterStep(const planning::NavigatorInput& state, int agent,
                                   const planning::MotionOutcome& step, core::Rng& rng) override {
    ++after_steps;
    return {};
  }
  std::vector<int> observations, this_step;
  int after_steps = 0;
  int max_steps = -1;  // what the loop told the navigator its cap is

 private:
  int steps_;
};

TEST(AgentLoop, EveryAgentObservesEachStepMovesAlongItsPathAndTheNavigatorEndsTheRun) {
  const core::World w = testing::RoomWorld(60, 30);
  Config config;
  WalkEast navigator(4);
  LoopOptions o;
  o.num_agents = 2;
  int calls = 0;
  o.on_step = [&](const mapping::MapView&, const std::vector<std::vector<core::Vec2>>&) { ++calls; };
  const LoopResult r = RunAgentLoop(w, config, o, navigator, 5);
  EXPECT_EQ(r.steps, 5) << "four steps moved, the fifth ended the run";
  EXPECT_TRUE(r.ended_by_navigator);
  EXPECT_EQ(navigator.observations, (std::vector<int>{2, 4, 6, 8, 10})) << "both agents observe every step";
  EXPECT_EQ(navigator.this_step, (std::vector<int>{2, 2, 2, 2, 2})) << "the navigator sees this step's observations";
  EXPECT_EQ(navigator.after_steps, 8);
  EXPECT_EQ(calls, 5) << "after each of the 4 moves, and once with the final map";
  ASSERT_EQ(r.paths.size(), 2u);
  EXPECT_EQ(r.paths[0].size(), 5u);
  // Box2D works in floats.
  EXPECT_NEAR(r.paths[0].back().x - r.paths[0].front().x, 4 * config.motion.step_length, 1e-4);
  EXPECT_NEAR(r.distance[1], 4 * config.motion.step_length, 1e-4);
  EXPECT_EQ(r.mcmc_calls, 1) << "MCMC on step 0 (the next would be step 5)";
  EXPECT_EQ(r.final_view.num_observations, 10);
  ASSERT_TRUE(r.mapper);
}

TEST(AgentLoop, ATeamStandingTogetherAddsItsSharedViewToTheMapOnce) {
  // Three agents start at the same pose and walk east together, staying on one pose.  With a sensor that
  // sees the same place the same way, their views are one look: the map gets one observation a step, the
  // navigator still all three.
  const core::World w = testing::RoomWorld(60, 30);
  Config config;
  sim::NoisySensorOptions& s = config.sensor.noisy;
  s.range_sigma = s.range_sigma_per_unit = s.bearing_sigma = s.miss_probability = 0.0;
  s.false_positives_per_observation = s.label_confusion = s.label_softness = 0.0;
  WalkEast exact(2);
  LoopOptions o;
  o.num_agents = 3;
  RunAgentLoop(w, config, o, exact, 5);
  EXPECT_EQ(exact.observations, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(exact.this_step, (std::vector<int>{3, 3, 3}));
  // The default noisy sensor draws its errors afresh for every view: separate looks, all added.
  WalkEast noisy(2);
  const Config defaults;
  RunAgentLoop(w, defaults, o, noisy, 5);
  EXPECT_EQ(noisy.observations, (std::vector<int>{3, 6, 9}));
}

TEST(AgentLoop, TheStepCapEndsARunTheNavigatorDoesNot) {
  const core::World w = testing::RoomWorld(60, 30);
  WalkEast navigator(1000);
  LoopOptions o;
  o.max_steps = 7;
  o.mcmc_every = 3;
  const Config config;
  const LoopResult r = RunAgentLoop(w, config, o, navigator, 5);
  EXPECT_EQ(r.steps, 7);
  EXPECT_EQ(navigator.max_steps, 7) << "the navigator knows the cap (an inspection it cannot finish is not started)";
  EXPECT_FALSE(r.ended_by_navigator);
  EXPECT_EQ(r.mcmc_calls, 3) << "steps 0, 3 and 6";
}

TEST(AgentLoop, ThePathBudgetIsTheStepsLeftBeforeTheCapLessTheReserveTimesTheStepLength) {
  planning::NavigatorInput s;
  s.step_length = 2.0;
  s.step = 90;
  EXPECT_EQ(planning::PathBudget(s, 6), std::numeric_limits<double>::infinity()) << "no cap";
  s.max_steps = 100;  // steps 90 .. 99 are left: 10, 6 of them in hand
  EXPECT_DOUBLE_EQ(planning::PathBudget(s, 6), 8.0);
  EXPECT_DOUBLE_EQ(planning::PathBudget(s, 0), 20.0);
  EXPECT_DOUBLE_EQ(planning::PathBudget(s, 12), 0.0) << "never negative";
}

TEST(AgentLoop, TheSameSeedGivesTheSameMap) {
  const core::World w = testing::RoomWorld(60, 30);
  WalkEast a(6), b(6);
  const Config config;
  const LoopResult ra = RunAgentLoop(w, config, {}, a, 9), rb = RunAgentLoop(w, config, {}, b, 9);
  ASSERT_EQ(ra.final_view.vertices.size(), rb.final_view.vertices.size());
  for (size_t i = 0; i < ra.final_view.vertices.size(); ++i)
    EXPECT_EQ(ra.final_view.vertices[i].position.x, rb.final_view.vertices[i].position.x);
  EXPECT_EQ(ra.final_view.known_area(), rb.final_view.known_area());
}

}  // namespace
}  // namespace toponav::experiments

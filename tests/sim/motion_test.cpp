#include "sim/motion.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/rng.h"
#include "sim/worlds.h"
#include "tests/testing/worlds.h"

namespace toponav::sim {
namespace {

TEST(MotionSim, StepTravelsStepLengthAlongAFreePath) {
  const core::World w = testing::RoomWorld(50, 50);
  MotionSim sim(w, {});
  const int a = sim.AddAgent({10, 10, 0});
  const StepResult r = sim.Step(a, {{40, 10}});
  EXPECT_NEAR(r.distance, 1.8, 0.02);
  EXPECT_NEAR(r.pose.x, 11.8, 0.02);
  EXPECT_NEAR(r.pose.y, 10.0, 0.02);
  EXPECT_NEAR(r.pose.yaw, 0.0, 1e-3);
  EXPECT_FALSE(r.blocked);
  EXPECT_FALSE(r.reached_end);
}

TEST(MotionSim, StepFollowsPolylineAroundACorner) {
  const core::World w = testing::RoomWorld(50, 50);
  MotionSim sim(w, {});
  const int a = sim.AddAgent({10, 10, 0});
  const StepResult r = sim.Step(a, {{11, 10}, {11, 30}});  // 1 unit east, then 0.8 north
  EXPECT_NEAR(r.pose.x, 11.0, 0.05);
  EXPECT_NEAR(r.pose.y, 10.8, 0.05);
  const StepResult end = sim.Step(a, {{11, 11.5}});
  EXPECT_TRUE(end.reached_end);
}

TEST(MotionSim, WallBlocksAndAgentStopsOutsideIt) {
  core::World w = testing::RoomWorld(50, 50);
  w.obstacles.push_back(testing::Rect(20, 0.5, 22, 49.5));
  MotionSim sim(w, {});
  const int a = sim.AddAgent({15, 25, 0});
  StepResult r;
  for (int i = 0; i < 20; ++i) r = sim.Step(a, {{40, 25}});
  EXPECT_TRUE(r.blocked);
  EXPECT_LE(r.pose.x, 20.0 - 1.0 + 0.05);
  EXPECT_GE(r.pose.x, 20.0 - 1.0 - 0.2);
}

// A box of clutter (which the map never holds) right on the planned line, hugging a wall as the
// labyrinth's clutter does: the agent must get past it to the waypoint beyond.
int StepsPastClutter(const MotionOptions& options) {
  core::World w = testing::RoomWorld(50, 50);
  w.clutter.push_back({core::ClutterShape::kBox, {25, 3.0}, 1.5, 0.3, 2.25});
  MotionSim sim(w, options);
  const int a = sim.AddAgent({10, 3.5, 0});
  for (int step = 1; step <= 60; ++step)
    if (sim.Step(a, {{40, 3.5}}).reached_end) return step;
  return -1;
}

TEST(MotionSim, AgentSteersAroundClutterOnItsPath) {
  const int steps = StepsPastClutter({});
  EXPECT_GT(steps, 0) << "the agent never got past the box";
  EXPECT_LE(steps, 25) << "30 units at 1.8 a step plus a short detour";
}

TEST(MotionSim, WithoutAvoidanceClutterOnThePathStopsTheAgent) {
  MotionOptions options;
  options.avoid_margin = 0;
  EXPECT_EQ(StepsPastClutter(options), -1);
}

TEST(MotionSim, AgentsNeverEnterObstaclesOverThousandRandomSteps) {
  for (auto kind : {core::WorldKind::kLabyrinth, core::WorldKind::kOfficePark, core::WorldKind::kGuidedMaze}) {
    const core::World w = GenerateWorld(kind, {}, 11);
    const MotionOptions options;
    MotionSim sim(w, options);
    const int a = sim.AddAgent(w.start);
    core::Rng rng(99);
    core::Vec2 target = w.start.position();
    for (int step = 0; step < 1000; ++step) {
      if (step % 25 == 0)  // a new random target anywhere, often behind walls or inside obstacles
        target = {rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
      const StepResult r = sim.Step(a, {target});
      const core::Vec2 p = r.pose.position();
      ASSERT_TRUE(core::IsFree(w, p)) << core::ToString(kind) << " step " << step << " at " << p.x << "," << p.y;
      ASSERT_GE(core::SignedDistance(w, p), options.agent_radius * 0.9)
          << core::ToString(kind) << " step " << step << " at " << p.x << "," << p.y;
    }
  }
}

TEST(MotionSim, AgentsDoNotCollideWithEachOther) {
  const core::World w = testing::RoomWorld(50, 50);
  MotionSim sim(w, {});
  const int a = sim.AddAgent({10, 10, 0});
  const int b = sim.AddAgent({10, 10, 0});
  EXPECT_EQ(sim.num_agents(), 2);
  sim.Step(a, {{40, 10}});
  sim.Step(b, {{40, 10}});
  EXPECT_NEAR(sim.Pose(a).x, sim.Pose(b).x, 1e-6);
}

TEST(MotionSim, AddingAnAgentInsideAWallIsAnError) {
  core::World w = testing::RoomWorld(50, 50);
  w.obstacles.push_back(testing::Rect(20, 20, 30, 30));
  MotionSim sim(w, {});
  EXPECT_THROW(sim.AddAgent({25, 25, 0}), core::DataError);
  EXPECT_THROW(sim.AddAgent({19.5, 25, 0}), core::DataError);  // the disc would overlap the wall
}

}  // namespace
}  // namespace toponav::sim

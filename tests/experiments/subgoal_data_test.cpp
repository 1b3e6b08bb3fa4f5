#include "experiments/subgoal_data.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/worlds.h"

namespace toponav::experiments {
namespace {

TEST(SubgoalData, AnOptimisticRunThroughASmallMazeYieldsLabelledSamplesWithAWayToTheGoal) {
  sim::GuidedMazeOptions mo;
  mo.cells_x = 3;
  mo.cells_y = 4;
  const core::World maze = sim::GenerateGuidedMaze(mo, 12);
  Config cfg;
  cfg.planning.frontier_row_gap = 10.0;
  const auto samples = CollectSubgoalSamples(maze, cfg, 12, 2);
  ASSERT_FALSE(samples.empty());
  int positive = 0, negative = 0, previous = -1;
  for (const auto& s : samples) {
    EXPECT_EQ(s.step % 2, 0);
    EXPECT_GT(s.step, previous) << "in step order";
    previous = s.step;
    EXPECT_EQ(s.world_seed, maze.seed);
    EXPECT_EQ(s.labels.mask.size(), s.labels.grid.size());
    for (size_t i = 0; i < s.labels.mask.size(); ++i) {
      if (!s.labels.mask[i]) {
        EXPECT_EQ(s.labels.ps[i], 0.0f);
        continue;
      }
      positive += s.labels.ps[i] == 1.0f;
      negative += s.labels.ps[i] == 0.0f;
      EXPECT_GE(s.labels.delta_success[i], 0.0f);
      EXPECT_GE(s.labels.exploration[i], 0.0f);
    }
  }
  EXPECT_GT(positive, 0) << "some frontier leads to the goal";
  EXPECT_GT(negative + positive, positive) << "and some do not (a maze has dead ends)";
}

TEST(SubgoalData, ASearchThroughALabyrinthLabelsEveryFrontierWithWhatLiesPastIt) {
  const core::World w = sim::GenerateWorld(core::WorldKind::kLabyrinth, {}, 3000);
  Config cfg;
  cfg.search.tour = true;
  cfg.bench.max_steps = 40;
  const auto samples = CollectSubgoalSamples(w, cfg, 3000, 5);
  ASSERT_FALSE(samples.empty());
  int explored = 0;
  for (const auto& s : samples) {
    EXPECT_EQ(s.goal.x, s.pose.x) << "the goal is where the agent stands";
    EXPECT_EQ(s.goal.y, s.pose.y);
    for (size_t i = 0; i < s.labels.mask.size(); ++i) {
      if (!s.labels.mask[i]) continue;
      EXPECT_EQ(s.labels.ps[i], 0.0f) << "no frontier leads to a goal in known space";
      explored += s.labels.exploration[i] > 10.0f;
    }
  }
  EXPECT_GT(explored, 0) << "the rest of the labyrinth lies past some frontier";
}

TEST(SubgoalData, ExamplesCarryThePanoramaVertexLabelsGoalInViewAndSubgoalLabelsOfTheirPose) {
  Config cfg;
  cfg.planning.frontier_row_gap = 10.0;
  cfg.subgoal_data.train_first_seed = 1000;
  cfg.subgoal_data.train_num_seeds = 1;
  cfg.subgoal_data.every = 15;
  int calls = 0;
  const auto examples = MakeSubgoalExamples(cfg, sim::Split::kTrain, [&](int done, int total, size_t) {
    ++calls;
    EXPECT_EQ(total, 1);
    EXPECT_EQ(done, 1);
  });
  EXPECT_EQ(calls, 1);
  const core::World maze = sim::GenerateWorld(core::WorldKind::kGuidedMaze, cfg.worlds, 1000);
  const auto samples = CollectSubgoalSamples(maze, cfg, 1000, 15, {64, 256, 100.0});
  ASSERT_EQ(examples.size(), samples.size()) << "one example per sample of the maze's run";
  ASSERT_FALSE(examples.empty());
  for (size_t i = 0; i < examples.size(); ++i) {
    const SubgoalExample& e = examples[i];
    EXPECT_EQ(e.world_seed, 1000u);
    EXPECT_EQ(e.step, samples[i].step);
    EXPECT_EQ(e.image.width, 512);
    EXPECT_EQ(e.image.height, 128);
    EXPECT_EQ(e.labels.grid.rows, 32);
    EXPECT_EQ(e.subgoal.grid.cols, 256);
    EXPECT_EQ(e.subgoal.mask, samples[i].labels.mask);
    const core::Pose2& p = samples[i].pose;  // the goal in the agent's frame, turned back, is the maze's goal
    const core::Vec2 g{p.x + std::cos(p.yaw) * e.goal.x - std::sin(p.yaw) * e.goal.y,
                       p.y + std::sin(p.yaw) * e.goal.x + std::cos(p.yaw) * e.goal.y};
    EXPECT_NEAR(g.x, maze.goal.x, 1e-9);
    EXPECT_NEAR(g.y, maze.goal.y, 1e-9);
  }
  size_t vertices = 0;
  for (uint8_t c : examples[0].labels.cells) vertices += c > 0;
  EXPECT_GT(vertices, 0u) << "a maze panorama sees wall corners";
}

}  // namespace
}  // namespace toponav::experiments

#include "experiments/subgoal_data.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace toponav::experiments

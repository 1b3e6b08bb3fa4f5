#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>

#include "learning/internal/vertex_net.h"

namespace toponav::learning::internal {
namespace {

TEST(SubgoalNet, GivesTheVertexGridAndAFinerSubgoalGrid) {
  torch::manual_seed(1);
  SubgoalNet net(0.25);
  net->eval();
  torch::NoGradGuard no_grad;
  const auto image = torch::rand({2, 3, 128, 512});
  const auto goal = torch::stack({GoalImage(40, 0.5), GoalImage(10, -2.0)});
  const auto [vertex, subgoal] = net->forward(image, goal);
  EXPECT_EQ(vertex.sizes(), (std::vector<int64_t>{2, 5, 32, 128}));
  EXPECT_EQ(subgoal.sizes(), (std::vector<int64_t>{2, 3, 64, 256}));
  // The goal reaches the outputs: another goal, other subgoal outputs.
  const auto other = net->forward(image, torch::stack({GoalImage(80, 2.5), GoalImage(10, -2.0)})).second;
  EXPECT_GT((other[0] - subgoal[0]).abs().max().item<float>(), 1e-6);
  EXPECT_LT((other[1] - subgoal[1]).abs().max().item<float>(), 1e-6) << "the batch's other sample is unchanged";
}

// Bearing is circular: turning the agent by 32 image columns (a multiple of the 5 poolings' 32) turns every
// output by as many of its own columns, with the goal image turned with it (the decoder's upsampling wraps too).
TEST(SubgoalNet, TurningTheImageAndTheGoalTurnsTheOutputs) {
  torch::manual_seed(2);
  SubgoalNet net(0.25);
  net->eval();
  torch::NoGradGuard no_grad;
  const auto image = torch::rand({1, 3, 128, 512});
  const double step = 2 * M_PI * 32 / 512;  // the bearing 32 columns span
  const auto [v0, s0] = net->forward(image, GoalImage(30, 1.0).unsqueeze(0));
  // Rolling the image right by 32 columns looks like the world turned by +step: the goal's bearing too.
  const auto [v1, s1] = net->forward(image.roll(32, 3), GoalImage(30, 1.0 + step).unsqueeze(0));
  EXPECT_LT((v1 - v0.roll(8, 3)).abs().max().item<float>(), 1e-4);
  EXPECT_LT((s1 - s0.roll(16, 3)).abs().max().item<float>(), 1e-4);
}

TEST(SubgoalNet, TheGoalImageHoldsRangeTimesSinAndCosOfTheRelativeBearing) {
  const auto g = GoalImage(10.0, 0.0, 4, 8);  // columns look along -pi, -3pi/4, ..., 3pi/4
  EXPECT_EQ(g.sizes(), (std::vector<int64_t>{2, 4, 8}));
  EXPECT_NEAR(g[0][0][4].item<float>(), 0.0, 1e-5);   // column 4 looks straight ahead: sin 0
  EXPECT_NEAR(g[1][3][4].item<float>(), 10.0, 1e-5);  // cos 0, on every row
  EXPECT_NEAR(g[1][0][0].item<float>(), -10.0, 1e-5); // column 0 looks backwards
  EXPECT_NEAR(g[0][0][6].item<float>(), -10.0, 1e-5); // column 6 looks left (+pi/2): sin(0 - pi/2)
}

}  // namespace
}  // namespace toponav::learning::internal

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <limits>

#include "learning/internal/vertex_net.h"

namespace toponav::learning::internal {
namespace {

// Equal where both are numbers, and NaN in the same cells.
bool SameValues(const torch::Tensor& a, const torch::Tensor& b) {
  if (a.sizes() != b.sizes() || !torch::equal(a.isnan(), b.isnan())) return false;
  const torch::Tensor numbers = ~a.isnan();
  return torch::equal(a.masked_select(numbers), b.masked_select(numbers));
}

TEST(MaxPool2x2, EqualsTorchsMaxPoolOnEvenOddAndStridedInputsWithAndWithoutGradients) {
  torch::manual_seed(3);
  MaxPool2x2 pool;
  std::vector<torch::Tensor> inputs;
  for (const auto& shape : std::vector<std::vector<int64_t>>{{2, 3, 8, 16}, {1, 4, 7, 9}, {1, 1, 2, 2}})
    inputs.push_back(torch::randn(shape));
  inputs.push_back(torch::randn({2, 3, 10, 6}).transpose(2, 3));  // not contiguous
  torch::Tensor special = torch::randn({1, 2, 4, 4});
  special[0][0][0][0] = std::numeric_limits<float>::quiet_NaN();
  special[0][1].fill_(-std::numeric_limits<float>::infinity());
  inputs.push_back(special);
  for (const auto& x : inputs) {
    const torch::Tensor expected = torch::max_pool2d(x, 2);
    EXPECT_TRUE(SameValues(pool->forward(x), expected)) << x.sizes();  // the fast path (no gradient)
    EXPECT_TRUE(SameValues(pool->forward(x.clone().requires_grad_(true)).detach(), expected)) << x.sizes();
  }
}

TEST(MaxPool2x2, InTrainingTheGradientGoesToOneMaximumEvenOnTies) {
  MaxPool2x2 pool;
  const torch::Tensor x = torch::tensor({5.0f, 5.0f, 2.0f, 0.0f}).reshape({1, 1, 2, 2}).requires_grad_(true);
  pool->forward(x).sum().backward();
  EXPECT_FLOAT_EQ(x.grad().sum().item<float>(), 1.0f);
  EXPECT_EQ(x.grad().eq(1.0f).sum().item<int64_t>(), 1) << "max_pool2d's gradient, not a split between the ties";
}

}  // namespace
}  // namespace toponav::learning::internal

#include <gtest/gtest.h>
#include <torch/torch.h>

#include "learning/internal/vertex_net.h"

namespace toponav::learning::internal {
namespace {

TEST(MaxPool2x2, EqualsTorchsMaxPoolOnEvenAndOddSizesWithAndWithoutGradients) {
  torch::manual_seed(3);
  MaxPool2x2 pool;
  for (const auto& shape : std::vector<std::vector<int64_t>>{{2, 3, 8, 16}, {1, 4, 7, 9}, {1, 1, 2, 2}}) {
    const torch::Tensor x = torch::randn(shape);
    const torch::Tensor expected = torch::max_pool2d(x, 2);
    const torch::Tensor got = pool->forward(x);  // the fast path (x needs no gradient)
    ASSERT_EQ(got.sizes(), expected.sizes());
    EXPECT_TRUE(torch::equal(got, expected));
    EXPECT_TRUE(torch::equal(pool->forward(x.clone().requires_grad_(true)).detach(), expected));
  }
  const torch::Tensor x = torch::tensor({1.0f, 5.0f, 2.0f, 0.0f}).reshape({1, 1, 2, 2}).requires_grad_(true);
  pool->forward(x).sum().backward();
  EXPECT_TRUE(torch::equal(x.grad(), torch::tensor({0.0f, 1.0f, 0.0f, 0.0f}).reshape({1, 1, 2, 2})))
      << "the gradient goes to the maximum only";
}

}  // namespace
}  // namespace toponav::learning::internal

#include "learning/internal/net_ops.h"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <limits>

namespace toponav::learning::internal {
namespace {

namespace F = torch::nn::functional;

// Equal where both are numbers, and NaN in the same cells.
bool SameValues(const torch::Tensor& a, const torch::Tensor& b) {
  if (a.sizes() != b.sizes() || !torch::equal(a.isnan(), b.isnan())) return false;
  const torch::Tensor numbers = ~a.isnan();
  return torch::equal(a.masked_select(numbers), b.masked_select(numbers));
}

// Inputs of even, odd and tiny sizes, one not contiguous, and one with NaN, -inf and tied windows.
std::vector<torch::Tensor> Inputs() {
  torch::manual_seed(3);
  std::vector<torch::Tensor> inputs;
  for (const auto& shape : std::vector<std::vector<int64_t>>{{2, 3, 8, 16}, {1, 4, 7, 9}, {1, 1, 2, 2}})
    inputs.push_back(torch::randn(shape));
  inputs.push_back(torch::randn({2, 3, 10, 6}).transpose(2, 3));  // not contiguous
  torch::Tensor special = torch::randn({1, 3, 4, 4});
  special[0][0][0][0] = std::numeric_limits<float>::quiet_NaN();
  special[0][1].fill_(-std::numeric_limits<float>::infinity());
  special[0][2] = torch::randint(0, 2, {4, 4}).to(torch::kFloat);  // ties in most windows
  inputs.push_back(special);
  return inputs;
}

// f(x) and the gradient of a random weighting of it.
std::pair<torch::Tensor, torch::Tensor> ValueAndGradient(const std::function<torch::Tensor(torch::Tensor)>& f,
                                                         const torch::Tensor& input, const torch::Tensor& weights) {
  const torch::Tensor x = input.detach().clone().requires_grad_(true);
  const torch::Tensor y = f(x);
  (y * weights.reshape(y.sizes())).sum().backward();
  return {y.detach(), x.grad()};
}

TEST(MaxPool2, EqualsTorchsMaxPoolWithoutGradients) {
  for (const auto& x : Inputs()) EXPECT_TRUE(SameValues(MaxPool2(x), torch::max_pool2d(x, 2))) << x.sizes();
}

TEST(MaxPool2, EqualsTorchsMaxPoolAndItsGradientInTraining) {
  for (const auto& x : Inputs()) {
    const torch::Tensor w = torch::randn({torch::max_pool2d(x, 2).numel()});
    const auto [y, g] = ValueAndGradient(MaxPool2, x, w);
    const auto [y_ref, g_ref] = ValueAndGradient([](torch::Tensor t) { return torch::max_pool2d(t, 2); }, x, w);
    EXPECT_TRUE(SameValues(y, y_ref)) << x.sizes();
    EXPECT_TRUE(SameValues(g, g_ref)) << x.sizes();
  }
}

TEST(MaxPool2, InTrainingTheGradientGoesToOneMaximumEvenOnTies) {
  const torch::Tensor x = torch::tensor({5.0f, 5.0f, 2.0f, 0.0f}).reshape({1, 1, 2, 2}).requires_grad_(true);
  MaxPool2(x).sum().backward();
  EXPECT_FLOAT_EQ(x.grad().sum().item<float>(), 1.0f);
  EXPECT_EQ(x.grad()[0][0][0][0].item<float>(), 1.0f) << "max_pool2d's gradient: the first maximum, not a split";
}

TEST(PadCircularWidth, EqualsTorchsCircularPadAndItsGradient) {
  const auto reference = [](torch::Tensor t) {
    return F::pad(t, F::PadFuncOptions({1, 1, 0, 0}).mode(torch::kCircular));
  };
  for (const auto& x : Inputs()) {
    const torch::Tensor w = torch::randn({reference(x).numel()});
    const auto [y, g] = ValueAndGradient(PadCircularWidth, x, w);
    const auto [y_ref, g_ref] = ValueAndGradient(reference, x, w);
    EXPECT_TRUE(SameValues(y, y_ref)) << x.sizes();
    EXPECT_TRUE(SameValues(g, g_ref)) << x.sizes();
    EXPECT_TRUE(SameValues(PadCircularWidth(x), y_ref)) << "without gradients";
  }
}

TEST(PadCircularWidth, WrapsTheColumns) {
  const torch::Tensor x = torch::arange(4, torch::kFloat).reshape({1, 1, 1, 4});
  EXPECT_TRUE(
      torch::equal(PadCircularWidth(x), torch::tensor({3.0f, 0.0f, 1.0f, 2.0f, 3.0f, 0.0f}).reshape({1, 1, 1, 6})));
}

}  // namespace
}  // namespace toponav::learning::internal

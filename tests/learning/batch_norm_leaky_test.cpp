#include "learning/internal/batch_norm_leaky.h"

#include <gtest/gtest.h>
#include <torch/torch.h>

namespace toponav::learning::internal {
namespace {

// torch::nn::BatchNorm2d then LeakyReLU, the modules BatchNormLeaky stands for.
struct Reference {
  explicit Reference(int64_t channels) : norm(channels), leaky(torch::nn::LeakyReLUOptions().negative_slope(0.1)) {}
  torch::Tensor forward(const torch::Tensor& x) { return leaky->forward(norm->forward(x)); }
  torch::nn::BatchNorm2d norm;
  torch::nn::LeakyReLU leaky;
};

// The same weights, biases and running statistics in both.
void CopyState(BatchNormLeaky& to, const Reference& from) {
  torch::NoGradGuard no_grad;
  to->weight.copy_(from.norm->weight);
  to->bias.copy_(from.norm->bias);
  to->running_mean.copy_(from.norm->running_mean);
  to->running_var.copy_(from.norm->running_var);
}

// Activations like a convolution's: a mean far from 0 in some channels, sizes not a multiple of the lanes.
std::vector<torch::Tensor> Inputs() {
  torch::manual_seed(5);
  return {torch::randn({2, 3, 5, 7}) * 3 + torch::tensor({0.5f, 40.0f, -2.0f}).reshape({1, 3, 1, 1}),
          torch::randn({1, 4, 16, 33}), torch::randn({8, 2, 64, 256}) * 0.01f,
          torch::randn({2, 6, 9, 4}).transpose(2, 3)};  // not contiguous
}

TEST(BatchNormLeaky, TrainsLikeBatchNormThenLeakyReluValuesGradientsAndRunningStatistics) {
  for (const torch::Tensor& input : Inputs()) {
    const int64_t channels = input.size(1);
    Reference ref(channels);
    {
      torch::NoGradGuard no_grad;
      ref.norm->weight.copy_(torch::randn({channels}));  // negative ones too
      ref.norm->bias.copy_(torch::randn({channels}));
    }
    BatchNormLeaky fused(channels, 0.1);
    CopyState(fused, ref);
    const torch::Tensor weights = torch::randn(input.sizes());
    const torch::Tensor x = input.clone().requires_grad_(true), x_ref = input.clone().requires_grad_(true);
    const torch::Tensor y = fused->forward(x), y_ref = ref.forward(x_ref);
    (y * weights).sum().backward();
    (y_ref * weights).sum().backward();
    EXPECT_TRUE(torch::allclose(y, y_ref, 1e-4, 1e-5)) << input.sizes();
    EXPECT_TRUE(torch::allclose(x.grad(), x_ref.grad(), 1e-3, 1e-4)) << input.sizes();
    EXPECT_TRUE(torch::allclose(fused->weight.grad(), ref.norm->weight.grad(), 1e-3, 1e-3)) << input.sizes();
    EXPECT_TRUE(torch::allclose(fused->bias.grad(), ref.norm->bias.grad(), 1e-3, 1e-3)) << input.sizes();
    EXPECT_TRUE(torch::allclose(fused->running_mean, ref.norm->running_mean, 1e-5, 1e-5)) << input.sizes();
    EXPECT_TRUE(torch::allclose(fused->running_var, ref.norm->running_var, 1e-4, 1e-5)) << input.sizes();
    EXPECT_EQ(fused->num_batches_tracked.item<int64_t>(), 1);
  }
}

TEST(BatchNormLeaky, EvaluatesExactlyAsBatchNormThenLeakyRelu) {
  Reference ref(3);
  {
    torch::NoGradGuard no_grad;
    ref.norm->running_mean.copy_(torch::tensor({0.3f, -2.0f, 7.0f}));
    ref.norm->running_var.copy_(torch::tensor({0.5f, 4.0f, 0.01f}));
    ref.norm->weight.copy_(torch::tensor({1.5f, -0.7f, 0.2f}));
  }
  BatchNormLeaky fused(3, 0.1);
  CopyState(fused, ref);
  ref.norm->eval();
  fused->eval();
  const torch::Tensor x = torch::randn({2, 3, 8, 16}) * 4;
  EXPECT_TRUE(torch::equal(fused->forward(x), ref.forward(x))) << "the same outputs, bit for bit";
}

TEST(BatchNormLeaky, NamesItsTensorsAsBatchNorm2d) {
  std::vector<std::string> ours, theirs;
  for (const auto& t : BatchNormLeaky(4, 0.1)->named_parameters()) ours.push_back(t.key());
  for (const auto& t : BatchNormLeaky(4, 0.1)->named_buffers()) ours.push_back(t.key());
  for (const auto& t : torch::nn::BatchNorm2d(4)->named_parameters()) theirs.push_back(t.key());
  for (const auto& t : torch::nn::BatchNorm2d(4)->named_buffers()) theirs.push_back(t.key());
  EXPECT_EQ(ours, theirs);
}

}  // namespace
}  // namespace toponav::learning::internal

#pragma once
// BatchNorm2d followed by LeakyReLU, the pair after every convolution of the vertex network, as one module.
// In training on the CPU (float32) it is one autograd function with its gradient written out: two passes over
// the activations forward (batch statistics; normalize, scale, shift and LeakyReLU) and two backward, and only
// its input kept for the backward pass.  In evaluation, and on other devices and types, it is
// torch::batch_norm then torch::leaky_relu: the outputs of BatchNorm2d then LeakyReLU, bit for bit.
#include <torch/torch.h>

namespace toponav::learning::internal {

struct BatchNormLeakyImpl : torch::nn::Module {
  // 'slope': LeakyReLU's negative slope.  BatchNorm2d's defaults: eps 1e-5, momentum 0.1.
  BatchNormLeakyImpl(int64_t channels, double slope);
  torch::Tensor forward(const torch::Tensor& x);
  // Named as BatchNorm2d's, so models saved with a BatchNorm2d here load unchanged.
  torch::Tensor weight, bias, running_mean, running_var, num_batches_tracked;
  double slope, eps = 1e-5, momentum = 0.1;
};
TORCH_MODULE(BatchNormLeaky);

// The training path alone, for any float32 CPU input [B, C, H, W] (B * H * W >= 2): batch statistics (the
// biased variance normalizes, the unbiased one updates 'running_var'), then LeakyReLU('slope').  Updates the
// running statistics in place.
torch::Tensor BatchNormLeakyTraining(const torch::Tensor& x, const torch::Tensor& weight, const torch::Tensor& bias,
                                     torch::Tensor& running_mean, torch::Tensor& running_var, double momentum,
                                     double eps, double slope);

}  // namespace toponav::learning::internal

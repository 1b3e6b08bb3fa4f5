#pragma once
// The LibTorch module of the vertex network (internal to the learning layer).
#include <torch/torch.h>

namespace toponav::learning::internal {

// 3x3 convolution padded circularly along the width (bearing) and with zeros along the height.
struct CircularConvImpl : torch::nn::Module {
  CircularConvImpl(int64_t in, int64_t out);
  torch::Tensor forward(const torch::Tensor& x);
  torch::nn::Conv2d conv{nullptr};
};
TORCH_MODULE(CircularConv);

struct VertexNetImpl : torch::nn::Module {
  explicit VertexNetImpl(double width);
  // [B, 3, 128, 512] in [0, 1] -> [B, 5, 32, 128] logits (channel 0 vertex, 1-4 labels).
  torch::Tensor forward(torch::Tensor x);
  torch::nn::Sequential encoder{nullptr}, decoder{nullptr};
  torch::nn::Conv2d head{nullptr};
};
TORCH_MODULE(VertexNet);

}  // namespace toponav::learning::internal

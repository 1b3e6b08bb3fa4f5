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

// The encoder's 2x2 max-pool with stride 2: MaxPool2 (net_ops.h), equal to torch::nn::MaxPool2d(2) value for
// value and in its gradient.  It has no parameters, so models saved with MaxPool2d load unchanged.
struct MaxPool2x2Impl : torch::nn::Module {
  torch::Tensor forward(const torch::Tensor& x);
};
TORCH_MODULE(MaxPool2x2);

struct VertexNetImpl : torch::nn::Module {
  explicit VertexNetImpl(double width);
  // [B, 3, 128, 512] in [0, 1] -> [B, 5, 32, 128] logits (channel 0 vertex, 1-4 labels).
  torch::Tensor forward(torch::Tensor x);
  torch::nn::Sequential encoder{nullptr}, decoder{nullptr};
  torch::nn::Conv2d head{nullptr};
};
TORCH_MODULE(VertexNet);

// The vertex network extended for Learned Subgoal Planning (paper Sec. V; lsp.md §2.5b): the goal enters as a
// 2-channel image [r_g sin(theta_g - phi), r_g cos(theta_g - phi)] per bearing column phi (after a BatchNorm)
// at the input of the third encoder block; the vertex head stays at 32x128, and one more decoder block gives
// a finer 64x256 grid with 3 subgoal channels (Ps logit, success cost, exploration cost).
struct SubgoalNetImpl : torch::nn::Module {
  explicit SubgoalNetImpl(double width);
  // image [B, 3, 128, 512] in [0, 1], goal [B, 2, 32, 128] -> {[B, 5, 32, 128] vertex logits,
  // [B, 3, 64, 256] subgoal outputs}.
  std::pair<torch::Tensor, torch::Tensor> forward(torch::Tensor image, torch::Tensor goal);
  torch::nn::Sequential encoder_a{nullptr}, encoder_b{nullptr}, decoder{nullptr}, fine{nullptr};
  torch::nn::BatchNorm2d goal_norm{nullptr};
  torch::nn::Conv2d vertex_head{nullptr}, subgoal_head{nullptr};
};
TORCH_MODULE(SubgoalNet);

// The goal image for a goal at 'range' and 'bearing' (radians, counter-clockwise from the heading): per column
// j of a 'cols'-wide grid looking along core::ColumnToBearing(j, cols), [range sin(bearing - phi_j),
// range cos(bearing - phi_j)], repeated down 'rows' rows.  [2, rows, cols].
torch::Tensor GoalImage(double range, double bearing, int64_t rows = 32, int64_t cols = 128);

}  // namespace toponav::learning::internal

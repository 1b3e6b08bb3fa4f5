#include "learning/internal/vertex_net.h"

#include <algorithm>
#include <cmath>

#include "learning/internal/batch_norm_leaky.h"
#include "learning/internal/net_ops.h"

namespace toponav::learning::internal {

namespace F = torch::nn::functional;

torch::Tensor MaxPool2x2Impl::forward(const torch::Tensor& x) { return MaxPool2(x); }

CircularConvImpl::CircularConvImpl(int64_t in, int64_t out) {
  conv = register_module("conv", torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, 3).padding({1, 0})));
}

torch::Tensor CircularConvImpl::forward(const torch::Tensor& x) { return conv->forward(PadCircularWidth(x)); }

namespace {

int64_t Scaled(int64_t channels, double width) { return std::max<int64_t>(4, int64_t(std::lround(channels * width))); }

// BatchNorm -> LeakyReLU(0.1) as one module, then an Identity: two modules a pair, so the Sequential's indices
// (the tensors' names in model files) are those of files saved with BatchNorm2d and LeakyReLU modules.
void AddNormLeaky(torch::nn::Sequential& s, int64_t channels) {
  s->push_back(BatchNormLeaky(channels, 0.1));
  s->push_back(torch::nn::Identity());
}

// [3x3 conv -> BatchNorm -> LeakyReLU(0.1)]
void AddConv(torch::nn::Sequential& s, int64_t in, int64_t out) {
  s->push_back(CircularConv(in, out));
  AddNormLeaky(s, out);
}

// The decoder's 2x upsampling: a 3x3 transposed convolution with stride 2, its input padded circularly by one
// column on each side (bearing wraps) and the extra columns cropped again, so its output is 2H + 2 by 2W + 2
// like a plain one.  Its parameters are named as a ConvTranspose2d's ('weight', 'bias'), so models saved
// before it wrapped still load.
struct CircularConvTransposeImpl : torch::nn::Module {
  CircularConvTransposeImpl(int64_t in, int64_t out) {
    torch::nn::ConvTranspose2d init(torch::nn::ConvTranspose2dOptions(in, out, 3).stride(2).output_padding(1));
    weight = register_parameter("weight", init->weight.detach().clone());
    bias = register_parameter("bias", init->bias.detach().clone());
  }
  torch::Tensor forward(const torch::Tensor& x) {
    const auto padded = PadCircularWidth(x);
    const auto y =
        F::conv_transpose2d(padded, weight, F::ConvTranspose2dFuncOptions().bias(bias).stride(2).output_padding(1));
    return y.slice(3, 2, y.size(3) - 2);
  }
  torch::Tensor weight, bias;
};
TORCH_MODULE(CircularConvTranspose);

// Crops one cell from every border (the transposed convolution's 2H + 2 -> 2H).
struct CropImpl : torch::nn::Module {
  torch::Tensor forward(const torch::Tensor& x) { return x.slice(2, 1, x.size(2) - 1).slice(3, 1, x.size(3) - 1); }
};
TORCH_MODULE(Crop);

}  // namespace

namespace {

// Two convolutions, then a 2x2 max-pool.
void AddEncoderBlock(torch::nn::Sequential& s, int64_t in, int64_t out) {
  AddConv(s, in, out);
  AddConv(s, out, out);
  s->push_back(MaxPool2x2());
}

// A convolution, then an exact 2x upsampling (transposed convolution, cropped).
void AddDecoderBlock(torch::nn::Sequential& s, int64_t in, int64_t out) {
  AddConv(s, in, out);
  s->push_back(CircularConvTranspose(out, out));
  AddNormLeaky(s, out);
  s->push_back(Crop());
}

constexpr int64_t kEncoder[] = {64, 64, 128, 128, 256};
constexpr int64_t kDecoder[] = {128, 64, 64};

}  // namespace

VertexNetImpl::VertexNetImpl(double width) {
  encoder = torch::nn::Sequential();
  int64_t in = 3;
  for (int64_t c : kEncoder) {
    AddEncoderBlock(encoder, in, Scaled(c, width));
    in = Scaled(c, width);
  }
  decoder = torch::nn::Sequential();
  for (int64_t c : kDecoder) {
    AddDecoderBlock(decoder, in, Scaled(c, width));
    in = Scaled(c, width);
  }
  head = torch::nn::Conv2d(torch::nn::Conv2dOptions(in, 5, 1));
  register_module("encoder", encoder);
  register_module("decoder", decoder);
  register_module("head", head);
}

torch::Tensor VertexNetImpl::forward(torch::Tensor x) { return head->forward(decoder->forward(encoder->forward(x))); }

SubgoalNetImpl::SubgoalNetImpl(double width) {
  encoder_a = torch::nn::Sequential();
  encoder_b = torch::nn::Sequential();
  int64_t in = 3;
  for (int k = 0; k < 5; ++k) {
    const int64_t out = Scaled(kEncoder[k], width);
    AddEncoderBlock(k < 2 ? encoder_a : encoder_b, k == 2 ? in + 2 : in, out);  // the goal joins block 3
    in = out;
  }
  decoder = torch::nn::Sequential();
  for (int64_t c : kDecoder) {
    AddDecoderBlock(decoder, in, Scaled(c, width));
    in = Scaled(c, width);
  }
  fine = torch::nn::Sequential();
  AddDecoderBlock(fine, in, Scaled(32, width));
  goal_norm = torch::nn::BatchNorm2d(2);
  vertex_head = torch::nn::Conv2d(torch::nn::Conv2dOptions(in, 5, 1));
  subgoal_head = torch::nn::Conv2d(torch::nn::Conv2dOptions(Scaled(32, width), 3, 1));
  register_module("encoder_a", encoder_a);
  register_module("encoder_b", encoder_b);
  register_module("decoder", decoder);
  register_module("fine", fine);
  register_module("goal_norm", goal_norm);
  register_module("vertex_head", vertex_head);
  register_module("subgoal_head", subgoal_head);
}

std::pair<torch::Tensor, torch::Tensor> SubgoalNetImpl::forward(torch::Tensor image, torch::Tensor goal) {
  const torch::Tensor a = encoder_a->forward(image);
  const torch::Tensor d = decoder->forward(encoder_b->forward(torch::cat({a, goal_norm->forward(goal)}, 1)));
  return {vertex_head->forward(d), subgoal_head->forward(fine->forward(d))};
}

torch::Tensor GoalImage(double range, double bearing, int64_t rows, int64_t cols) {
  const auto phi = torch::arange(cols, torch::kFloat64) * (2 * M_PI / double(cols)) - M_PI;
  const auto rel = bearing - phi;
  const auto row = torch::stack({range * torch::sin(rel), range * torch::cos(rel)}).to(torch::kFloat32);  // [2, cols]
  return row.unsqueeze(1).expand({2, rows, cols}).contiguous();
}

}  // namespace toponav::learning::internal

#include "learning/internal/vertex_net.h"

#include <algorithm>
#include <cmath>

namespace toponav::learning::internal {

namespace F = torch::nn::functional;

CircularConvImpl::CircularConvImpl(int64_t in, int64_t out) {
  conv = register_module("conv", torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, 3).padding({1, 0})));
}

torch::Tensor CircularConvImpl::forward(const torch::Tensor& x) {
  return conv->forward(F::pad(x, F::PadFuncOptions({1, 1, 0, 0}).mode(torch::kCircular)));
}

namespace {

int64_t Scaled(int64_t channels, double width) { return std::max<int64_t>(4, int64_t(std::lround(channels * width))); }

// [3x3 conv -> BatchNorm -> LeakyReLU(0.1)]
void AddConv(torch::nn::Sequential& s, int64_t in, int64_t out) {
  s->push_back(CircularConv(in, out));
  s->push_back(torch::nn::BatchNorm2d(out));
  s->push_back(torch::nn::LeakyReLU(torch::nn::LeakyReLUOptions().negative_slope(0.1)));
}

// Crops one cell from every border (the transposed convolution's 2H + 2 -> 2H).
struct CropImpl : torch::nn::Module {
  torch::Tensor forward(const torch::Tensor& x) {
    return x.slice(2, 1, x.size(2) - 1).slice(3, 1, x.size(3) - 1);
  }
};
TORCH_MODULE(Crop);

}  // namespace

VertexNetImpl::VertexNetImpl(double width) {
  encoder = torch::nn::Sequential();
  int64_t in = 3;
  for (int64_t c : {64, 64, 128, 128, 256}) {
    const int64_t out = Scaled(c, width);
    AddConv(encoder, in, out);
    AddConv(encoder, out, out);
    encoder->push_back(torch::nn::MaxPool2d(2));
    in = out;
  }
  decoder = torch::nn::Sequential();
  for (int64_t c : {128, 64, 64}) {
    const int64_t out = Scaled(c, width);
    AddConv(decoder, in, out);
    decoder->push_back(torch::nn::ConvTranspose2d(torch::nn::ConvTranspose2dOptions(out, out, 3).stride(2).output_padding(1)));
    decoder->push_back(torch::nn::BatchNorm2d(out));
    decoder->push_back(torch::nn::LeakyReLU(torch::nn::LeakyReLUOptions().negative_slope(0.1)));
    decoder->push_back(Crop());
    in = out;
  }
  head = torch::nn::Conv2d(torch::nn::Conv2dOptions(in, 5, 1));
  register_module("encoder", encoder);
  register_module("decoder", decoder);
  register_module("head", head);
}

torch::Tensor VertexNetImpl::forward(torch::Tensor x) { return head->forward(decoder->forward(encoder->forward(x))); }

}  // namespace toponav::learning::internal

#include "learning/internal/net_ops.h"

#include <ATen/Parallel.h>

namespace toponav::learning::internal {

namespace {

using torch::autograd::AutogradContext;
using torch::autograd::variable_list;

struct PadCircularWidthFn : torch::autograd::Function<PadCircularWidthFn> {
  static torch::Tensor forward(AutogradContext*, const torch::Tensor& x) {
    const int64_t w = x.size(3);
    return torch::cat({x.narrow(3, w - 1, 1), x, x.narrow(3, 0, 1)}, 3);
  }
  static variable_list backward(AutogradContext*, variable_list grads) {
    TORCH_CHECK(!torch::GradMode::is_enabled(), "PadCircularWidth: no second derivative (create_graph)");
    const torch::Tensor& g = grads[0];
    const int64_t w = g.size(3) - 2;
    torch::Tensor gx = g.narrow(3, 1, w).clone(torch::MemoryFormat::Contiguous);  // never the incoming gradient
    gx.narrow(3, 0, 1).add_(g.narrow(3, w + 1, 1));
    gx.narrow(3, w - 1, 1).add_(g.narrow(3, 0, 1));
    return {gx};
  }
};

// One row of 2x2 windows: 'top' and the row below it -> each window's maximum and which of its cells gave it,
// 0-3 in max_pool2d's scan order (0,0), (0,1), (1,0), (1,1): a later cell wins when greater, or NaN.  Without
// branches, so random inputs cost no mispredictions.
void PoolRow(const float* top, int64_t width, int64_t windows, float* out, uint8_t* which) {
  const float* bottom = top + width;
  for (int64_t j = 0; j < windows; ++j) {
    float best = top[2 * j];
    uint8_t cell = 0;
    const float later[3] = {top[2 * j + 1], bottom[2 * j], bottom[2 * j + 1]};
    for (uint8_t k = 0; k < 3; ++k) {
      const float v = later[k];
      const bool wins = (v > best) | (v != v);
      best = wins ? v : best;
      cell = wins ? uint8_t(k + 1) : cell;
    }
    out[j] = best;
    which[j] = cell;
  }
}

// The gradient of one row of windows: each window's to the cell that gave its maximum, 0 to the other three.
void UnpoolRow(const float* grad, const uint8_t* which, int64_t windows, int64_t width, float* top) {
  float* bottom = top + width;
  for (int64_t j = 0; j < windows; ++j) {
    const float g = grad[j];
    const uint8_t cell = which[j];
    top[2 * j] = cell == 0 ? g : 0.0f;
    top[2 * j + 1] = cell == 1 ? g : 0.0f;
    bottom[2 * j] = cell == 2 ? g : 0.0f;
    bottom[2 * j + 1] = cell == 3 ? g : 0.0f;
  }
}

// The training path, for contiguous float32 CPU tensors: the maxima and the cell each came from in one pass,
// the gradient written in one pass (max_pool2d spends most of its time on branches and index arithmetic).
struct MaxPool2Fn : torch::autograd::Function<MaxPool2Fn> {
  static torch::Tensor forward(AutogradContext* ctx, const torch::Tensor& input) {
    const torch::Tensor x = input.contiguous();
    const int64_t planes = x.size(0) * x.size(1), height = x.size(2), width = x.size(3);
    const int64_t rows = height / 2, windows = width / 2;
    torch::Tensor out = torch::empty({x.size(0), x.size(1), rows, windows}, x.options());
    torch::Tensor which = torch::empty(out.sizes(), x.options().dtype(torch::kUInt8));
    const float* in = x.data_ptr<float>();
    float* o = out.data_ptr<float>();
    uint8_t* w = which.data_ptr<uint8_t>();
    at::parallel_for(0, planes * rows, 16, [&](int64_t begin, int64_t end) {
      for (int64_t r = begin; r < end; ++r)
        PoolRow(in + ((r / rows) * height + 2 * (r % rows)) * width, width, windows, o + r * windows, w + r * windows);
    });
    ctx->save_for_backward({which});
    ctx->saved_data["sizes"] = x.sizes().vec();
    return out;
  }
  static variable_list backward(AutogradContext* ctx, variable_list grads) {
    TORCH_CHECK(!torch::GradMode::is_enabled(), "MaxPool2: no second derivative (create_graph)");
    const torch::Tensor which = ctx->get_saved_variables()[0];
    const std::vector<int64_t> sizes = ctx->saved_data["sizes"].toIntVector();
    const torch::Tensor g = grads[0].contiguous();
    torch::Tensor gx = torch::empty(sizes, g.options());
    const int64_t height = sizes[2], width = sizes[3], rows = height / 2, windows = width / 2;
    if (height % 2) gx.select(2, height - 1).zero_();  // the dropped last row and column get no gradient
    if (width % 2) gx.select(3, width - 1).zero_();
    const float* gp = g.data_ptr<float>();
    const uint8_t* w = which.data_ptr<uint8_t>();
    float* out = gx.data_ptr<float>();
    at::parallel_for(0, which.numel() / windows, 16, [&](int64_t begin, int64_t end) {
      for (int64_t r = begin; r < end; ++r)
        UnpoolRow(gp + r * windows, w + r * windows, windows, width,
                  out + ((r / rows) * height + 2 * (r % rows)) * width);
    });
    return {gx};
  }
};

}  // namespace

torch::Tensor PadCircularWidth(const torch::Tensor& x) {
  TORCH_CHECK(x.dim() == 4 && x.size(3) >= 1, "PadCircularWidth: a [B, C, H, W >= 1] input");
  return PadCircularWidthFn::apply(x);
}

torch::Tensor MaxPool2(const torch::Tensor& x) {
  TORCH_CHECK(x.dim() == 4 && x.size(2) >= 2 && x.size(3) >= 2, "MaxPool2: a [B, C, H >= 2, W >= 2] input");
  if (x.requires_grad()) {
    if (x.is_cpu() && x.scalar_type() == torch::kFloat) return MaxPool2Fn::apply(x);
    return torch::max_pool2d(x, 2);  // another device or type: the library's
  }
  const int64_t h = x.size(2) / 2 * 2, w = x.size(3) / 2 * 2;
  const torch::Tensor rows = torch::max(x.slice(2, 0, h, 2), x.slice(2, 1, h, 2));
  return torch::max(rows.slice(3, 0, w, 2), rows.slice(3, 1, w, 2));
}

}  // namespace toponav::learning::internal

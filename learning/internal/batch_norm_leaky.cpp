#include "learning/internal/batch_norm_leaky.h"

#include <ATen/Parallel.h>

#include <algorithm>
#include <cmath>

namespace toponav::learning::internal {

namespace {

using torch::autograd::AutogradContext;
using torch::autograd::variable_list;

constexpr int kLanes = 16;        // independent float sums, so the compiler vectorizes without reordering
constexpr int64_t kBlock = 4096;  // values a lane sums in float before the block's sum goes to a double

// One channel's constants: z = x * scale + shift, y = LeakyReLU(z); xhat = (x - mean) * invstd.
struct Channel {
  float scale, shift, mean, invstd, slope;
};

// The loops below are written to vectorize (CMakeLists.txt compiles this file with -fno-trapping-math, which
// lets the compiler turn the LeakyReLU's select into a blend; the results are the same).

// Over values 0..n-1: the sums of a and of a * b, where f(i, a, b) gives the pair at i.  Float lanes, each
// block's sums added to the doubles.
template <class F>
void PairSums(int64_t n, F f, double* sum_a, double* sum_ab) {
  for (int64_t start = 0; start < n; start += kBlock) {
    const int64_t end = std::min(n, start + kBlock);
    float s[kLanes] = {}, p[kLanes] = {};
    int64_t i = start;
    for (; i + kLanes <= end; i += kLanes)
      for (int k = 0; k < kLanes; ++k) {
        float a, b;
        f(i + k, a, b);
        s[k] += a;
        p[k] += a * b;
      }
    for (; i < end; ++i) {
      float a, b;
      f(i, a, b);
      s[0] += a;
      p[0] += a * b;
    }
    for (int k = 0; k < kLanes; ++k) {
      *sum_a += s[k];
      *sum_ab += p[k];
    }
  }
}

// Over n values of one plane: the sums of d = x - offset and of d * d.
void StatisticsSums(const float* __restrict x, int64_t n, float offset, double* sum, double* sum_sq) {
  PairSums(
      n, [&](int64_t i, float& a, float& b) { a = b = x[i] - offset; }, sum, sum_sq);
}

// The gradient through the LeakyReLU at one value.
inline float Dz(float x, float g, const Channel& c) {
  const float low = g * c.slope;
  return x * c.scale + c.shift > 0 ? g : low;
}

// Over n values of one plane: the sums of dz and of dz * xhat.
void GradientSums(const float* __restrict x, const float* __restrict g, int64_t n, const Channel& c, double* sum_dz,
                  double* sum_dz_xhat) {
  const auto pair = [&](int64_t i, float& dz, float& xhat) {
    dz = Dz(x[i], g[i], c);
    xhat = (x[i] - c.mean) * c.invstd;
  };
  PairSums(n, pair, sum_dz, sum_dz_xhat);
}

void NormalizePlane(const float* __restrict x, int64_t n, const Channel& c, float* __restrict y) {
  for (int64_t i = 0; i < n; ++i) {
    const float z = x[i] * c.scale + c.shift;
    const float low = z * c.slope;
    y[i] = z > 0 ? z : low;
  }
}

// dx = weight * invstd * (dz - mean(dz) - xhat * mean(dz * xhat)), the means over the channel.
void InputGradientPlane(const float* __restrict x, const float* __restrict g, int64_t n, const Channel& c, float k,
                        float mean_dz, float mean_dz_xhat, float* __restrict dx) {
  for (int64_t i = 0; i < n; ++i) dx[i] = k * (Dz(x[i], g[i], c) - mean_dz - (x[i] - c.mean) * c.invstd * mean_dz_xhat);
}

// The planes of channel c of a contiguous [B, C, H, W] tensor: f(offset of the plane, its size) for each b.
template <class F>
void ForPlanes(const torch::Tensor& t, int64_t c, F f) {
  const int64_t channels = t.size(1), plane = t.size(2) * t.size(3);
  for (int64_t b = 0; b < t.size(0); ++b) f((b * channels + c) * plane, plane);
}

// Per channel: the batch mean and the biased variance, its sums taken about the mean of the channel's first
// plane, so that a mean far from 0 does not cancel the variance away.  Two float tensors [C].
std::pair<torch::Tensor, torch::Tensor> ChannelStatistics(const torch::Tensor& x) {
  const int64_t channels = x.size(1);
  torch::Tensor mean = torch::empty({channels}, x.options()), var = torch::empty({channels}, x.options());
  const float* in = x.data_ptr<float>();
  float *mean_out = mean.data_ptr<float>(), *var_out = var.data_ptr<float>();
  const double count = double(x.numel() / channels);
  at::parallel_for(0, channels, 1, [&](int64_t c0, int64_t c1) {
    for (int64_t c = c0; c < c1; ++c) {
      const int64_t plane = x.size(2) * x.size(3);
      double sum = 0, sum_sq = 0;
      StatisticsSums(in + c * plane, plane, 0.0f, &sum, &sum_sq);
      const float offset = float(sum / double(plane));
      sum = sum_sq = 0;
      ForPlanes(x, c, [&](int64_t at, int64_t n) { StatisticsSums(in + at, n, offset, &sum, &sum_sq); });
      const double m = sum / count;
      mean_out[c] = float(offset + m);
      var_out[c] = float(std::max(0.0, sum_sq / count - m * m));
    }
  });
  return {mean, var};
}

// Each channel's constants.
std::vector<Channel> Channels(const torch::Tensor& weight, const torch::Tensor& bias, const torch::Tensor& mean,
                              const torch::Tensor& invstd, double slope) {
  const int64_t n = mean.numel();
  const auto w = weight.contiguous(), b = bias.contiguous();
  std::vector<Channel> out(static_cast<size_t>(n));
  for (int64_t c = 0; c < n; ++c) {
    Channel& ch = out[size_t(c)];
    ch.mean = mean.data_ptr<float>()[c];
    ch.invstd = invstd.data_ptr<float>()[c];
    ch.scale = w.data_ptr<float>()[c] * ch.invstd;
    ch.shift = b.data_ptr<float>()[c] - ch.mean * ch.scale;
    ch.slope = float(slope);
  }
  return out;
}

struct BatchNormLeakyFn : torch::autograd::Function<BatchNormLeakyFn> {
  static torch::Tensor forward(AutogradContext* ctx, const torch::Tensor& x, const torch::Tensor& weight,
                               const torch::Tensor& bias, const torch::Tensor& mean, const torch::Tensor& invstd,
                               double slope) {
    const std::vector<Channel> channels = Channels(weight, bias, mean, invstd, slope);
    torch::Tensor y = torch::empty_like(x);
    const float* in = x.data_ptr<float>();
    float* out = y.data_ptr<float>();
    at::parallel_for(0, x.size(1), 1, [&](int64_t c0, int64_t c1) {
      for (int64_t c = c0; c < c1; ++c)
        ForPlanes(x, c, [&](int64_t at, int64_t n) { NormalizePlane(in + at, n, channels[size_t(c)], out + at); });
    });
    ctx->save_for_backward({x, weight, bias, mean, invstd});
    ctx->saved_data["slope"] = slope;
    return y;
  }
  static variable_list backward(AutogradContext* ctx, variable_list grads);
};

variable_list BatchNormLeakyFn::backward(AutogradContext* ctx, variable_list grads) {
  TORCH_CHECK(!torch::GradMode::is_enabled(), "BatchNormLeaky: no second derivative (create_graph)");
  const auto saved = ctx->get_saved_variables();
  const torch::Tensor& x = saved[0];
  const std::vector<Channel> channels =
      Channels(saved[1], saved[2], saved[3], saved[4], ctx->saved_data["slope"].toDouble());
  const torch::Tensor dy = grads[0].contiguous();
  const double count = double(x.numel() / x.size(1));
  torch::Tensor dx = torch::empty_like(x), dweight = torch::empty({x.size(1)}, x.options());
  torch::Tensor dbias = torch::empty({x.size(1)}, x.options());
  const torch::Tensor weight = saved[1].contiguous();
  const float *in = x.data_ptr<float>(), *g = dy.data_ptr<float>(), *w = weight.data_ptr<float>();
  float *out = dx.data_ptr<float>(), *dw = dweight.data_ptr<float>(), *db = dbias.data_ptr<float>();
  at::parallel_for(0, x.size(1), 1, [&](int64_t c0, int64_t c1) {
    for (int64_t c = c0; c < c1; ++c) {
      const Channel& ch = channels[size_t(c)];
      double sum_dz = 0, sum_dz_xhat = 0;
      ForPlanes(x, c, [&](int64_t at, int64_t n) { GradientSums(in + at, g + at, n, ch, &sum_dz, &sum_dz_xhat); });
      dw[c] = float(sum_dz_xhat);
      db[c] = float(sum_dz);
      const float k = w[c] * ch.invstd, mean_dz = float(sum_dz / count), mean_dz_xhat = float(sum_dz_xhat / count);
      ForPlanes(x, c, [&](int64_t at, int64_t n) {
        InputGradientPlane(in + at, g + at, n, ch, k, mean_dz, mean_dz_xhat, out + at);
      });
    }
  });
  return {dx, dweight, dbias, torch::Tensor(), torch::Tensor(), torch::Tensor()};
}

}  // namespace

torch::Tensor BatchNormLeakyTraining(const torch::Tensor& x, const torch::Tensor& weight, const torch::Tensor& bias,
                                     torch::Tensor& running_mean, torch::Tensor& running_var, double momentum,
                                     double eps, double slope) {
  TORCH_CHECK(x.dim() == 4 && x.size(1) > 0 && x.is_cpu() && x.scalar_type() == torch::kFloat,
              "BatchNormLeakyTraining: a float32 CPU input [B, C > 0, H, W]");
  const int64_t count = x.numel() / x.size(1);
  TORCH_CHECK(count >= 2, "BatchNormLeakyTraining: batch statistics need two values a channel");
  const torch::Tensor xc = x.contiguous();
  torch::Tensor mean, var;
  {
    torch::NoGradGuard no_grad;
    std::tie(mean, var) = ChannelStatistics(xc.detach());
    running_mean.mul_(1 - momentum).add_(mean, momentum);
    running_var.mul_(1 - momentum).add_(var * (double(count) / double(count - 1)), momentum);
  }
  return BatchNormLeakyFn::apply(xc, weight, bias, mean, (var + eps).rsqrt(), slope);
}

BatchNormLeakyImpl::BatchNormLeakyImpl(int64_t channels, double slope_) : slope(slope_) {
  weight = register_parameter("weight", torch::ones({channels}));
  bias = register_parameter("bias", torch::zeros({channels}));
  running_mean = register_buffer("running_mean", torch::zeros({channels}));
  running_var = register_buffer("running_var", torch::ones({channels}));
  num_batches_tracked = register_buffer("num_batches_tracked", torch::zeros({}, torch::kLong));
}

torch::Tensor BatchNormLeakyImpl::forward(const torch::Tensor& x) {
  TORCH_CHECK(x.dim() == 4, "BatchNormLeaky: a [B, C, H, W] input");
  if (is_training()) {
    torch::NoGradGuard no_grad;
    num_batches_tracked += 1;
  }
  if (is_training() && x.is_cpu() && x.scalar_type() == torch::kFloat)
    return BatchNormLeakyTraining(x, weight, bias, running_mean, running_var, momentum, eps, slope);
  const torch::Tensor y = torch::batch_norm(x, weight, bias, running_mean, running_var, is_training(), momentum, eps,
                                            at::globalContext().userEnabledCuDNN());
  return torch::leaky_relu(y, slope);
}

}  // namespace toponav::learning::internal

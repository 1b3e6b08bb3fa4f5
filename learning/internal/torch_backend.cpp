// The only place that chooses CPU or CUDA (aesthetics.md rule 20).
#include <torch/torch.h>

#include <iostream>

#include "learning/learning.h"

namespace toponav::learning {

BackendInfo SelectBackend(bool prefer_cuda, int num_threads) {
  BackendInfo info;
  info.torch_version = TORCH_VERSION;
  info.cuda_available = torch::cuda::is_available();
  if (num_threads > 0) torch::set_num_threads(num_threads);
  info.num_threads = torch::get_num_threads();
  if (prefer_cuda && info.cuda_available) {
    info.device = "cuda:0";
  } else {
    if (prefer_cuda) std::cerr << "warning: CUDA requested but not available; using the CPU\n";
    info.device = "cpu";
  }
  return info;
}

double ConvolutionCheck(int height, int width) {
  torch::NoGradGuard no_grad;
  auto image = torch::ones({1, 1, height, width});
  auto kernel = torch::ones({1, 1, 3, 3});
  auto out = torch::conv2d(image, kernel, {}, 1, 1);
  return out.sum().item<double>();
}

}  // namespace toponav::learning

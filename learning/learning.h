#pragma once
// Front door of the learning layer.  So far: the compute backend (the one place that chooses CPU or CUDA).
#include <string>

namespace toponav::learning {

struct BackendInfo {
  std::string torch_version;
  std::string device;          // "cpu" or "cuda:0"
  int num_threads = 1;         // intra-op threads on the CPU
  bool cuda_available = false;
};

// Picks the device: CUDA when 'prefer_cuda' and a CUDA build with a GPU is present, otherwise the CPU
// (with a warning on stderr when CUDA was asked for).  'num_threads' > 0 sets the CPU thread count.
BackendInfo SelectBackend(bool prefer_cuda, int num_threads = 0);

// A real computation on the selected backend: the sum of a 3x3 convolution of an all-ones 1x1xHxW image
// with an all-ones kernel (zero padding).  Used by `toponav info` and the tests to prove LibTorch works.
double ConvolutionCheck(int height, int width);

}  // namespace toponav::learning

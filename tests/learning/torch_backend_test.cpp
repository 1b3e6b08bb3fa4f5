#include <gtest/gtest.h>

#include "learning/learning.h"

namespace toponav::learning {
namespace {

TEST(TorchBackend, CpuIsAlwaysAvailable) {
  const BackendInfo info = SelectBackend(false, 2);
  EXPECT_EQ(info.device, "cpu");
  EXPECT_FALSE(info.torch_version.empty());
  EXPECT_GE(info.num_threads, 1);
}

TEST(TorchBackend, CudaRequestFallsBackWhenUnavailable) {
  const BackendInfo info = SelectBackend(true);
  EXPECT_EQ(info.device, info.cuda_available ? "cuda:0" : "cpu");
}

TEST(TorchBackend, ConvolutionComputesTheExpectedSum) {
  // Ones image HxW, ones 3x3 kernel, zero padding: each output sums its in-bounds neighbourhood.
  // Row and column neighbourhood counts are (2, 3, ..., 3, 2); the total is their products summed.
  auto line = [](int n) { return n == 1 ? 1.0 : 2.0 * 2 + 3.0 * (n - 2); };
  EXPECT_DOUBLE_EQ(ConvolutionCheck(4, 5), line(4) * line(5));
  EXPECT_DOUBLE_EQ(ConvolutionCheck(8, 3), line(8) * line(3));
}

}  // namespace
}  // namespace toponav::learning

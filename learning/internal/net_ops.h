#pragma once
// Two of the vertex network's layers as LibTorch autograd functions with their gradients written out: the same
// values as the library's own (F::pad circular, max_pool2d), forward and backward, but without the per-slice
// autograd graph (pad) or the indexed kernels (max-pool) that take most of LibTorch 1.13's CPU time in them.
#include <torch/torch.h>

namespace toponav::learning::internal {

// x [B, C, H, W] -> [B, C, H, W + 2]: the last column copied before the first and the first after the last
// (bearing wraps), as F::pad(x, {1, 1, 0, 0}) in circular mode.  Its gradient adds each copy's gradient to
// the column it came from.
torch::Tensor PadCircularWidth(const torch::Tensor& x);

// A 2x2 max-pool with stride 2 (an odd last row or column is dropped), as torch::max_pool2d(x, 2) value for
// value (NaN wins its window).  Without gradients it is the elementwise maximum of the even and odd rows, then
// columns.  With them each window's gradient goes to the cell max_pool2d's backward picks: the first maximum
// in row-major order (the last NaN where there is one).
torch::Tensor MaxPool2(const torch::Tensor& x);

}  // namespace toponav::learning::internal

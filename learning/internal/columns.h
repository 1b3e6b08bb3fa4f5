#pragma once
// Moving the columns of row-major grids (panoramas and range-bearing grids): rolls and mirrors in bearing.
#include <cstddef>
#include <vector>

namespace toponav::learning::internal {

// Moves column c of a row-major rows x cols grid of 'channels' values a cell to column to(c, cols).
template <class T, class To>
void MoveColumns(const std::vector<T>& in, int rows, int cols, size_t channels, const To& to, std::vector<T>* out) {
  for (int row = 0; row < rows; ++row)
    for (int c = 0; c < cols; ++c) {
      const size_t from = size_t(row) * size_t(cols) + size_t(c);
      const size_t dest = size_t(row) * size_t(cols) + size_t(to(c, cols));
      for (size_t k = 0; k < channels; ++k) (*out)[dest * channels + k] = in[from * channels + k];
    }
}

// Column c moved to column (cols - c) mod cols: bearing b becomes -b.
inline int MirrorColumn(int c, int cols) { return (cols - c) % cols; }

}  // namespace toponav::learning::internal

#pragma once
// The learned sensor's output grid (vertexnav.md §4.3): 'rows' range bins by 'cols' bearing bins.  Row k holds
// ranges nearest (k + 1) * max_range / rows (bin centres dr, 2 dr, ..., max_range); column j looks along
// bearing core::ColumnToBearing(j, cols), and bearing wraps around (column cols - 1 neighbours column 0).
#include <cstddef>

namespace toponav::core {

struct RangeBearingGrid {
  int rows = 32;
  int cols = 128;
  double max_range = 100.0;

  double RangeStep() const { return max_range / rows; }
  // The row whose range is nearest 'range' (clamped to the grid; a range at or beyond max_range maps to the
  // last row, so callers leave such vertices out).
  int RangeRow(double range) const;
  int BearingCol(double bearing) const;    // nearest column, wrapping
  double RowRange(int row) const { return (row + 1) * RangeStep(); }
  double ColBearing(int col) const;
  size_t Index(int row, int col) const { return size_t(row) * size_t(cols) + size_t(col); }
  size_t size() const { return size_t(rows) * size_t(cols); }
};

}  // namespace toponav::core

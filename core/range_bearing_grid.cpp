#include "core/range_bearing_grid.h"

#include <algorithm>
#include <cmath>

#include "core/detection.h"

namespace toponav::core {

int RangeBearingGrid::RangeRow(double range) const {
  return std::clamp(int(std::lround(range / RangeStep())) - 1, 0, rows - 1);
}

int RangeBearingGrid::BearingCol(double bearing) const { return BearingToColumn(bearing, cols); }

double RangeBearingGrid::ColBearing(int col) const { return ColumnToBearing(col, cols); }

}  // namespace toponav::core

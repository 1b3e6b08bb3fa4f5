#pragma once
// Frontier properties on a sensor's range-bearing grid: the labels the subgoal network learns (paper Sec. V;
// lsp.md §2.6), made by planning::RasterizeSubgoalLabels and read by the learning layer.
#include <cstdint>
#include <vector>

#include "core/range_bearing_grid.h"

namespace toponav::core {

// The subgoal network's output grid (finer than the vertex grid's 32x128): labels and outputs share it.
inline constexpr RangeBearingGrid kSubgoalGrid{64, 256, 100.0};

struct SubgoalLabelGrid {
  RangeBearingGrid grid;
  std::vector<uint8_t> mask;                         // 1: a frontier cell the pose sees
  std::vector<float> ps, delta_success, exploration; // its frontier's properties (0 elsewhere)
};

}  // namespace toponav::core

#pragma once
// Training labels for the learned vertex sensor (vertexnav.md §4.3), from the ray-cast ground truth: on the
// range-bearing grid, each visible vertex (closer than max_range) marks the cell nearest its range and
// bearing with its 4-way label.  Two vertices in one cell: the nearer one wins (the reference overwrote in
// bearing order).
#include <cstdint>
#include <vector>

#include "core/range_bearing_grid.h"
#include "sim/raycast.h"

namespace toponav::sim {

// Per cell: kNoVertex, or 1 + core::VertexLabel (1 right gap, 2 corner, 3 left gap, 4 point).
constexpr uint8_t kNoVertex = 0;
struct VertexLabelGrid {
  core::RangeBearingGrid grid;
  std::vector<uint8_t> cells;  // grid.size(), row-major (row = range bin)
  int num_vertices() const;
};

VertexLabelGrid RasterizeVertexLabels(const std::vector<VisibleVertex>& visible, const core::RangeBearingGrid& grid);

}  // namespace toponav::sim

#include "sim/vertex_labels.h"

#include <algorithm>
#include <limits>

namespace toponav::sim {

int VertexLabelGrid::num_vertices() const {
  return int(std::count_if(cells.begin(), cells.end(), [](uint8_t c) { return c != kNoVertex; }));
}

VertexLabelGrid RasterizeVertexLabels(const std::vector<VisibleVertex>& visible, const core::RangeBearingGrid& grid) {
  VertexLabelGrid out;
  out.grid = grid;
  out.cells.assign(grid.size(), kNoVertex);
  std::vector<double> nearest(grid.size(), std::numeric_limits<double>::infinity());
  for (const auto& v : visible) {
    if (!(v.range < grid.max_range)) continue;
    const size_t i = grid.Index(grid.RangeRow(v.range), grid.BearingCol(v.bearing));
    if (v.range >= nearest[i]) continue;
    nearest[i] = v.range;
    out.cells[i] = uint8_t(1 + int(v.label));
  }
  return out;
}

}  // namespace toponav::sim

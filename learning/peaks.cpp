#include "learning/peaks.h"

#include <algorithm>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "core/geometry.h"

namespace toponav::learning {

namespace {

// The cells of one connected component (8-connected, wrapping in bearing) of 'on', starting at 'seed';
// marks them seen.  Returns the highest cell.
Peak FloodComponent(const std::vector<float>& prob, const std::vector<char>& on, const core::RangeBearingGrid& g,
                    int seed_row, int seed_col, std::vector<char>* seen) {
  Peak best{seed_row, seed_col, prob[g.Index(seed_row, seed_col)]};
  std::vector<std::pair<int, int>> stack{{seed_row, seed_col}};
  (*seen)[g.Index(seed_row, seed_col)] = 1;
  while (!stack.empty()) {
    const auto [r, c] = stack.back();
    stack.pop_back();
    const float v = prob[g.Index(r, c)];
    if (v > best.value || (v == best.value && (r < best.row || (r == best.row && c < best.col)))) best = {r, c, v};
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int rr = r + dr, cc = (c + dc + g.cols) % g.cols;
        if (rr < 0 || rr >= g.rows) continue;
        const size_t i = g.Index(rr, cc);
        if (!on[i] || (*seen)[i]) continue;
        (*seen)[i] = 1;
        stack.push_back({rr, cc});
      }
  }
  return best;
}

// The offset, in cells, of the centroid of three neighbouring values (before, at, after the peak): where the
// network spreads a vertex over two cells, it lies between them.
double CentroidOffset(float before, float at, float after) {
  const float sum = before + at + after;
  return sum > 0.0f ? std::clamp(double(after - before) / sum, -0.5, 0.5) : 0.0;
}

// The peak's range and bearing, refined within its cell by the centroid along each axis (range rows beyond
// the grid count as 0; bearing wraps around).
std::pair<double, double> RefinedRangeBearing(const std::vector<float>& prob, const core::RangeBearingGrid& g,
                                              const Peak& p) {
  auto at = [&](int r, int c) { return r < 0 || r >= g.rows ? 0.0f : prob[g.Index(r, (c + g.cols) % g.cols)]; };
  const double dr = CentroidOffset(at(p.row - 1, p.col), p.value, at(p.row + 1, p.col));
  const double dc = CentroidOffset(at(p.row, p.col - 1), p.value, at(p.row, p.col + 1));
  const double bearing_step = 2.0 * core::kPi / g.cols;
  return {g.RowRange(p.row) + dr * g.RangeStep(), core::WrapAngle(g.ColBearing(p.col) + dc * bearing_step)};
}

}  // namespace

std::vector<Peak> DetectPeaks(const std::vector<float>& prob, const core::RangeBearingGrid& grid, float threshold) {
  TOPONAV_CHECK(prob.size() == grid.size(),
                "probability map of " << prob.size() << " cells for a grid of " << grid.size());
  std::vector<char> on(grid.size()), seen(grid.size(), 0);
  for (size_t i = 0; i < prob.size(); ++i) on[i] = prob[i] >= threshold - 0.1f;
  std::vector<Peak> peaks;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const size_t i = grid.Index(r, c);
      if (!on[i] || seen[i]) continue;
      const Peak p = FloodComponent(prob, on, grid, r, c, &seen);
      if (p.value > threshold) peaks.push_back(p);
    }
  std::sort(peaks.begin(), peaks.end(),
            [](const Peak& a, const Peak& b) { return a.col != b.col ? a.col < b.col : a.row < b.row; });
  return peaks;
}

std::vector<core::Detection> DecodeDetections(const std::vector<float>& prob, const std::vector<float>& label_probs,
                                              const core::RangeBearingGrid& grid, const DecodeOptions& o) {
  TOPONAV_CHECK(label_probs.size() == 4 * grid.size(), "label map of " << label_probs.size() << " values");
  std::vector<core::Detection> out;
  for (const Peak& p : DetectPeaks(prob, grid, o.threshold)) {
    core::Detection d;
    if (o.sub_bin) {
      std::tie(d.range, d.bearing) = RefinedRangeBearing(prob, grid, p);
    } else {
      d.range = grid.RowRange(p.row);
      d.bearing = grid.ColBearing(p.col);
    }
    d.polar = {o.sigma_range * o.sigma_range, 0.0, o.sigma_bearing * o.sigma_bearing};
    for (int k = 0; k < 4; ++k) d.labels[size_t(k)] = label_probs[4 * grid.Index(p.row, p.col) + size_t(k)];
    out.push_back(d);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.bearing < b.bearing; });
  return out;
}

}  // namespace toponav::learning

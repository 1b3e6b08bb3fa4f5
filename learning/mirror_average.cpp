#include "learning/mirror_average.h"

#include "core/error.h"
#include "learning/internal/columns.h"

namespace toponav::learning {

namespace {

// Column c of a row-major rows x cols grid of 'channels' values a cell, moved to column (cols - c) mod cols.
template <class T>
std::vector<T> FlipColumns(const std::vector<T>& in, int rows, int cols, size_t channels) {
  TOPONAV_CHECK(in.size() == size_t(rows) * size_t(cols) * channels, "a grid of " << in.size() << " values");
  std::vector<T> out(in.size());
  internal::MoveColumns(in, rows, cols, channels, internal::MirrorColumn, &out);
  return out;
}

std::vector<float> Mean(const std::vector<float>& a, const std::vector<float>& b) {
  TOPONAV_CHECK(a.size() == b.size(), "outputs of " << a.size() << " and " << b.size() << " values");
  std::vector<float> out(a.size());
  for (size_t i = 0; i < a.size(); ++i) out[i] = 0.5f * (a[i] + b[i]);
  return out;
}

}  // namespace

core::Panorama MirroredPanorama(const core::Panorama& image) {
  core::Panorama out = image;
  out.rgb = FlipColumns(image.rgb, image.height, image.width, 3);
  if (!image.depth.empty()) out.depth = FlipColumns(image.depth, image.height, image.width, 1);
  if (!image.ids.empty()) out.ids = FlipColumns(image.ids, image.height, image.width, 1);
  return out;
}

GridOutput MirroredBack(const GridOutput& out) {
  GridOutput r = out;
  r.vertex = FlipColumns(out.vertex, out.grid.rows, out.grid.cols, 1);
  r.labels = FlipColumns(out.labels, out.grid.rows, out.grid.cols, 4);
  for (size_t i = 0; i + 3 < r.labels.size(); i += 4) std::swap(r.labels[i], r.labels[i + 2]);  // right <-> left
  return r;
}

SubgoalOutput MirroredBack(const SubgoalOutput& out) {
  SubgoalOutput r = out;
  for (auto field : {&SubgoalOutput::ps, &SubgoalOutput::delta_success, &SubgoalOutput::exploration})
    r.*field = FlipColumns(out.*field, out.grid.rows, out.grid.cols, 1);
  return r;
}

GridOutput Mean(const GridOutput& a, const GridOutput& b) {
  GridOutput r = a;
  r.vertex = Mean(a.vertex, b.vertex);
  r.labels = Mean(a.labels, b.labels);
  return r;
}

SubgoalOutput Mean(const SubgoalOutput& a, const SubgoalOutput& b) {
  SubgoalOutput r = a;
  for (auto field : {&SubgoalOutput::ps, &SubgoalOutput::delta_success, &SubgoalOutput::exploration})
    r.*field = Mean(a.*field, b.*field);
  return r;
}

}  // namespace toponav::learning

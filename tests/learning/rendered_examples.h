#pragma once
// Training examples for the learning tests: panoramas of a world's start, turned to two headings, with
// their ray-cast vertex labels.
#include <vector>

#include "core/image.h"
#include "core/subgoal_labels.h"
#include "core/world.h"
#include "sim/raycast.h"
#include "sim/render.h"
#include "sim/vertex_labels.h"

namespace toponav::learning::testing {

struct Rendered {
  std::vector<core::Pose2> poses;
  std::vector<core::Panorama> images;
  std::vector<sim::VertexLabelGrid> labels;
};

inline Rendered RenderAtStart(const core::World& w, const std::vector<double>& yaws = {0.0, 2.0}) {
  const sim::Renderer renderer(w, {});
  const sim::RayCaster caster(w);
  Rendered r;
  for (double yaw : yaws) {
    const core::Pose2 pose{w.start.x, w.start.y, yaw};
    r.poses.push_back(pose);
    r.images.push_back(renderer.Render(pose));
    r.labels.push_back(sim::RasterizeVertexLabels(caster.VisibleVertices(pose, 100.0), core::RangeBearingGrid{}));
  }
  return r;
}

// Made-up subgoal labels: a band of frontier cells in row 10 of the 64x256 grid, the left half (columns
// below 128) leading to the goal (Ps 1, success cost 30), the right half not (exploration cost 120).
inline core::SubgoalLabelGrid SubgoalBand() {
  core::SubgoalLabelGrid s;
  s.grid = {64, 256, 100.0};
  s.mask.assign(s.grid.size(), 0);
  s.ps.assign(s.grid.size(), 0.0f);
  s.delta_success.assign(s.grid.size(), 0.0f);
  s.exploration.assign(s.grid.size(), 0.0f);
  for (int col = 0; col < 256; ++col) {
    const size_t i = s.grid.Index(10, col);
    s.mask[i] = 1;
    const bool left = col < 128;
    s.ps[i] = left ? 1.0f : 0.0f;
    s.delta_success[i] = left ? 30.0f : 0.0f;
    s.exploration[i] = left ? 0.0f : 120.0f;
  }
  return s;
}

}  // namespace toponav::learning::testing

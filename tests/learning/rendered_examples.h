#pragma once
// Training examples for the learning tests: panoramas of a world's start, turned to two headings, with
// their ray-cast vertex labels.
#include <vector>

#include "core/image.h"
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

}  // namespace toponav::learning::testing

#pragma once
// Ray-cast ground truth (Embree): which map vertices an agent sees, with their 4-way labels; the exact
// visibility polygon; and depth scans that include clutter.  Queries are const and safe from many threads.
#include <limits>
#include <memory>
#include <vector>

#include "core/detection.h"
#include "core/world.h"

namespace toponav::sim {

struct VisibleVertex {
  core::VertexRef ref;      // which map vertex (ring, index)
  core::Vec2 position;      // world position
  double range = 0.0;       // distance from the agent
  double bearing = 0.0;     // relative to the agent's heading, in [-pi, pi)
  core::VertexLabel label = core::VertexLabel::kPoint;
};

class RayCaster {
 public:
  // Builds the scene once: map walls, clutter, and for open worlds an invisible far box that closes the
  // visibility polygon.  Throws core::InternalError if Embree fails.
  explicit RayCaster(const core::World& world);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Map vertices visible from 'pose' (walls occlude, clutter does not: the camera looks over it), strictly
  // closer than 'max_range', sorted by ascending bearing and labelled from their angular neighbours
  // (vertexnav.md §3.1).  A pose inside an obstacle sees that obstacle's vertices.
  std::vector<VisibleVertex> VisibleVertices(const core::Pose2& pose,
                                             double max_range = std::numeric_limits<double>::infinity()) const;

  // The region of the polygon map visible from 'p' (walls only, unlimited range), counter-clockwise.  Its
  // points are map vertices and exact (double precision) intersections of rays through vertices with walls.
  // Empty if 'p' is outside the map.
  core::Ring VisibilityPolygon(const core::Vec2& p) const;

  // 'num_rays' distances, ray j along bearing core::ColumnToBearing(j, num_rays) from the heading; walls and
  // (if 'include_clutter') clutter block rays; misses read 'max_range'.
  std::vector<double> DepthScan(const core::Pose2& pose, int num_rays, double max_range,
                                bool include_clutter = true) const;

  // Distance to the first wall (or clutter) hit along 'angle' (world frame); 'max_range' on a miss.
  double CastRay(const core::Vec2& origin, double angle, double max_range, bool include_clutter = true) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::sim

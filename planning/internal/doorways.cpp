#include "planning/internal/doorways.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace toponav::planning {

using core::Vec2;

namespace {

// How far along the wall from pa toward pb the foot of p's perpendicular lies (world units; outside [0,
// length] where it falls past an end).
double Along(const mapping::MapWall& wall, const Vec2& p) {
  const Vec2 d = wall.pb - wall.pa;
  const double length = core::Distance(wall.pa, wall.pb);
  return ((p - wall.pa).x * d.x + (p - wall.pa).y * d.y) / length;
}

}  // namespace

std::vector<Doorway> DoorwayHypotheses(const mapping::MapView& view, double tolerance, double min_width,
                                       double max_width) {
  std::vector<Doorway> out;
  for (size_t w = 0; w < view.walls.size(); ++w) {
    const auto& wall = view.walls[w];
    const Vec2 d = wall.pb - wall.pa;
    const double length = core::Distance(wall.pa, wall.pb);
    if (length < min_width) continue;
    // (position along the wall, what marks it there)
    enum Mark { kEnd, kCorner, kRejected };
    std::vector<std::pair<double, Mark>> marks{{0.0, kEnd}, {length, kEnd}};
    // p marks the wall where it lies within 'tolerance' of it and more than 'margin' from its ends.
    const auto mark = [&](const Vec2& p, Mark m, double margin) {
      const double t = Along(wall, p);
      if (t > margin && t < length - margin && core::DistanceToSegment(p, {wall.pa, wall.pb}) <= tolerance)
        marks.push_back({t, m});
    };
    for (const auto& v : view.rejected) mark(v.position, kRejected, 0.0);
    // Corners: the map's own vertices (not the ends of walls a policy added), away from the wall's ends.
    for (const auto& v : view.vertices)
      if (v.id != wall.a && v.id != wall.b && v.num_detections > 0) mark(v.position, kCorner, tolerance);
    std::sort(marks.begin(), marks.end());
    for (size_t i = 0; i + 1 < marks.size(); ++i) {
      const Mark m0 = marks[i].second, m1 = marks[i + 1].second;
      const bool jambs = m0 == kRejected || m1 == kRejected || (m0 == kCorner && m1 == kCorner);
      const double width = marks[i + 1].first - marks[i].first;
      if (!jambs || width < min_width || width > max_width) continue;
      out.push_back({wall.pa + d * (marks[i].first / length), wall.pa + d * (marks[i + 1].first / length), int(w)});
    }
  }
  return out;
}

std::vector<Doorway> OpeningsNear(const mapping::MapView& view, size_t num_walls, const Vec2& at, double reach,
                                  double width) {
  std::vector<Doorway> out;
  for (size_t w = 0; w < std::min(num_walls, view.walls.size()); ++w) {
    const auto& wall = view.walls[w];
    const double length = core::Distance(wall.pa, wall.pb);
    if (length <= 0 || core::DistanceToSegment(at, {wall.pa, wall.pb}) > reach) continue;
    const Vec2 u = (wall.pb - wall.pa) * (1.0 / length);
    const double half = std::min(width, length) / 2;
    const double t = std::clamp(Along(wall, at), half, length - half);
    out.push_back({wall.pa + u * (t - half), wall.pa + u * (t + half), int(w)});
  }
  return out;
}

std::optional<Doorway> Anchored(const mapping::MapView& view, size_t num_walls, const Doorway& doorway,
                                double tolerance) {
  for (size_t w = 0; w < std::min(num_walls, view.walls.size()); ++w) {
    const auto& wall = view.walls[w];
    const Vec2 pa = wall.pa, pb = wall.pb;
    const double length = core::Distance(pa, pb);
    if (length <= 0 || core::DistanceToSegment(doorway.a, {pa, pb}) > tolerance ||
        core::DistanceToSegment(doorway.b, {pa, pb}) > tolerance)
      continue;
    const Vec2 u = (pb - pa) * (1.0 / length);
    const double ta = std::clamp(Along(wall, doorway.a), 0.0, length);
    const double tb = std::clamp(Along(wall, doorway.b), 0.0, length);
    return Doorway{pa + u * std::min(ta, tb), pa + u * std::max(ta, tb), int(w)};
  }
  return std::nullopt;
}

mapping::MapView WithDoorway(const mapping::MapView& view, const Doorway& doorway) {
  mapping::MapView v = view;
  const mapping::MapWall wall = v.walls.at(size_t(doorway.wall));
  v.walls.erase(v.walls.begin() + doorway.wall);
  int next_id = INT_MIN / 2;  // ids no map vertex has
  for (const auto& x : v.vertices) next_id = std::max(next_id, x.id);
  const int ja = next_id + 1, jb = next_id + 2;
  v.vertices.push_back({ja, doorway.a, {}, 0});
  v.vertices.push_back({jb, doorway.b, {}, 0});
  if (core::Distance(wall.pa, doorway.a) > 1e-6)
    v.walls.push_back({wall.a, ja, wall.pa, doorway.a, wall.probability, wall.certain});
  if (core::Distance(doorway.b, wall.pb) > 1e-6)
    v.walls.push_back({jb, wall.b, doorway.b, wall.pb, wall.probability, wall.certain});
  return v;
}

}  // namespace toponav::planning

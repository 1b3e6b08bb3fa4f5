#include "planning/internal/straight_vertices.h"

#include <cmath>
#include <map>

#include "planning/navigation.h"

namespace toponav::planning {

using core::Vec2;

std::map<int, std::vector<Vec2>> WallEnds(const mapping::MapView& view) {
  std::map<int, std::vector<Vec2>> ends;
  for (const auto& w : view.walls) {
    ends[w.a].push_back(w.pb);
    ends[w.b].push_back(w.pa);
  }
  return ends;
}

std::vector<InspectionSite> StraightVertices(const mapping::MapView& view, double max_bend, double standoff) {
  const std::map<int, std::vector<Vec2>> ends = WallEnds(view);
  std::vector<InspectionSite> out;
  for (const auto& v : view.vertices) {
    const auto it = ends.find(v.id);
    if (it == ends.end() || it->second.size() != 2) continue;
    const Vec2 d0 = it->second[0] - v.position, d1 = it->second[1] - v.position;
    const double angle = std::abs(std::atan2(core::Cross(d0, d1), core::Dot(d0, d1)));  // pi: straight on
    if (core::kPi - angle > max_bend) continue;
    const Vec2 along = it->second[1] - it->second[0];
    const double length = std::hypot(along.x, along.y);
    if (length <= 0) continue;
    const Vec2 normal{-along.y / length, along.x / length};
    InspectionSite s{v.id, v.position, {}};
    for (const double side : {1.0, -1.0}) {
      const Vec2 p = v.position + normal * (side * standoff);
      if (InKnown(view, p)) s.lookouts.push_back(p);
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace toponav::planning

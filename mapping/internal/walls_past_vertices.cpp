#include "mapping/internal/walls_past_vertices.h"

namespace toponav::mapping::internal {

namespace {

// True if a map vertex b joined to 'a' by a map wall (other than a-c) lies within 'tolerance' of the inside
// of segment a-c, more than twice that short of c (nearer, b and c are one corner's two detections).
bool PassesNeighbour(const MapCore& m, const MapState& ms, int a, int c, double tolerance) {
  const core::Segment2 ac{m.Pos(a), m.Pos(c)};
  for (int b : m.walls.Neighbours(a)) {
    if (b == c || !ms.mapped[size_t(b)] || !ms.HasWall(a, b)) continue;
    if (core::NearSegmentInterior(m.Pos(b), ac, tolerance) && core::Distance(m.Pos(b), ac.b) > 2 * tolerance)
      return true;
  }
  return false;
}

}  // namespace

MapState WithoutWallsPastVertices(const MapCore& m, const MapState& ms, double tolerance) {
  MapState out = ms;
  out.walls.clear();  // refilled below; the few walls left out also leave wall_keys
  for (const auto& w : ms.walls) {
    if (PassesNeighbour(m, ms, w.first, w.second, tolerance) || PassesNeighbour(m, ms, w.second, w.first, tolerance))
      out.wall_keys.erase(WallKey(w.first, w.second));
    else
      out.walls.push_back(w);
  }
  return out;
}

}  // namespace toponav::mapping::internal

#include "mapping/internal/walls_past_vertices.h"

#include <cmath>

namespace toponav::mapping::internal {

using core::Vec2;

namespace {

// True if a map vertex b joined to 'a' by a map wall (other than a-c) lies within 'tolerance' of the inside
// of segment a-c, more than twice that short of c (nearer, b and c are one corner's two detections).
bool PassesNeighbour(const MapCore& m, const MapState& ms, int a, int c, double tolerance) {
  const Vec2 pa = m.Pos(a), d = m.Pos(c) - pa;
  const double len2 = core::Dot(d, d);
  if (len2 < 1e-12) return false;
  for (int b : m.walls.Neighbours(a)) {
    if (b == c || !ms.mapped[size_t(b)] || !ms.HasWall(a, b)) continue;
    const Vec2 ab = m.Pos(b) - pa;
    const double t = core::Dot(ab, d) / len2;
    if (t > 0 && t < 1 && std::abs(core::Cross(d, ab)) / std::sqrt(len2) < tolerance &&
        core::Distance(m.Pos(b), m.Pos(c)) > 2 * tolerance)
      return true;
  }
  return false;
}

}  // namespace

MapState WithoutWallsPastVertices(const MapCore& m, const MapState& ms, double tolerance) {
  MapState out = ms;
  out.walls.clear();
  out.wall_keys.clear();
  for (const auto& w : ms.walls) {
    if (PassesNeighbour(m, ms, w.first, w.second, tolerance) || PassesNeighbour(m, ms, w.second, w.first, tolerance))
      continue;
    out.walls.push_back(w);
    out.wall_keys.insert(WallKey(w.first, w.second));
  }
  return out;
}

}  // namespace toponav::mapping::internal

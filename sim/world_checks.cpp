// ValidateWorld: everything the later stages (ray casting, Box2D motion, rendering, path grids, the map)
// rely on, checked once when a world is read or built, so a world that passes never aborts them.
#include <cmath>
#include <string>

#include "core/error.h"
#include "sim/world_io.h"

namespace toponav::sim {

using core::DataError;
using core::Ring;
using core::Vec2;
using core::World;

namespace {

std::string Name(int i) { return i < 0 ? std::string("boundary") : "obstacles[" + std::to_string(i) + "]"; }

std::string Where(const Vec2& p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

// Finite and within kMaxCoordinate of the origin.
void CheckPoint(const Vec2& p, const std::string& where, const std::string& source) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw DataError(source, where + ": not a finite number");
  if (std::abs(p.x) > kMaxCoordinate || std::abs(p.y) > kMaxCoordinate)
    throw DataError(source, where + ": coordinate " + Where(p) + " is farther than " + std::to_string(kMaxCoordinate) +
                                " from the origin");
}

// At least 3 points, each within range, consecutive ones at least kMinVertexSpacing apart, no angle sharper
// than kMinVertexAngle, simple.
void CheckRing(const Ring& ring, const std::string& where, const std::string& source) {
  if (ring.size() < 3) throw DataError(source, where + ": a polygon needs at least 3 points");
  for (size_t i = 0; i < ring.size(); ++i) CheckPoint(ring[i], where + "[" + std::to_string(i) + "]", source);
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 &a = ring[(i + n - 1) % n], &b = ring[i], &c = ring[(i + 1) % n];
    if (core::Distance(b, c) < kMinVertexSpacing)
      throw DataError(source, where + "[" + std::to_string(i) + "]: closer than " + std::to_string(kMinVertexSpacing) +
                                  " to the next point");
    const Vec2 u = a - b, v = c - b;
    const double angle = std::abs(std::atan2(core::Cross(u, v), core::Dot(u, v)));
    if (angle < kMinVertexAngle)
      throw DataError(source, where + "[" + std::to_string(i) + "]: the polygon's angle there is sharper than " +
                                  std::to_string(kMinVertexAngle) + " rad (a sliver)");
  }
  if (!core::IsSimple(ring)) throw DataError(source, where + ": polygon is self-intersecting or degenerate");
}

bool Touches(const Ring& a, const Ring& b) {
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t k = 0; k < b.size(); ++k)
      if (core::SegmentsIntersect({a[i], a[(i + 1) % a.size()]}, {b[k], b[(k + 1) % b.size()]})) return true;
  return false;
}

// Rings must not cross, touch or nest (obstacles inside the boundary, not inside each other).
void CheckLayout(const World& w, const std::string& source) {
  for (size_t i = 0; i < w.obstacles.size(); ++i) {
    const Ring& o = w.obstacles[i];
    if (w.has_boundary() && (Touches(o, w.boundary) || !core::Contains(w.boundary, o[0])))
      throw DataError(source, Name(int(i)) + ": must lie inside the boundary without touching it");
    for (size_t k = i + 1; k < w.obstacles.size(); ++k)
      if (Touches(o, w.obstacles[k]) || core::Contains(o, w.obstacles[k][0]) || core::Contains(w.obstacles[k], o[0]))
        throw DataError(source, Name(int(i)) + " and " + Name(int(k)) + " overlap or touch");
  }
}

// The bounds are the search region and the extent of every grid: they hold the whole map, the start and the
// goal, and are at most kMaxWorldSize across.
void CheckBounds(const World& w, const std::string& source) {
  CheckPoint(w.bounds.min, "bounds.min", source);
  CheckPoint(w.bounds.max, "bounds.max", source);
  if (!(w.bounds.max.x > w.bounds.min.x && w.bounds.max.y > w.bounds.min.y))
    throw DataError(source, "bounds: max must exceed min");
  if (w.bounds.width() > kMaxWorldSize || w.bounds.height() > kMaxWorldSize)
    throw DataError(source, "bounds: " + std::to_string(w.bounds.width()) + " x " + std::to_string(w.bounds.height()) +
                                " is larger than " + std::to_string(kMaxWorldSize) + " across");
  for (const Vec2& p : core::MapVertices(w))
    if (!w.bounds.Contains(p)) throw DataError(source, "bounds: the map point " + Where(p) + " lies outside them");
}

void CheckPlaces(const World& w, const std::string& source) {
  CheckPoint(w.start.position(), "start", source);
  if (!std::isfinite(w.start.yaw)) throw DataError(source, "start.yaw: not a finite number");
  CheckPoint(w.goal, "goal", source);
  if (!w.bounds.Contains(w.start.position()))
    throw DataError(source, "start " + Where(w.start.position()) + " is outside the bounds");
  if (!w.bounds.Contains(w.goal)) throw DataError(source, "goal " + Where(w.goal) + " is outside the bounds");
  if (!core::IsFree(w, w.start.position(), true))
    throw DataError(source, "start " + Where(w.start.position()) + " is not in free space");
  if (!core::IsFree(w, w.goal, false)) throw DataError(source, "goal " + Where(w.goal) + " is not in free space");
  for (size_t i = 0; i < w.clutter.size(); ++i) {
    const auto& c = w.clutter[i];
    const std::string where = "clutter[" + std::to_string(i) + "]";
    CheckPoint(c.center, where + ".center", source);
    if (!(c.size >= kMinVertexSpacing && c.size <= kMaxClutterSize))
      throw DataError(source, where + ".size: must be in [" + std::to_string(kMinVertexSpacing) + ", " +
                                  std::to_string(kMaxClutterSize) + "]");
    if (!std::isfinite(c.yaw) || !(c.height > 0 && c.height < kMaxClutterSize))
      throw DataError(source,
                      where + ": yaw must be finite and height in (0, " + std::to_string(kMaxClutterSize) + ")");
    if (!core::IsFree(w, c.center, false))
      throw DataError(source, where + ".center " + Where(c.center) + " is not in free space");
  }
  for (size_t i = 0; i < w.guide_path.size(); ++i)
    CheckPoint(w.guide_path[i], "guide_path[" + std::to_string(i) + "]", source);
  if (!std::isfinite(w.guide_path_width) || w.guide_path_width < 0 || w.guide_path_width > kMaxClutterSize)
    throw DataError(source, "guide_path_width: must be in [0, " + std::to_string(kMaxClutterSize) + "]");
}

}  // namespace

void ValidateWorld(const World& w, const std::string& source) {
  if (w.has_boundary()) CheckRing(w.boundary, "boundary", source);
  for (size_t i = 0; i < w.obstacles.size(); ++i) CheckRing(w.obstacles[i], Name(int(i)), source);
  if (!w.has_boundary() && w.obstacles.empty()) throw DataError(source, "the world has no boundary and no obstacles");
  CheckLayout(w, source);
  CheckBounds(w, source);
  CheckPlaces(w, source);
}

}  // namespace toponav::sim

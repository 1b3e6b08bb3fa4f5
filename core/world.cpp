#include "core/world.h"

#include <algorithm>
#include <limits>

namespace toponav::core {

const char* ToString(WorldKind kind) {
  switch (kind) {
    case WorldKind::kLabyrinth: return "labyrinth";
    case WorldKind::kOfficePark: return "office_park";
    case WorldKind::kGuidedMaze: return "guided_maze";
    case WorldKind::kCustom: return "custom";
  }
  return "?";
}

std::optional<WorldKind> ParseWorldKind(const std::string& t) {
  for (WorldKind k : {WorldKind::kLabyrinth, WorldKind::kOfficePark, WorldKind::kGuidedMaze, WorldKind::kCustom})
    if (t == ToString(k)) return k;
  return std::nullopt;
}

const char* ToString(ClutterShape shape) {
  switch (shape) {
    case ClutterShape::kBox: return "box";
    case ClutterShape::kCylinder: return "cylinder";
    case ClutterShape::kTree: return "tree";
  }
  return "?";
}

std::optional<ClutterShape> ParseClutterShape(const std::string& t) {
  for (ClutterShape s : {ClutterShape::kBox, ClutterShape::kCylinder, ClutterShape::kTree})
    if (t == ToString(s)) return s;
  return std::nullopt;
}

std::vector<const Ring*> MapRings(const World& world) {
  std::vector<const Ring*> rings;
  if (world.has_boundary()) rings.push_back(&world.boundary);
  for (const auto& o : world.obstacles) rings.push_back(&o);
  return rings;
}

std::vector<Vec2> MapVertices(const World& world) {
  std::vector<Vec2> v;
  for (const Ring* r : MapRings(world)) v.insert(v.end(), r->begin(), r->end());
  return v;
}

std::vector<Segment2> MapWalls(const World& world) {
  std::vector<Segment2> walls;
  for (const Ring* r : MapRings(world))
    for (size_t i = 0; i < r->size(); ++i) walls.push_back({(*r)[i], (*r)[(i + 1) % r->size()]});
  return walls;
}

namespace {
double ClutterSignedDistance(const Clutter& c, const Vec2& p) {
  if (c.shape != ClutterShape::kBox) return Distance(p, c.center) - c.size;
  const Vec2 q = Rotate(p - c.center, -c.yaw);
  const double dx = std::abs(q.x) - c.size, dy = std::abs(q.y) - c.size;
  const double outside = Norm({std::max(dx, 0.0), std::max(dy, 0.0)});
  return outside + std::min(std::max(dx, dy), 0.0);
}
}  // namespace

bool IsFree(const World& world, const Vec2& p, bool include_clutter) {
  if (world.has_boundary() && !Contains(world.boundary, p)) return false;
  if (!world.has_boundary() && !world.bounds.Contains(p)) return false;
  for (const auto& o : world.obstacles)
    if (Contains(o, p)) return false;
  if (include_clutter)
    for (const auto& c : world.clutter)
      if (ClutterSignedDistance(c, p) < 0) return false;
  return true;
}

double SignedDistance(const World& world, const Vec2& p, bool include_clutter) {
  double d = std::numeric_limits<double>::infinity();
  bool inside_obstacle = world.has_boundary() && !Contains(world.boundary, p);
  for (const Ring* r : MapRings(world)) d = std::min(d, DistanceToRing(p, *r));
  for (const auto& o : world.obstacles) inside_obstacle = inside_obstacle || Contains(o, p);
  if (inside_obstacle) return -d;
  if (include_clutter)
    for (const auto& c : world.clutter) d = std::min(d, ClutterSignedDistance(c, p));
  return d;
}

Polygon FreeSpacePolygon(const World& world) {
  Polygon poly;
  if (world.has_boundary()) {
    poly.outer = world.boundary;
  } else {
    const Aabb2& b = world.bounds;
    poly.outer = {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
  }
  for (auto h : world.obstacles) {
    Reverse(h);
    poly.holes.push_back(std::move(h));
  }
  return poly;
}

}  // namespace toponav::core

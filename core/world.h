#pragma once
// A world: the true polygonal map (obstacle rings: their vertices and walls), clutter that blocks motion and
// sensing but is not part of the polygon map, the region of interest, start and goal, and an optional guiding path.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry.h"

namespace toponav::core {

enum class WorldKind { kLabyrinth, kOfficePark, kGuidedMaze, kCustom };
const char* ToString(WorldKind kind);
std::optional<WorldKind> ParseWorldKind(const std::string& text);  // "labyrinth", "office_park", ...

enum class ClutterShape { kBox, kCylinder, kTree };
const char* ToString(ClutterShape shape);
std::optional<ClutterShape> ParseClutterShape(const std::string& text);

// A free-standing object.  Box: 'size' is the half side length, rotated by 'yaw'.  Cylinder and tree:
// 'size' is the radius of the part that blocks motion and rays (a tree's trunk plus a margin).
struct Clutter {
  ClutterShape shape = ClutterShape::kBox;
  Vec2 center;
  double size = 1.0;
  double yaw = 0.0;
  double height = 2.25;
  // Radius of a circle that contains the object's footprint.
  double BoundingRadius() const { return shape == ClutterShape::kBox ? size * std::sqrt(2.0) : size; }
};

struct World {
  WorldKind kind = WorldKind::kCustom;
  uint64_t seed = 0;
  // Indoor worlds: the outer wall, counter-clockwise, free space inside.  Empty for open worlds.
  Ring boundary;
  // Obstacles (walls around pillars, buildings), counter-clockwise, obstacle inside.
  std::vector<Ring> obstacles;
  std::vector<Clutter> clutter;
  // The region of interest: the whole map for indoor worlds, the search area for the office park.
  Aabb2 bounds;
  Pose2 start;
  Vec2 goal;
  // Polyline drawn on the floor (guided maze); empty if the world has none.
  std::vector<Vec2> guide_path;
  double guide_path_width = 0.0;

  bool has_boundary() const { return !boundary.empty(); }
};

// Identifies one map vertex: ring 0 is the boundary when the world has one, then the obstacles in order.
struct VertexRef {
  int ring = 0;
  int index = 0;
};

// All rings of the polygon map in VertexRef order (boundary first if present).
std::vector<const Ring*> MapRings(const World& world);
std::vector<Vec2> MapVertices(const World& world);
std::vector<Segment2> MapWalls(const World& world);

// True if p is in free space: inside the boundary (if any), outside every obstacle and every clutter item.
bool IsFree(const World& world, const Vec2& p, bool include_clutter = true);
// Distance to the nearest wall or clutter item: positive in free space, negative inside an obstacle.
double SignedDistance(const World& world, const Vec2& p, bool include_clutter = true);
// True free space as polygons (map walls only, no clutter): the boundary with obstacles as holes, or for
// open worlds the bounds rectangle minus obstacles (obstacles must lie inside the bounds).
Polygon FreeSpacePolygon(const World& world);

}  // namespace toponav::core

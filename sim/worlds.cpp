#include "sim/worlds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/rng.h"
#include "sim/internal/grid_polygon.h"
#include "sim/internal/labyrinth_rooms.h"

namespace toponav::sim {

using core::Aabb2;
using core::Clutter;
using core::ClutterShape;
using core::kPi;
using core::Ring;
using core::Rng;
using core::Vec2;
using core::World;

namespace {

// Shifts every coordinate of the world by 'offset'.
void Translate(World& w, const Vec2& offset) {
  for (auto& p : w.boundary) p = p + offset;
  for (auto& r : w.obstacles)
    for (auto& p : r) p = p + offset;
  for (auto& c : w.clutter) c.center = c.center + offset;
  for (auto& p : w.guide_path) p = p + offset;
  w.bounds.min = w.bounds.min + offset;
  w.bounds.max = w.bounds.max + offset;
  w.start.x += offset.x;
  w.start.y += offset.y;
  w.goal = w.goal + offset;
}

// Rejection-samples a point of the bounds with SignedDistance in [lo, hi] (clutter included).
bool SamplePoint(const World& w, Rng& rng, double lo, double hi, int tries, Vec2* out) {
  for (int i = 0; i < tries; ++i) {
    const Vec2 p{rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
    if (!core::IsFree(w, p)) continue;
    const double d = core::SignedDistance(w, p);
    if (d >= lo && d <= hi) {
      *out = p;
      return true;
    }
  }
  return false;
}

// Start anywhere with enough clearance; goal the farthest of several such samples.
void PlaceStartAndGoal(World& w, Rng& rng, double clearance) {
  Vec2 start;
  TOPONAV_CHECK(SamplePoint(w, rng, clearance, 1e9, 200000, &start), "no start pose with clearance " << clearance);
  w.start = {start.x, start.y, rng.Uniform(-kPi, kPi)};
  double best = -1;
  for (int i = 0; i < 50; ++i) {
    Vec2 g;
    if (SamplePoint(w, rng, clearance, 1e9, 20000, &g) && core::Distance(g, start) > best) {
      best = core::Distance(g, start);
      w.goal = g;
    }
  }
  TOPONAV_CHECK(best >= 0, "no goal with clearance " << clearance);
}

// ---------------------------------------------------------------- labyrinth

using internal::GridRoom;
using internal::RoomGap;

bool ValidLabyrinthGrid(const LabyrinthOptions& o, const std::vector<char>& g) {
  const int n = o.grid_cells;
  auto at = [&](int x, int y) { return g[size_t(y) * n + x] != 0; };
  for (int y = 0; y < n; ++y) {  // straight runs
    int run_x = 0, run_y = 0;
    for (int x = 0; x < n; ++x) {
      run_x = at(x, y) ? run_x + 1 : 0;
      run_y = at(y, x) ? run_y + 1 : 0;
      if (run_x > o.max_straight_run_cells || run_y > o.max_straight_run_cells) return false;
    }
  }
  for (int y = 0; y + 1 < n; ++y)  // 2x2 blocks whose only free cells are diagonal
    for (int x = 0; x + 1 < n; ++x) {
      const bool a = at(x, y), b = at(x + 1, y), c = at(x, y + 1), d = at(x + 1, y + 1);
      if ((a && d && !b && !c) || (b && c && !a && !d)) return false;
    }
  return internal::CountComponents(n, n, g) == 1;
}

// The rooms, drawn all at once; empty when any two come within room_separation_cells (the set is redrawn).
std::vector<GridRoom> DrawRooms(const LabyrinthOptions& o, Rng& rng) {
  const int n = o.grid_cells;
  std::vector<GridRoom> rooms;
  for (int i = 0; i < o.num_rooms; ++i) {
    GridRoom r{0, 0, rng.UniformInt(o.room_min_cells - 1, o.room_max_cells - 1),
               rng.UniformInt(o.room_min_cells - 1, o.room_max_cells - 1)};
    r.x0 = rng.UniformInt(0, n - 1 - r.w);
    r.y0 = rng.UniformInt(0, n - 1 - r.h);
    rooms.push_back(r);
  }
  for (size_t i = 0; i < rooms.size(); ++i)
    for (size_t j = i + 1; j < rooms.size(); ++j)
      if (RoomGap(rooms[i], rooms[j]) <= o.room_separation_cells) return {};
  return rooms;
}

// Which rooms a corridor joins: one of four connection patterns (vertexnav.md §5.2), generalised to any room
// count k >= 2.
std::vector<std::pair<int, int>> DrawLinks(int k, Rng& rng) {
  std::vector<std::pair<int, int>> links;
  const int pattern = k >= 4 ? rng.UniformInt(0, 3) : 2;
  if (pattern == 0) {
    links = {{0, 1}, {1, 2}, {2, 0}};
    for (int i = 3; i < k; ++i) links.push_back({i, rng.UniformInt(0, i - 1)});
  } else if (pattern == 1) {
    for (int i = 0; i < k; ++i) links.push_back({i, (i + 1) % k});
  } else if (pattern == 2) {
    for (int i = 0; i + 1 < k; ++i) links.push_back({i, i + 1});
  } else {
    for (int i = 0; i + 1 < k; ++i) {
      links.push_back({i, i + 1});
      if (i % 2 == 0) links.push_back({i, i + 1});
    }
  }
  return links;
}

// Carves an L-shaped corridor between interior cells (not on a room's edge) of each linked pair of rooms into
// the n x n grid 'g'; false when two such cells lie farther apart than max_corridor_offset_cells in x or y.
bool CarveCorridors(const LabyrinthOptions& o, const std::vector<GridRoom>& rooms,
                    const std::vector<std::pair<int, int>>& links, Rng& rng, std::vector<char>* g) {
  const int n = o.grid_cells;
  for (const auto& [i, j] : links) {
    const GridRoom& a = rooms[size_t(i)];
    const GridRoom& b = rooms[size_t(j)];
    const int ax = rng.UniformInt(a.x0 + 1, a.x0 + a.w - 1), ay = rng.UniformInt(a.y0 + 1, a.y0 + a.h - 1);
    const int bx = rng.UniformInt(b.x0 + 1, b.x0 + b.w - 1), by = rng.UniformInt(b.y0 + 1, b.y0 + b.h - 1);
    if (std::abs(ax - bx) > o.max_corridor_offset_cells || std::abs(ay - by) > o.max_corridor_offset_cells)
      return false;
    const bool x_first = rng.Bernoulli(0.5);
    int x = ax, y = ay;
    auto carve = [&]() { (*g)[size_t(y) * n + x] = 1; };
    for (int leg = 0; leg < 2; ++leg) {
      if ((leg == 0) == x_first)
        while (x != bx) { x += bx > x ? 1 : -1; carve(); }
      else
        while (y != by) { y += by > y ? 1 : -1; carve(); }
    }
  }
  return true;
}

std::vector<char> LabyrinthGrid(const LabyrinthOptions& o, Rng& rng) {
  const int n = o.grid_cells;
  for (int attempt = 0; attempt < 100000; ++attempt) {
    const std::vector<GridRoom> rooms = DrawRooms(o, rng);
    if (rooms.empty()) continue;
    const std::vector<std::pair<int, int>> links = DrawLinks(o.num_rooms, rng);
    std::vector<char> g(size_t(n) * n, 0);
    for (const auto& r : rooms)
      for (int y = r.y0; y <= r.y0 + r.h; ++y)
        for (int x = r.x0; x <= r.x0 + r.w; ++x) g[size_t(y) * n + x] = 1;
    if (CarveCorridors(o, rooms, links, rng, &g) && ValidLabyrinthGrid(o, g)) return g;
  }
  throw core::InternalError("labyrinth: no valid layout after 100000 attempts (check the options)");
}

void AddWallClutter(World& w, const LabyrinthOptions& o, Rng& rng) {
  for (int i = 0, tries = 0; i < o.num_clutter && tries < 200000; ++tries) {
    Clutter c;
    c.shape = i % 2 == 0 ? ClutterShape::kBox : ClutterShape::kCylinder;
    c.size = c.shape == ClutterShape::kBox ? o.box_half_size : o.cylinder_radius;
    c.height = o.clutter_height;
    c.yaw = c.shape == ClutterShape::kBox ? rng.Uniform(0.0, kPi / 2) : 0.0;
    const double r = c.BoundingRadius();
    const Vec2 p{rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
    if (!core::IsFree(w, p, false)) continue;
    const double wall_gap = core::SignedDistance(w, p, false) - r;
    if (wall_gap < 0.1 || wall_gap > o.clutter_max_wall_gap) continue;
    bool apart = true;  // keep objects from touching each other
    for (const auto& other : w.clutter)
      apart = apart && core::Distance(other.center, p) > r + other.BoundingRadius() + 0.5;
    if (!apart) continue;
    c.center = p;
    w.clutter.push_back(c);
    ++i;
  }
}

// ---------------------------------------------------------------- office park

Ring Footprint(int type, double sx, double sy, double yaw, const Vec2& center) {
  Ring base;
  if (type == 0) {  // E1: 21x21 square with a 7x7 notch (L-shape)
    base = {{-10.5, -10.5}, {10.5, -10.5}, {10.5, 3.5}, {3.5, 3.5}, {3.5, 10.5}, {-10.5, 10.5}};
  } else if (type == 1) {  // E5: 14x7 rectangle
    base = {{-7, -3.5}, {7, -3.5}, {7, 3.5}, {-7, 3.5}};
  } else {  // A1: 28.2 square
    base = {{-14.1, -14.1}, {14.1, -14.1}, {14.1, 14.1}, {-14.1, 14.1}};
  }
  Ring out;
  for (const auto& p : base) out.push_back(center + core::Rotate({p.x * sx, p.y * sy}, yaw));
  return out;
}

double NearestBuilding(const std::vector<Ring>& buildings, const Vec2& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& b : buildings) d = std::min(d, core::Contains(b, p) ? 0.0 : core::DistanceToRing(p, b));
  return d;
}

std::vector<Ring> PlaceBuildings(const OfficeParkOptions& o, Rng& rng) {
  auto candidate = [&]() {
    const int type = rng.UniformInt(0, 2);
    const double factor = type == 2 ? 0.5 : (type == 1 ? 1.5 : 1.0);
    const Vec2 c{rng.Uniform(-20.0, 280.0), rng.Uniform(-150.0, 150.0)};
    const double sx = rng.Uniform(o.scale_min, o.scale_max) * factor;
    const double sy_draw = rng.Uniform(o.scale_min, o.scale_max) * factor;
    const double sy = type == 2 ? sx : sy_draw;  // the square footprint stays square
    return Footprint(type, sx, sy, rng.Uniform(0.0, 2 * kPi), c);
  };
  for (int attempt = 0; attempt < 1000; ++attempt) {
    std::vector<Ring> buildings{candidate()};
    for (int round = 0; round < 20 && int(buildings.size()) < o.num_buildings; ++round) {
      double best_score = std::numeric_limits<double>::infinity();
      Ring best;
      for (int i = 0; i < o.candidates_per_round; ++i) {
        Ring r = candidate();
        std::vector<double> d;
        for (const auto& b : buildings) d.push_back(core::RingDistance(r, b));
        std::sort(d.begin(), d.end());
        if (!(d[0] > o.min_building_gap && d[0] < o.max_building_gap)) continue;
        const size_t k = std::min<size_t>(3, d.size());
        double mean = 0;
        for (size_t j = 0; j < k; ++j) mean += d[j] / double(k);
        if (mean < best_score) {
          best_score = mean;
          best = std::move(r);
        }
      }
      if (!best.empty()) buildings.push_back(std::move(best));
    }
    if (int(buildings.size()) == o.num_buildings) return buildings;
  }
  throw core::InternalError("office park: could not place the buildings (check the options)");
}

}  // namespace

World GenerateLabyrinth(const LabyrinthOptions& o, uint64_t seed) {
  Rng rng(seed);
  const std::vector<char> coarse = LabyrinthGrid(o, rng);
  const int n = o.grid_cells;
  // Free space = union of the free cells, each grown by d on every side (a mitre buffer of the cell union),
  // so corridors one cell wide are exactly hall_width wide.  Growing splits each grid line k*s into k*s-d and
  // k*s+d; a refined cell is free if any grown free cell covers it.
  const double s = o.hall_width / (1.0 + o.inflate_ratio);
  const double d = s * o.inflate_ratio / 2.0;
  std::vector<double> lines;
  for (int k = 0; k <= n; ++k) {
    lines.push_back(k * s - d);
    lines.push_back(k * s + d);
  }
  const int nr = int(lines.size()) - 1;  // refined interval t: even -> thin strip at line t/2, odd -> cell t/2
  auto coarse_of = [&](int t, int* lo, int* hi) {
    if (t % 2 == 1) *lo = *hi = t / 2;
    else { *lo = t / 2 - 1; *hi = t / 2; }
  };
  std::vector<char> fine(size_t(nr) * nr, 0);
  for (int ty = 0; ty < nr; ++ty)
    for (int tx = 0; tx < nr; ++tx) {
      int x0, x1, y0, y1;
      coarse_of(tx, &x0, &x1);
      coarse_of(ty, &y0, &y1);
      bool f = false;
      for (int cy = y0; cy <= y1 && !f; ++cy)
        for (int cx = x0; cx <= x1 && !f; ++cx)
          f = cx >= 0 && cy >= 0 && cx < n && cy < n && coarse[size_t(cy) * n + cx];
      fine[size_t(ty) * nr + tx] = f;
    }
  if (o.inflate_ratio == 0) {  // degenerate zero-width strips: use the coarse grid itself
    lines.clear();
    for (int k = 0; k <= n; ++k) lines.push_back(k * s);
    fine = coarse;
  }
  World w;
  w.kind = core::WorldKind::kLabyrinth;
  w.seed = seed;
  TOPONAV_CHECK(internal::SplitBoundaryAndObstacles(internal::TraceFreeRegion(lines, lines, fine), &w.boundary,
                                                    &w.obstacles),
                "labyrinth free space is not connected");
  w.bounds = core::Bounds(w.boundary);
  Translate(w, (w.bounds.min + w.bounds.max) * -0.5);
  AddWallClutter(w, o, rng);
  PlaceStartAndGoal(w, rng, o.start_clearance);
  return w;
}

World GenerateOfficePark(const OfficeParkOptions& o, uint64_t seed) {
  Rng rng(seed);
  World w;
  w.kind = core::WorldKind::kOfficePark;
  w.seed = seed;
  w.obstacles = PlaceBuildings(o, rng);
  const double inf = std::numeric_limits<double>::infinity();
  Aabb2 b{{inf, inf}, {-inf, -inf}};
  for (const auto& r : w.obstacles) b = core::Bounds(r, b);
  b.min = b.min - Vec2{o.bounds_margin, o.bounds_margin};
  b.max = b.max + Vec2{o.bounds_margin, o.bounds_margin};
  w.bounds = b;
  Translate(w, (b.min + b.max) * -0.5);
  for (int i = 0, tries = 0; i < o.num_trees && tries < 200000; ++tries) {
    const Vec2 p{rng.Uniform(w.bounds.min.x + o.tree_radius, w.bounds.max.x - o.tree_radius),
                 rng.Uniform(w.bounds.min.y + o.tree_radius, w.bounds.max.y - o.tree_radius)};
    const double gap = NearestBuilding(w.obstacles, p) - o.tree_radius;
    if (gap < o.tree_min_gap || gap > o.tree_max_gap) continue;
    bool clear = true;
    for (const auto& c : w.clutter) clear = clear && core::Distance(c.center, p) > c.size + o.tree_radius + 2.0;
    if (!clear) continue;
    w.clutter.push_back({ClutterShape::kTree, p, o.tree_radius, 0.0, rng.Uniform(12.0, 20.0)});
    ++i;
  }
  bool placed = false;
  for (int tries = 0; tries < 200000 && !placed; ++tries) {
    const Vec2 p{rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
    const double gap = NearestBuilding(w.obstacles, p);
    if (gap < o.start_min_gap || gap > o.start_max_gap || core::SignedDistance(w, p) < o.start_min_gap) continue;
    w.start = {p.x, p.y, rng.Uniform(-kPi, kPi)};
    placed = true;
  }
  TOPONAV_CHECK(placed, "office park: no start pose");
  // The goal: the farthest from the start of 50 free samples that keep the start's clearance from
  // buildings, trees and the region's edge.
  double best = -1;
  for (int i = 0, tries = 0; i < 50 && tries < 200000; ++tries) {
    const double m = o.start_min_gap;
    const Vec2 p{rng.Uniform(w.bounds.min.x + m, w.bounds.max.x - m),
                 rng.Uniform(w.bounds.min.y + m, w.bounds.max.y - m)};
    if (!core::IsFree(w, p) || core::SignedDistance(w, p) < m) continue;
    ++i;
    if (core::Distance(p, w.start.position()) > best) {
      best = core::Distance(p, w.start.position());
      w.goal = p;
    }
  }
  TOPONAV_CHECK(best >= 0, "office park: no goal");
  return w;
}

namespace {

using MazeTree = std::vector<std::vector<int>>;  // per cell (y * nx + x): the cells it opens onto

// Randomized Kruskal over all walls between adjacent cells of an nx x ny grid: a spanning tree.
MazeTree KruskalMaze(int nx, int ny, Rng& rng) {
  auto id = [&](int x, int y) { return y * nx + x; };
  std::vector<std::array<int, 2>> walls;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      if (x + 1 < nx) walls.push_back({id(x, y), id(x + 1, y)});
      if (y + 1 < ny) walls.push_back({id(x, y), id(x, y + 1)});
    }
  rng.Shuffle(walls);
  std::vector<int> parent(size_t(nx * ny));
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
  auto find = [&](int a) {
    while (parent[size_t(a)] != a) a = parent[size_t(a)] = parent[size_t(parent[size_t(a)])];
    return a;
  };
  MazeTree adj(size_t(nx * ny));
  for (const auto& wl : walls) {
    const int a = find(wl[0]), b = find(wl[1]);
    if (a == b) continue;
    parent[size_t(a)] = b;
    adj[size_t(wl[0])].push_back(wl[1]);
    adj[size_t(wl[1])].push_back(wl[0]);
  }
  return adj;
}

// The unique tree route start -> goal (BFS parents).
std::vector<int> TreeRoute(const MazeTree& adj, int start, int goal) {
  std::vector<int> from(adj.size(), -1);
  std::vector<int> queue{start};
  from[size_t(start)] = start;
  for (size_t q = 0; q < queue.size(); ++q)
    for (int nb : adj[size_t(queue[q])])
      if (from[size_t(nb)] < 0) {
        from[size_t(nb)] = queue[q];
        queue.push_back(nb);
      }
  std::vector<int> route{goal};
  while (route.back() != start) route.push_back(from[size_t(route.back())]);
  std::reverse(route.begin(), route.end());
  return route;
}

// Refined grid lines along one axis: border | cell | wall | cell | ... | cell | border.
std::vector<double> MazeLines(const GuidedMazeOptions& o, int cells) {
  const double pitch = o.corridor_width + o.wall_thickness;
  std::vector<double> l{0.0};
  for (int i = 0; i < cells; ++i) {
    l.push_back(o.border + i * pitch);
    l.push_back(o.border + i * pitch + o.corridor_width);
  }
  l.push_back(l.back() + o.border);
  return l;
}

// Free tiles of the refined grid (fx x fy tiles between the lines): every cell, and the wall tiles the tree
// opens.
std::vector<char> MazeTiles(const MazeTree& adj, int nx, int fx, int fy) {
  auto id = [&](int x, int y) { return y * nx + x; };
  auto connected = [&](int a, int b) {
    return std::find(adj[size_t(a)].begin(), adj[size_t(a)].end(), b) != adj[size_t(a)].end();
  };
  std::vector<char> fine(size_t(fx) * fy, 0);
  for (int ty = 1; ty < fy - 1; ++ty)
    for (int tx = 1; tx < fx - 1; ++tx) {
      const bool cell_x = tx % 2 == 1, cell_y = ty % 2 == 1;
      const int cx = (tx - 1) / 2, cy = (ty - 1) / 2;
      bool f = false;
      if (cell_x && cell_y) f = true;
      else if (!cell_x && cell_y) f = connected(id(cx, cy), id(cx + 1, cy));
      else if (cell_x && !cell_y) f = connected(id(cx, cy), id(cx, cy + 1));
      fine[size_t(ty) * fx + tx] = f;
    }
  return fine;
}

}  // namespace

World GenerateGuidedMaze(const GuidedMazeOptions& o, uint64_t seed) {
  Rng rng(seed);
  const int nx = o.cells_x, ny = o.cells_y;
  const MazeTree adj = KruskalMaze(nx, ny, rng);
  const int start = rng.UniformInt(0, nx * ny - 1);
  int goal = rng.UniformInt(0, nx * ny - 2);
  if (goal >= start) ++goal;
  const std::vector<double> xs = MazeLines(o, nx), ys = MazeLines(o, ny);
  const int fx = int(xs.size()) - 1, fy = int(ys.size()) - 1;
  World w;
  w.kind = core::WorldKind::kGuidedMaze;
  w.seed = seed;
  TOPONAV_CHECK(internal::SplitBoundaryAndObstacles(internal::TraceFreeRegion(xs, ys, MazeTiles(adj, nx, fx, fy)),
                                                    &w.boundary, &w.obstacles),
                "maze free space is not connected");
  w.bounds = core::Bounds(w.boundary);  // the free space's extent (as in the labyrinth), not the outer border's
  const double pitch = o.corridor_width + o.wall_thickness;
  auto center = [&](int c) {
    const int x = c % nx, y = c / nx;
    return Vec2{o.border + x * pitch + o.corridor_width / 2, o.border + y * pitch + o.corridor_width / 2};
  };
  for (int c : TreeRoute(adj, start, goal)) w.guide_path.push_back(center(c));
  w.guide_path_width = o.guide_path_width;
  const Vec2 s = center(start);
  w.start = {s.x, s.y, rng.Uniform(-kPi, kPi)};
  w.goal = center(goal);
  Translate(w, (w.bounds.min + w.bounds.max) * -0.5);
  return w;
}

World GenerateWorld(core::WorldKind kind, const WorldOptions& options, uint64_t seed) {
  switch (kind) {
    case core::WorldKind::kLabyrinth: return GenerateLabyrinth(options.labyrinth, seed);
    case core::WorldKind::kOfficePark: return GenerateOfficePark(options.office_park, seed);
    case core::WorldKind::kGuidedMaze: return GenerateGuidedMaze(options.guided_maze, seed);
    case core::WorldKind::kCustom: break;
  }
  throw core::ConfigError("<command line>", "kind", "custom", "custom worlds are read from files (--world FILE)");
}

}  // namespace toponav::sim

namespace toponav::sim::internal {

double RoomGap(const GridRoom& a, const GridRoom& b) {
  const double gx = std::max({0.0, double(b.x0 - (a.x0 + a.w)), double(a.x0 - (b.x0 + b.w))});
  const double gy = std::max({0.0, double(b.y0 - (a.y0 + a.h)), double(a.y0 - (b.y0 + b.h))});
  return gx + gy;
}

}  // namespace toponav::sim::internal

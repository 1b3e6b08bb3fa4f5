#include "sim/internal/scene.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/rng.h"

namespace toponav::sim::internal {

using core::Vec2;

namespace {

struct Color {
  float r, g, b;
};

class SceneBuilder {
 public:
  explicit SceneBuilder(Scene* s) : s_(s) {}

  // Groups everything added since the last call into one object with a ground-plane bounding circle.
  void EndObject(bool always = false) {
    SceneObject o;
    o.first = s_->objects.empty() ? 0 : s_->objects.back().first + s_->objects.back().count;
    o.count = uint32_t(s_->vertices.size()) - o.first;
    if (o.count == 0) return;
    double minx = 1e300, miny = 1e300, maxx = -1e300, maxy = -1e300;
    for (uint32_t i = o.first; i < o.first + o.count; ++i) {
      minx = std::min(minx, double(s_->vertices[i].pos[0]));
      maxx = std::max(maxx, double(s_->vertices[i].pos[0]));
      miny = std::min(miny, double(s_->vertices[i].pos[1]));
      maxy = std::max(maxy, double(s_->vertices[i].pos[1]));
    }
    o.cx = float((minx + maxx) / 2);
    o.cy = float((miny + maxy) / 2);
    o.radius = always ? -1.f : float(std::hypot(maxx - minx, maxy - miny) / 2 + 1e-3);
    s_->objects.push_back(o);
  }

  // A quad p0..p3 (counter-clockwise seen from the front) with per-corner uv.
  void Quad(const float p[4][3], const float n[3], Color c, const float uv[4][2], Pattern pattern, float length,
            int32_t id) {
    static const int tri[6] = {0, 1, 2, 0, 2, 3};
    for (int k : tri) {
      SceneVertex v{};
      for (int a = 0; a < 3; ++a) {
        v.pos[a] = p[k][a];
        v.normal[a] = n[a];
      }
      v.color[0] = c.r;
      v.color[1] = c.g;
      v.color[2] = c.b;
      v.uv[0] = uv[k][0];
      v.uv[1] = uv[k][1];
      v.material[0] = float(pattern);
      v.material[1] = length;
      v.id = id;
      s_->vertices.push_back(v);
    }
  }

  // A vertical wall over segment a->b facing 'normal' (2D), from z0 to z1.
  void Wall(Vec2 a, Vec2 b, Vec2 normal, double z0, double z1, Color c, Pattern pattern, int32_t id,
            bool corner_shading = true) {
    const float len = float(core::Distance(a, b));
    const float p[4][3] = {{float(a.x), float(a.y), float(z0)},
                           {float(b.x), float(b.y), float(z0)},
                           {float(b.x), float(b.y), float(z1)},
                           {float(a.x), float(a.y), float(z1)}};
    const float n[3] = {float(normal.x), float(normal.y), 0.f};
    const float uv[4][2] = {{0.f, float(z0)}, {len, float(z0)}, {len, float(z1)}, {0.f, float(z1)}};
    Quad(p, n, c, uv, pattern, corner_shading ? len : 0.f, id);
  }

  // A horizontal rectangle at height z, facing up (or down).
  void Flat(const core::Aabb2& r, double z, bool up, Color c, Pattern pattern, int32_t id) {
    const float x0 = float(r.min.x), y0 = float(r.min.y), x1 = float(r.max.x), y1 = float(r.max.y), zf = float(z);
    const float n[3] = {0.f, 0.f, up ? 1.f : -1.f};
    if (up) {
      const float p[4][3] = {{x0, y0, zf}, {x1, y0, zf}, {x1, y1, zf}, {x0, y1, zf}};
      const float uv[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
      Quad(p, n, c, uv, pattern, 0.f, id);
    } else {
      const float p[4][3] = {{x0, y0, zf}, {x0, y1, zf}, {x1, y1, zf}, {x1, y0, zf}};
      const float uv[4][2] = {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
      Quad(p, n, c, uv, pattern, 0.f, id);
    }
  }

  // A horizontal convex polygon (triangle fan) at height z facing up.
  void FanUp(const std::vector<Vec2>& pts, double z, Color c, Pattern pattern, int32_t id) {
    for (size_t i = 1; i + 1 < pts.size(); ++i) {
      for (const Vec2& q : {pts[0], pts[i], pts[i + 1]}) {
        SceneVertex v{};
        v.pos[0] = float(q.x);
        v.pos[1] = float(q.y);
        v.pos[2] = float(z);
        v.normal[2] = 1.f;
        v.color[0] = c.r;
        v.color[1] = c.g;
        v.color[2] = c.b;
        v.uv[0] = float(q.x);
        v.uv[1] = float(q.y);
        v.material[0] = float(pattern);
        v.id = id;
        s_->vertices.push_back(v);
      }
    }
  }

  // A closed prism over a counter-clockwise footprint.
  void Prism(const core::Ring& ring, double z0, double z1, Color c, Pattern pattern, int32_t id, bool top) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const Vec2 d = (b - a) / core::Distance(a, b);
      Wall(a, b, {d.y, -d.x}, z0, z1, c, pattern, id, false);
    }
    if (top) FanUp(ring, z1, {c.r * 0.9f, c.g * 0.9f, c.b * 0.9f}, kPlain, id);
  }

  // A rough sphere (latitude-longitude) for tree canopies.
  void Blob(Vec2 centre, double z, double radius, double squash, Color c, int32_t id) {
    const int slices = 8, stacks = 5;
    auto point = [&](int i, int j) {
      const double phi = core::kPi * j / stacks - core::kPi / 2, th = 2 * core::kPi * i / slices;
      return std::array<double, 3>{centre.x + radius * std::cos(phi) * std::cos(th),
                                   centre.y + radius * std::cos(phi) * std::sin(th),
                                   z + squash * radius * std::sin(phi)};
    };
    for (int j = 0; j < stacks; ++j)
      for (int i = 0; i < slices; ++i) {
        const auto a = point(i, j), b = point(i + 1, j), cc = point(i + 1, j + 1), d = point(i, j + 1);
        const float p[4][3] = {{float(a[0]), float(a[1]), float(a[2])},
                               {float(b[0]), float(b[1]), float(b[2])},
                               {float(cc[0]), float(cc[1]), float(cc[2])},
                               {float(d[0]), float(d[1]), float(d[2])}};
        const double phi = core::kPi * (j + 0.5) / stacks - core::kPi / 2, th = 2 * core::kPi * (i + 0.5) / slices;
        const float n[3] = {float(std::cos(phi) * std::cos(th)), float(std::cos(phi) * std::sin(th)),
                            float(std::sin(phi))};
        const float uv[4][2] = {
            {float(i), float(j)}, {float(i + 1), float(j)}, {float(i + 1), float(j + 1)}, {float(i), float(j + 1)}};
        Quad(p, n, c, uv, kLeaves, 0.f, id);
      }
  }

 private:
  Scene* s_;
};

core::Ring Circle(Vec2 c, double r, int sides) {
  core::Ring ring;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * core::kPi * k / sides;
    ring.push_back(c + Vec2{r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

Color Jitter(core::Rng& rng, Color c, float amount) {
  auto j = [&](float v) { return std::clamp(v + float(rng.Uniform(-amount, amount)), 0.f, 1.f); };
  return {j(c.r), j(c.g), j(c.b)};
}

// Floor (and for open worlds a ground plane out to the horizon) and ceiling.
void AddFlats(const core::World& world, const RenderOptions& o, core::Rng& rng, SceneBuilder& fb) {
  const bool indoor = world.has_boundary();
  const core::Aabb2& b = world.bounds;
  const double grow = indoor ? 5.0 : 3000.0;
  const core::Aabb2 floor{{b.min.x - grow, b.min.y - grow}, {b.max.x + grow, b.max.y + grow}};
  if (world.kind == core::WorldKind::kOfficePark || !indoor) {
    fb.Flat(floor, 0.0, true, Jitter(rng, {0.36f, 0.55f, 0.26f}, 0.05f), kGrass, kNoObstacle);
  } else if (world.kind == core::WorldKind::kGuidedMaze) {
    fb.Flat(floor, 0.0, true, Jitter(rng, {0.72f, 0.68f, 0.62f}, 0.04f), kTiles, kNoObstacle);
  } else {
    fb.Flat(floor, 0.0, true, Jitter(rng, {0.55f, 0.5f, 0.45f}, 0.1f), kTiles, kNoObstacle);
  }
  if (indoor) fb.Flat(floor, o.wall_height, false, Jitter(rng, {0.85f, 0.85f, 0.82f}, 0.05f), kCeiling, kNoObstacle);
}

// The map's walls: buildings' facades in the office park, painted walls indoors; one object a wall.
void AddMapWalls(const core::World& world, const RenderOptions& o, core::Rng& rng, SceneBuilder& sb) {
  static const Color kIndoorPalette[] = {{0.80f, 0.78f, 0.72f}, {0.62f, 0.70f, 0.78f}, {0.78f, 0.64f, 0.56f},
                                         {0.70f, 0.76f, 0.62f}, {0.86f, 0.84f, 0.80f}, {0.60f, 0.58f, 0.66f}};
  static const Color kFacadePalette[] = {{0.72f, 0.70f, 0.66f}, {0.55f, 0.42f, 0.36f}, {0.62f, 0.66f, 0.72f},
                                         {0.82f, 0.78f, 0.66f}, {0.45f, 0.47f, 0.50f}};
  const bool indoor = world.has_boundary();
  const auto rings = core::MapRings(world);
  for (size_t r = 0; r < rings.size(); ++r) {
    const core::Ring& ring = *rings[r];
    const bool boundary = indoor && r == 0;
    const bool building = world.kind == core::WorldKind::kOfficePark && !boundary;
    const double height = building ? rng.Uniform(30.0, 60.0) : o.wall_height;
    const Color building_color = Jitter(rng, kFacadePalette[rng.UniformInt(0, 4)], 0.05f);
    for (size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], c = ring[(i + 1) % ring.size()];
      const Vec2 d = (c - a) / core::Distance(a, c);
      const Vec2 n = boundary ? Vec2{-d.y, d.x} : Vec2{d.y, -d.x};  // towards free space
      Color color;
      Pattern pattern;
      if (building) {
        color = building_color;
        pattern = kWindows;
      } else {
        color = Jitter(rng, kIndoorPalette[rng.UniformInt(0, 5)], 0.06f);
        if (rng.Bernoulli(o.plain_wall_fraction)) pattern = kPlain;
        else pattern = static_cast<Pattern>(rng.UniformInt(kPanels, kStripes));
      }
      sb.Wall(a, c, n, 0.0, height, color, pattern, WallId(int(r), int(i)));
      sb.EndObject();
    }
  }
}

// Clutter: boxes, cylinders, trees; one object each.
void AddClutter(const core::World& world, core::Rng& rng, SceneBuilder& sb) {
  for (size_t i = 0; i < world.clutter.size(); ++i) {
    const core::Clutter& c = world.clutter[i];
    const int32_t id = ClutterId(int(i));
    if (c.shape == core::ClutterShape::kBox) {
      core::Ring ring;
      for (const Vec2 k : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}})
        ring.push_back(c.center + core::Rotate(k * c.size, c.yaw));
      sb.Prism(ring, 0.0, c.height, Jitter(rng, {0.55f, 0.38f, 0.22f}, 0.08f), kPanels, id, true);
    } else if (c.shape == core::ClutterShape::kCylinder) {
      sb.Prism(Circle(c.center, c.size, 20), 0.0, c.height, Jitter(rng, {0.25f, 0.45f, 0.70f}, 0.08f), kPlain, id,
               true);
    } else {
      sb.Prism(Circle(c.center, c.size, 12), 0.0, c.height * 0.55, Jitter(rng, {0.40f, 0.28f, 0.18f}, 0.05f), kBark,
               id, false);
      sb.Blob(c.center, c.height * 0.7, c.size * 3.2, 0.9, Jitter(rng, {0.22f, 0.48f, 0.20f}, 0.06f), id);
    }
    sb.EndObject();
  }
}

// The guiding path: green strips on the floor along the route.
void AddGuidePath(const core::World& world, SceneBuilder& sb) {
  if (world.guide_path.size() < 2) return;
  const Color green{0.16f, 0.78f, 0.22f};
  const double half = world.guide_path_width / 2, z = 0.05;
  for (size_t i = 0; i + 1 < world.guide_path.size(); ++i) {
    const Vec2 a = world.guide_path[i], c = world.guide_path[i + 1];
    const core::Aabb2 box{{std::min(a.x, c.x) - half, std::min(a.y, c.y) - half},
                          {std::max(a.x, c.x) + half, std::max(a.y, c.y) + half}};
    if (a.x == c.x || a.y == c.y) {
      sb.Flat(box, z, true, green, kPlain, kNoObstacle);
    } else {  // diagonal segments (hand-written worlds): a rotated strip
      const Vec2 d = (c - a) / core::Distance(a, c), n{-d.y * half, d.x * half};
      sb.FanUp({a - n, c - n, c + n, a + n}, z, green, kPlain, kNoObstacle);
    }
    sb.EndObject();
  }
}

}  // namespace

Scene BuildScene(const core::World& world, const RenderOptions& o) {
  Scene scene;
  SceneBuilder sb(&scene);
  core::Rng rng(core::DeriveSeed(world.seed, 0x52454e44));  // the scene's own stream: same seed, same look
  // Floor and ceiling go into the vertex list last: drawn after the walls, most of their pixels fail the depth
  // test before shading.  The random draws keep this order: flats, walls, clutter.
  Scene flats;
  SceneBuilder fb(&flats);
  AddFlats(world, o, rng, fb);
  AddMapWalls(world, o, rng, sb);
  AddClutter(world, rng, sb);
  AddGuidePath(world, sb);
  scene.vertices.insert(scene.vertices.end(), flats.vertices.begin(), flats.vertices.end());
  sb.EndObject(/*always=*/true);
  return scene;
}

}  // namespace toponav::sim::internal

#include "sim/world_io.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"

namespace toponav::sim {

using core::DataError;
using core::Ring;
using core::Vec2;
using core::World;
using nlohmann::json;

namespace {

json PointJson(const Vec2& p) { return json::array({p.x, p.y}); }

json RingJson(const Ring& r) {
  json a = json::array();
  for (const auto& p : r) a.push_back(PointJson(p));
  return a;
}

// Reads with a path-like context ("obstacles[2][5]") for error messages.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void Fail(const std::string& where, const std::string& problem) const {
    throw DataError(source_, where + ": " + problem);
  }
  const json& Key(const json& obj, const std::string& key, const std::string& where) const {
    if (!obj.is_object()) Fail(where, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) Fail(where.empty() ? key : where + "." + key, "missing key");
    return *it;
  }
  double Number(const json& v, const std::string& where) const {
    if (!v.is_number()) Fail(where, "expected a number, got " + std::string(v.type_name()));
    const double d = v.get<double>();
    if (!std::isfinite(d)) Fail(where, "not a finite number");
    return d;
  }
  Vec2 Point(const json& v, const std::string& where) const {
    if (!v.is_array() || v.size() != 2) Fail(where, "expected a point [x, y]");
    return {Number(v[0], where + "[0]"), Number(v[1], where + "[1]")};
  }
  Ring RingOf(const json& v, const std::string& where) const {
    if (!v.is_array()) Fail(where, "expected a list of points");
    Ring r;
    for (size_t i = 0; i < v.size(); ++i) r.push_back(Point(v[i], where + "[" + std::to_string(i) + "]"));
    return r;
  }

 private:
  std::string source_;
};

}  // namespace

std::string WorldToJson(const World& w) {
  json j;
  j["format"] = "toponav-world-1";
  j["kind"] = core::ToString(w.kind);
  j["seed"] = w.seed;
  j["boundary"] = RingJson(w.boundary);
  j["obstacles"] = json::array();
  for (const auto& o : w.obstacles) j["obstacles"].push_back(RingJson(o));
  j["clutter"] = json::array();
  for (const auto& c : w.clutter)
    j["clutter"].push_back({{"shape", core::ToString(c.shape)}, {"center", PointJson(c.center)}, {"size", c.size},
                            {"yaw", c.yaw}, {"height", c.height}});
  j["bounds"] = {{"min", PointJson(w.bounds.min)}, {"max", PointJson(w.bounds.max)}};
  j["start"] = {{"x", w.start.x}, {"y", w.start.y}, {"yaw", w.start.yaw}};
  j["goal"] = PointJson(w.goal);
  j["guide_path"] = RingJson(w.guide_path);
  j["guide_path_width"] = w.guide_path_width;
  return j.dump(1) + "\n";
}

World WorldFromJson(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw DataError(source, std::string("not valid JSON: ") + e.what());
  }
  Reader r(source);
  if (!j.is_object()) r.Fail("<top level>", "expected an object");
  static const char* kKeys[] = {"format", "kind", "seed", "boundary", "obstacles", "clutter", "bounds",
                                "start", "goal", "guide_path", "guide_path_width"};
  for (const auto& item : j.items()) {
    bool known = false;
    for (const char* k : kKeys) known = known || item.key() == k;
    if (!known) r.Fail(item.key(), "unknown key");
  }
  World w;
  if (j.contains("kind")) {
    const json& k = j["kind"];
    if (!k.is_string() || !core::ParseWorldKind(k.get<std::string>()))
      r.Fail("kind", "expected one of labyrinth, office_park, guided_maze, custom");
    w.kind = *core::ParseWorldKind(k.get<std::string>());
  }
  if (j.contains("seed")) {
    if (!j["seed"].is_number_unsigned()) r.Fail("seed", "expected a non-negative integer");
    w.seed = j["seed"].get<uint64_t>();
  }
  if (j.contains("boundary")) w.boundary = r.RingOf(j["boundary"], "boundary");
  const json& obstacles = r.Key(j, "obstacles", "");
  if (!obstacles.is_array()) r.Fail("obstacles", "expected a list of polygons");
  for (size_t i = 0; i < obstacles.size(); ++i)
    w.obstacles.push_back(r.RingOf(obstacles[i], "obstacles[" + std::to_string(i) + "]"));
  if (j.contains("clutter")) {
    const json& cl = j["clutter"];
    if (!cl.is_array()) r.Fail("clutter", "expected a list");
    for (size_t i = 0; i < cl.size(); ++i) {
      const std::string where = "clutter[" + std::to_string(i) + "]";
      core::Clutter c;
      const json& shape = r.Key(cl[i], "shape", where);
      if (!shape.is_string() || !core::ParseClutterShape(shape.get<std::string>()))
        r.Fail(where + ".shape", "expected box, cylinder or tree");
      c.shape = *core::ParseClutterShape(shape.get<std::string>());
      c.center = r.Point(r.Key(cl[i], "center", where), where + ".center");
      c.size = r.Number(r.Key(cl[i], "size", where), where + ".size");
      if (cl[i].contains("yaw")) c.yaw = r.Number(cl[i]["yaw"], where + ".yaw");
      if (cl[i].contains("height")) c.height = r.Number(cl[i]["height"], where + ".height");
      if (c.size <= 0) r.Fail(where + ".size", "must be > 0");
      w.clutter.push_back(c);
    }
  }
  const json& start = r.Key(j, "start", "");
  w.start = {r.Number(r.Key(start, "x", "start"), "start.x"), r.Number(r.Key(start, "y", "start"), "start.y"),
             start.contains("yaw") ? r.Number(start["yaw"], "start.yaw") : 0.0};
  w.goal = r.Point(r.Key(j, "goal", ""), "goal");
  if (j.contains("guide_path")) w.guide_path = r.RingOf(j["guide_path"], "guide_path");
  if (j.contains("guide_path_width")) w.guide_path_width = r.Number(j["guide_path_width"], "guide_path_width");
  if (j.contains("bounds")) {
    w.bounds = {r.Point(r.Key(j["bounds"], "min", "bounds"), "bounds.min"),
                r.Point(r.Key(j["bounds"], "max", "bounds"), "bounds.max")};
  } else {  // default: everything the map touches, grown by 10 units
    w.bounds = core::Bounds(core::MapVertices(w), core::Bounds(std::vector<Vec2>{w.start.position(), w.goal}));
    w.bounds.min = w.bounds.min - Vec2{10, 10};
    w.bounds.max = w.bounds.max + Vec2{10, 10};
  }
  // Hand-written files may use either orientation: normalise to counter-clockwise.
  if (!w.boundary.empty() && core::SignedArea(w.boundary) < 0) core::Reverse(w.boundary);
  for (auto& o : w.obstacles)
    if (core::SignedArea(o) < 0) core::Reverse(o);
  ValidateWorld(w, source);
  return w;
}

void ValidateWorld(const World& w, const std::string& source) {
  auto check_ring = [&](const Ring& ring, const std::string& where) {
    if (ring.size() < 3) throw DataError(source, where + ": a polygon needs at least 3 points");
    for (const auto& p : ring)
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw DataError(source, where + ": not a finite number");
    if (!core::IsSimple(ring)) throw DataError(source, where + ": polygon is self-intersecting or degenerate");
  };
  if (w.has_boundary()) check_ring(w.boundary, "boundary");
  for (size_t i = 0; i < w.obstacles.size(); ++i) check_ring(w.obstacles[i], "obstacles[" + std::to_string(i) + "]");
  if (!w.has_boundary() && w.obstacles.empty()) throw DataError(source, "the world has no boundary and no obstacles");
  // Rings must not cross, touch or nest (obstacles inside the boundary, not inside each other).
  auto name = [](int i) { return i < 0 ? std::string("boundary") : "obstacles[" + std::to_string(i) + "]"; };
  auto touches = [](const Ring& a, const Ring& b) {
    for (size_t i = 0; i < a.size(); ++i)
      for (size_t k = 0; k < b.size(); ++k)
        if (core::SegmentsIntersect({a[i], a[(i + 1) % a.size()]}, {b[k], b[(k + 1) % b.size()]})) return true;
    return false;
  };
  for (size_t i = 0; i < w.obstacles.size(); ++i) {
    const Ring& o = w.obstacles[i];
    if (w.has_boundary() && (touches(o, w.boundary) || !core::Contains(w.boundary, o[0])))
      throw DataError(source, name(int(i)) + ": must lie inside the boundary without touching it");
    for (size_t k = i + 1; k < w.obstacles.size(); ++k)
      if (touches(o, w.obstacles[k]) || core::Contains(o, w.obstacles[k][0]) || core::Contains(w.obstacles[k], o[0]))
        throw DataError(source, name(int(i)) + " and " + name(int(k)) + " overlap or touch");
  }
  if (!(w.bounds.max.x > w.bounds.min.x && w.bounds.max.y > w.bounds.min.y))
    throw DataError(source, "bounds: max must exceed min");
  if (!core::IsFree(w, w.start.position(), true))
    throw DataError(source, "start (" + std::to_string(w.start.x) + ", " + std::to_string(w.start.y) +
                                ") is not in free space");
}

void SaveWorld(const World& world, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw DataError(path, "cannot open for writing");
  out << WorldToJson(world);
  if (!out) throw DataError(path, "write failed");
}

World LoadWorld(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError(path, "cannot open for reading");
  std::stringstream ss;
  ss << in.rdbuf();
  return WorldFromJson(ss.str(), path);
}

}  // namespace toponav::sim

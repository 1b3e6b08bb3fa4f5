#include "sim/world_io.h"

#include <cmath>
#include <fstream>
#include <initializer_list>
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
  // Rejects keys of the object 'obj' other than 'keys'.
  void OnlyKeys(const json& obj, std::initializer_list<const char*> keys, const std::string& where) const {
    if (!obj.is_object()) Fail(where, "expected an object");
    for (const auto& item : obj.items()) {
      bool known = false;
      for (const char* k : keys) known = known || item.key() == k;
      if (!known) Fail(where.empty() ? item.key() : where + "." + item.key(), "unknown key");
    }
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

namespace {

// The world's "clutter" list.
std::vector<core::Clutter> ClutterFromJson(Reader& r, const json& cl) {
  if (!cl.is_array()) r.Fail("clutter", "expected a list");
  std::vector<core::Clutter> out;
  for (size_t i = 0; i < cl.size(); ++i) {
    const std::string where = "clutter[" + std::to_string(i) + "]";
    r.OnlyKeys(cl[i], {"shape", "center", "size", "yaw", "height"}, where);
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
    out.push_back(c);
  }
  return out;
}

// "bounds" when given; by default everything the map, the start and the goal touch, grown by 10 units.
core::Aabb2 BoundsFromJson(Reader& r, const json& j, const World& w) {
  if (j.contains("bounds")) {
    r.OnlyKeys(j["bounds"], {"min", "max"}, "bounds");
    return {r.Point(r.Key(j["bounds"], "min", "bounds"), "bounds.min"),
            r.Point(r.Key(j["bounds"], "max", "bounds"), "bounds.max")};
  }
  core::Aabb2 b = core::Bounds(core::MapVertices(w), core::Bounds(std::vector<Vec2>{w.start.position(), w.goal}));
  b.min = b.min - Vec2{10, 10};
  b.max = b.max + Vec2{10, 10};
  return b;
}

}  // namespace

World WorldFromJson(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw DataError(source, std::string("not valid JSON: ") + e.what());
  }
  Reader r(source);
  if (!j.is_object()) r.Fail("<top level>", "expected an object");
  r.OnlyKeys(j, {"format", "kind", "seed", "boundary", "obstacles", "clutter", "bounds", "start", "goal", "guide_path",
               "guide_path_width"}, "");
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
  if (j.contains("clutter")) w.clutter = ClutterFromJson(r, j["clutter"]);
  const json& start = r.Key(j, "start", "");
  r.OnlyKeys(start, {"x", "y", "yaw"}, "start");
  w.start = {r.Number(r.Key(start, "x", "start"), "start.x"), r.Number(r.Key(start, "y", "start"), "start.y"),
             start.contains("yaw") ? r.Number(start["yaw"], "start.yaw") : 0.0};
  w.goal = r.Point(r.Key(j, "goal", ""), "goal");
  if (j.contains("guide_path")) w.guide_path = r.RingOf(j["guide_path"], "guide_path");
  if (j.contains("guide_path_width")) w.guide_path_width = r.Number(j["guide_path_width"], "guide_path_width");
  w.bounds = BoundsFromJson(r, j, w);
  // Hand-written files may use either orientation: normalise to counter-clockwise.
  if (!w.boundary.empty() && core::SignedArea(w.boundary) < 0) core::Reverse(w.boundary);
  for (auto& o : w.obstacles)
    if (core::SignedArea(o) < 0) core::Reverse(o);
  ValidateWorld(w, source);
  return w;
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

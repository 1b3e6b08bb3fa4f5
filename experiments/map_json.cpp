#include "experiments/map_json.h"

namespace toponav::experiments {

namespace {

nlohmann::json Point(const core::Vec2& p) { return nlohmann::json::array({p.x, p.y}); }

nlohmann::json Points(const std::vector<core::Vec2>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : points) out.push_back(Point(p));
  return out;
}

nlohmann::json Vertices(const std::vector<mapping::MapVertex>& vertices) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : vertices)
    out.push_back({{"id", v.id},
                   {"x", v.position.x},
                   {"y", v.position.y},
                   {"cov", {v.covariance.xx, v.covariance.xy, v.covariance.yy}},
                   {"detections", v.num_detections}});
  return out;
}

}  // namespace

nlohmann::json MapGeometryJson(const mapping::MapView& view) {
  nlohmann::json walls = nlohmann::json::array(), known = nlohmann::json::array();
  nlohmann::json frontiers = nlohmann::json::array();
  for (const auto& w : view.walls)
    walls.push_back(
        {{"a", w.a}, {"b", w.b}, {"probability", w.probability}, {"from", Point(w.pa)}, {"to", Point(w.pb)}});
  for (const auto& poly : view.known_space) {
    nlohmann::json holes = nlohmann::json::array();
    for (const auto& h : poly.holes) holes.push_back(Points(h));
    known.push_back({{"outer", Points(poly.outer)}, {"holes", holes}});
  }
  for (const auto& f : view.frontiers)
    frontiers.push_back({{"id", f.id}, {"points", Points(f.points)}, {"length", f.length}});
  return {{"vertices", Vertices(view.vertices)},
          {"rejected", Vertices(view.rejected)},
          {"walls", walls},
          {"known_space", known},
          {"frontiers", frontiers}};
}

}  // namespace toponav::experiments

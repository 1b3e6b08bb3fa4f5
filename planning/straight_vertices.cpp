#include "planning/straight_vertices.h"

#include <cmath>
#include <limits>
#include <map>

#include "core/error.h"

namespace toponav::planning {

using core::Vec2;

namespace {

// The far ends of the walls at each vertex id.
std::map<int, std::vector<Vec2>> WallEnds(const mapping::MapView& view) {
  std::map<int, std::vector<Vec2>> ends;
  for (const auto& w : view.walls) {
    ends[w.a].push_back(w.pb);
    ends[w.b].push_back(w.pa);
  }
  return ends;
}

}  // namespace

std::vector<StraightVertex> StraightVertices(const mapping::MapView& view, double max_bend, double standoff) {
  const std::map<int, std::vector<Vec2>> ends = WallEnds(view);
  std::vector<StraightVertex> out;
  for (const auto& v : view.vertices) {
    const auto it = ends.find(v.id);
    if (it == ends.end() || it->second.size() != 2) continue;
    const Vec2 d0 = it->second[0] - v.position, d1 = it->second[1] - v.position;
    const double angle = std::abs(std::atan2(core::Cross(d0, d1), core::Dot(d0, d1)));  // pi: straight on
    if (core::kPi - angle > max_bend) continue;
    const Vec2 along = it->second[1] - it->second[0];
    const double length = std::hypot(along.x, along.y);
    if (length <= 0) continue;
    const Vec2 normal{-along.y / length, along.x / length};
    StraightVertex s{v.id, v.position, {}};
    for (const double side : {1.0, -1.0}) {
      const Vec2 p = v.position + normal * (side * standoff);
      if (InKnown(view, p)) s.lookouts.push_back(p);
    }
    out.push_back(std::move(s));
  }
  return out;
}

StraightVertexInspector::StraightVertexInspector(double max_bend, double standoff, double reach, int looks)
    : max_bend_(max_bend), standoff_(standoff), reach_(reach), looks_(looks) {
  TOPONAV_CHECK(max_bend > 0 && standoff > 0 && reach > 0 && looks >= 1, "straight-vertex inspection: bend "
                    << max_bend << ", standoff " << standoff << ", reach " << reach << ", looks " << looks);
}

bool StraightVertexInspector::Inspected(const Vec2& p) const {
  for (const auto& q : inspected_)
    if (core::Distance(p, q) <= reach_) return true;
  return false;
}

void StraightVertexInspector::GiveUp(int frontier_id) {
  const auto it = offered_.find(frontier_id);
  if (it != offered_.end() && !Inspected(it->second)) inspected_.push_back(it->second);
}

std::vector<FrontierTarget> StraightVertexInspector::Targets(const mapping::MapView& view, const VisibilityGraph& graph,
                                                             const std::vector<Vec2>& agents) {
  std::vector<StraightVertex> open;
  std::vector<Vec2> lookouts;
  for (StraightVertex& s : StraightVertices(view, max_bend_, standoff_))
    if (!Inspected(s.position)) {
      lookouts.insert(lookouts.end(), s.lookouts.begin(), s.lookouts.end());
      open.push_back(std::move(s));
    }
  std::vector<std::vector<Path>> paths;  // per agent, to every lookout in order
  for (const Vec2& agent : agents) paths.push_back(graph.PlanToMany(agent, lookouts));
  std::vector<FrontierTarget> targets;
  offered_.clear();
  size_t first = 0;  // the index of this vertex's first lookout
  for (const StraightVertex& s : open) {
    double best = std::numeric_limits<double>::infinity();
    FrontierTarget t;
    bool near = false;
    for (size_t a = 0; a < agents.size(); ++a)
      for (size_t k = 0; k < s.lookouts.size(); ++k) {
        const Path& path = paths[a][first + k];
        near = near || core::Distance(agents[a], s.lookouts[k]) <= reach_;
        if (path && path.cost < best) best = path.cost, t.point = s.lookouts[k];
      }
    first += s.lookouts.size();
    if ((near && ++looked_[s.id] >= looks_) || !std::isfinite(best)) {
      inspected_.push_back(s.position);
      continue;
    }
    t.frontier_id = kIdBase - s.id;
    t.outward = (s.position - t.point) * (1.0 / standoff_);
    offered_[t.frontier_id] = s.position;
    targeted_.insert(s.id);
    targets.push_back(t);
  }
  return targets;
}

}  // namespace toponav::planning

#include "planning/internal/vertex_inspector.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "planning/internal/unwalled_vertices.h"

namespace toponav::planning {

using core::Vec2;

VertexInspector::VertexInspector(const VertexInspectionOptions& o) : o_(o) {
  TOPONAV_CHECK((o.max_bend > 0 || o.unwalled_detections > 0) && o.max_bend >= 0 && o.unwalled_detections >= 0 &&
                    o.standoff > 0 && o.unwalled_standoff > 0 && o.reach > 0 && o.looks >= 1,
                "vertex inspection: bend " << o.max_bend << ", standoff " << o.standoff << ", unwalled detections "
                                           << o.unwalled_detections << ", unwalled standoff " << o.unwalled_standoff
                                           << ", reach " << o.reach << ", looks " << o.looks);
}

std::vector<InspectionSite> VertexInspector::Sites(const mapping::MapView& view) const {
  std::vector<InspectionSite> sites;
  if (o_.max_bend > 0) sites = StraightVertices(view, o_.max_bend, o_.standoff);
  if (o_.unwalled_detections > 0)
    for (InspectionSite& s : UnwalledVertices(view, o_.unwalled_detections, o_.unwalled_standoff))
      sites.push_back(std::move(s));
  return sites;
}

bool VertexInspector::Inspected(const Vec2& p) const {
  for (const auto& q : inspected_)
    if (core::Distance(p, q) <= o_.reach) return true;
  return false;
}

void VertexInspector::GiveUp(int frontier_id) {
  const auto it = offered_.find(frontier_id);
  if (it != offered_.end() && !Inspected(it->second)) inspected_.push_back(it->second);
}

std::vector<FrontierTarget> VertexInspector::Targets(const mapping::MapView& view, const VisibilityGraph& graph,
                                                     const std::vector<Vec2>& agents, double max_cost) {
  std::vector<InspectionSite> open;
  std::vector<Vec2> lookouts;
  for (InspectionSite& s : Sites(view))
    if (!Inspected(s.position)) {
      lookouts.insert(lookouts.end(), s.lookouts.begin(), s.lookouts.end());
      open.push_back(std::move(s));
    }
  std::vector<std::vector<Path>> paths;  // per agent, to every lookout in order
  for (const Vec2& agent : agents) paths.push_back(graph.PlanToMany(agent, lookouts));
  std::vector<FrontierTarget> targets;
  offered_.clear();
  size_t first = 0;  // the index of this vertex's first lookout
  for (const InspectionSite& s : open) {
    double best = std::numeric_limits<double>::infinity();
    FrontierTarget t;
    bool near = false;
    for (size_t a = 0; a < agents.size(); ++a)
      for (size_t k = 0; k < s.lookouts.size(); ++k) {
        const Path& path = paths[a][first + k];
        near = near || core::Distance(agents[a], s.lookouts[k]) <= o_.reach;
        if (path && path.cost < best) best = path.cost, t.point = s.lookouts[k];
      }
    first += s.lookouts.size();
    if ((near && ++looked_[s.id] >= o_.looks) || !std::isfinite(best) || best > max_cost) {
      inspected_.push_back(s.position);
      continue;
    }
    t.frontier_id = kIdBase - s.id;
    t.outward = (s.position - t.point) * (1.0 / core::Distance(s.position, t.point));
    offered_[t.frontier_id] = s.position;
    targeted_.insert(s.id);
    targets.push_back(t);
  }
  return targets;
}

}  // namespace toponav::planning

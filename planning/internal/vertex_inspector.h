#pragma once
// Before a search ends: agents look from close by at the map vertices that say the map may be wrong -- those
// map walls run straight through (planning/internal/straight_vertices.h: a walled-over doorway's jambs) and those the
// map lacks walls for (planning/internal/unwalled_vertices.h: a hollow building's corners).
#include <limits>
#include <map>
#include <set>
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"
#include "planning/navigation.h"
#include "planning/internal/straight_vertices.h"

namespace toponav::planning {

struct VertexInspectionOptions {
  double max_bend = 0.0;            // > 0: vertices walls run straight through within this bend (radians) ...
  double standoff = 10.0;           // ... looked at from this far (world units)
  int unwalled_detections = 0;      // > 0: vertices the map lacks walls for (rejected ones with at least
                                    // this many detections) ...
  double unwalled_standoff = 14.0;  // ... looked at from this far (world units)
  double reach = 4.0;               // an agent this close to a lookout is looking (world units) ...
  int looks = 6;                    // ... and after this many Targets calls the vertex is inspected
};

class VertexInspector {
 public:
  // Frontier ids of the inspector's targets: kIdBase - the vertex's id.
  static constexpr int kIdBase = -1000;
  static bool IsInspection(int frontier_id) { return frontier_id <= kIdBase; }
  // A vertex counts as inspected once an agent has been within 'reach' of one of its lookouts at 'looks' calls
  // of Targets (one a step: the map's sampler runs every few steps, and what the agent saw must reach the map
  // before the search may end), and stays inspected (a vertex within 'reach' of an inspected one's place).
  explicit VertexInspector(const VertexInspectionOptions& options);
  // One target per vertex not yet inspected, at its lookout nearest (by path) to an agent.  Vertices looked
  // at long enough, and those no agent can get to within 'max_cost' (path length, world units: what the run
  // has left), become inspected.  The budget is checked at every call, so a vertex an agent is still looking
  // at is let go too once its lookout lies beyond the budget (the run's last looks are not started).
  std::vector<FrontierTarget> Targets(const mapping::MapView& view, const VisibilityGraph& graph,
                                      const std::vector<core::Vec2>& agents,
                                      double max_cost = std::numeric_limits<double>::infinity());
  // The vertex of target 'frontier_id' (from the last Targets call) counts as inspected: no agent can get there.
  void GiveUp(int frontier_id);
  int inspected() const { return int(inspected_.size()); }  // vertices done: looked at, given up or out of reach
  int targeted() const { return int(targeted_.size()); }    // vertices ever offered as targets

 private:
  std::vector<InspectionSite> Sites(const mapping::MapView& view) const;
  bool Inspected(const core::Vec2& p) const;
  VertexInspectionOptions o_;
  std::vector<core::Vec2> inspected_;  // where inspected vertices were
  std::map<int, int> looked_;          // vertex id -> calls with an agent within reach of a lookout
  std::map<int, core::Vec2> offered_;  // the last call's targets: frontier id -> vertex position
  std::set<int> targeted_;             // vertex ids ever offered
};

}  // namespace toponav::planning

#pragma once
// Map vertices that map walls pass straight through.  Every vertex of the worlds here is a corner, where
// walls meet at a clear angle; a map vertex with two walls continuing within a small bend of a straight line
// is a detection on a wall's face or -- the case that matters -- the jamb of an opening the map has walled
// over.  Seen from afar, a doorway's jambs can carry labels that say the wall runs on to both sides; the
// map then draws a wall across the doorway and the search ends "explored" with the rooms behind it cut off.
// Before the search ends, the inspector sends an agent to look at each such vertex from close by, where
// the jamb shows its gap and the far side's vertices show through the opening.
#include <map>
#include <set>
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"
#include "planning/navigation.h"

namespace toponav::planning {

struct StraightVertex {
  int id = 0;                       // the map vertex's id
  core::Vec2 position;
  std::vector<core::Vec2> lookouts;  // 'standoff' from it square to its walls, on the known side(s)
};

// The map vertices with exactly two map walls whose directions from the vertex are within 'max_bend'
// (radians) of opposite, with their lookouts (points of known space; none when neither side is known).
std::vector<StraightVertex> StraightVertices(const mapping::MapView& view, double max_bend, double standoff);

class StraightVertexInspector {
 public:
  // Frontier ids of the inspector's targets: kIdBase - the vertex's id.
  static constexpr int kIdBase = -1000;
  static bool IsInspection(int frontier_id) { return frontier_id <= kIdBase; }
  // 'max_bend' and 'standoff' as for StraightVertices; a vertex counts as inspected once an agent has been
  // within 'reach' of one of its lookouts at 'looks' calls of Targets (one a step: the map's sampler runs
  // every few steps, and what the agent saw must reach the map before the search may end), and stays
  // inspected (a vertex within 'reach' of an inspected one's place).
  StraightVertexInspector(double max_bend, double standoff, double reach, int looks);
  // One target per straight vertex not yet inspected, at its lookout nearest (by path) to an agent.  Vertices
  // looked at long enough, and those no agent can get to, become inspected.
  std::vector<FrontierTarget> Targets(const mapping::MapView& view, const VisibilityGraph& graph,
                                      const std::vector<core::Vec2>& agents);
  // The vertex of target 'frontier_id' (from the last Targets call) counts as inspected: no agent can get there.
  void GiveUp(int frontier_id);
  int inspected() const { return int(inspected_.size()); }  // vertices done: looked at, given up or out of reach
  int targeted() const { return int(targeted_.size()); }    // vertices ever offered as targets

 private:
  bool Inspected(const core::Vec2& p) const;
  double max_bend_, standoff_, reach_;
  int looks_;
  std::vector<core::Vec2> inspected_;  // where inspected vertices were
  std::map<int, int> looked_;          // vertex id -> calls with an agent within reach of a lookout
  std::map<int, core::Vec2> offered_;  // the last call's targets: frontier id -> vertex position
  std::set<int> targeted_;             // vertex ids ever offered
};

}  // namespace toponav::planning

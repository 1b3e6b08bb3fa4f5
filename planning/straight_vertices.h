#pragma once
// Map vertices that map walls pass straight through.  Every vertex of the worlds here is a corner, where
// walls meet at a clear angle; a map vertex with two walls continuing within a small bend of a straight line
// is a detection on a wall's face or -- the case that matters -- the jamb of an opening the map has walled
// over.  Seen from afar, a doorway's jambs can carry labels that say the wall runs on to both sides; the
// map then draws a wall across the doorway and the search ends "explored" with the rooms behind it cut off.
// Before the search ends, the inspector sends an agent to look at each such vertex from close by, where
// the jamb shows its gap and the far side's vertices show through the opening.
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
  // 'max_bend' and 'standoff' as for StraightVertices; a vertex counts as inspected once an agent came within
  // 'reach' of one of its lookouts, and stays inspected (a vertex within 'reach' of an inspected one's place).
  StraightVertexInspector(double max_bend, double standoff, double reach);
  // One target per straight vertex not yet inspected, at its lookout nearest (by path) to an agent.  Vertices
  // an agent is within reach of a lookout of, and those no agent can get to, become inspected.
  std::vector<FrontierTarget> Targets(const mapping::MapView& view, const VisibilityGraph& graph,
                                      const std::vector<core::Vec2>& agents);
  int inspected() const { return int(inspected_.size()); }

 private:
  bool Inspected(const core::Vec2& p) const;
  double max_bend_, standoff_, reach_;
  std::vector<core::Vec2> inspected_;  // where inspected vertices were
};

}  // namespace toponav::planning

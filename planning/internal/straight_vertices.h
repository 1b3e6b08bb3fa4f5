#pragma once
// Map vertices that map walls pass straight through.  Every vertex of the worlds here is a corner, where
// walls meet at a clear angle; a map vertex with two walls continuing within a small bend of a straight line
// is a detection on a wall's face or -- the case that matters -- the jamb of an opening the map has walled
// over.  Seen from afar, a doorway's jambs can carry labels that say the wall runs on to both sides; the
// map then draws a wall across the doorway and the search ends "explored" with the rooms behind it cut off.
// Before the search ends, planning::VertexInspector sends an agent to look at each such vertex from close
// by, where the jamb shows its gap and the far side's vertices show through the opening.
#include <map>
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"

namespace toponav::planning {

// A vertex to look at and the points of known space to look from.
struct InspectionSite {
  int id = 0;                       // the vertex's id (a map vertex or a rejected one)
  core::Vec2 position;
  std::vector<core::Vec2> lookouts;
};

// The far ends of the map walls at each map vertex id (vertices without walls have no entry).
std::map<int, std::vector<core::Vec2>> WallEnds(const mapping::MapView& view);

// The map vertices with exactly two map walls whose directions from the vertex are within 'max_bend'
// (radians) of opposite, with their lookouts 'standoff' from the vertex square to its walls, on the known
// side(s) (none when neither side is known).
std::vector<InspectionSite> StraightVertices(const mapping::MapView& view, double max_bend, double standoff);

}  // namespace toponav::planning

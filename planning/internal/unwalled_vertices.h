#pragma once
// Vertices the map lacks walls for.  Every vertex of the worlds here is a corner where two walls meet, so a
// map vertex no map wall reaches, one that a single map wall reaches with known space all round it, or a
// vertex the sensor kept detecting that the posterior leaves out and that lies off every map wall, is a
// corner whose walls the map lacks.  In an open world that is how a hollow building looks: an agent walked
// along one of its sides, saw the sides end on, the corners' labels did not say "wall" and the posterior
// rejected them, or kept one side and not the next; the map then has an open chain of walls there or none,
// known space runs through the building, and the search ends "explored" with the building's inside counted
// as free.  (The end of an open chain with unknown space on its inside is a building whose last side the
// search took for closed: its inside is not counted as free.)  Before the search ends,
// planning::VertexInspector sends an agent to look at each such vertex from outside, where its walls face the
// camera.
#include <vector>

#include "mapping/mapping.h"
#include "planning/internal/straight_vertices.h"

namespace toponav::planning {

// The map vertices no map wall ends at, those one map wall ends at with known space at 14 of 16 points 3
// units round them, and the rejected vertices with at least 'min_detections' detections that lie more than 2
// units off every map wall.  Each is looked at from 'standoff' away, outward: away from the mean of the map
// vertices within 45 units (the rest of its building, in an office park), and 45 degrees either side of
// that; lookouts outside known space are dropped.
std::vector<InspectionSite> UnwalledVertices(const mapping::MapView& view, int min_detections, double standoff);

}  // namespace toponav::planning

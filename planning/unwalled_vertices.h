#pragma once
// Vertices the map has no walls for.  Every vertex of the worlds here is a corner where two walls meet, so a
// map vertex no map wall reaches, or a vertex the sensor kept detecting that the posterior leaves out and that
// lies off every map wall, is a corner whose walls the map lacks.  In an open world that is how a hollow
// building looks: an agent walked along one of its sides, saw the sides end on, the corners' labels did not
// say "wall" and the posterior rejected them; the map then has no walls there, known space runs through the
// building, and the search ends "explored" with the building's inside counted as free.  Before the search
// ends, planning::VertexInspector sends an agent to look at each such vertex from outside, where its walls
// face the camera.
#include <vector>

#include "mapping/mapping.h"
#include "planning/straight_vertices.h"

namespace toponav::planning {

// The map vertices no map wall ends at, and the rejected vertices with at least 'min_detections' detections
// that lie more than 2 units off every map wall.  Each is looked at from 'standoff' away, outward: away from
// the mean of the map vertices within 45 units (the rest of its building, in an office park), and 45
// degrees either side of that; lookouts outside known space are dropped.
std::vector<InspectionSite> UnwalledVertices(const mapping::MapView& view, int min_detections, double standoff);

}  // namespace toponav::planning

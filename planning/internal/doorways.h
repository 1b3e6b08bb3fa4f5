#pragma once
// Doorway hypotheses.  A map wall with two of the posterior's rejected vertices on it an opening's width apart (or
// one and the wall's end or a map corner the wall was drawn past, or two such corners) is often a wall drawn across
// an opening whose jambs were seen only from afar: the map's MCMC flips one or two vertices at a time and cannot
// reach a map that needs the jambs and the corners seen through the opening together.  Where the map seals the goal
// off, planning through such a doorway and driving up to it decides: through an opening the agent sees the far side
// from close by; at a true wall it makes no headway and the hypothesis is dropped.
#include <optional>
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"

namespace toponav::planning {

struct Doorway {
  core::Vec2 a, b;  // the jambs, on one map wall
  int wall = 0;     // index of that wall in the view's walls
  core::Vec2 middle() const { return (a + b) * 0.5; }
};

// Consecutive points along each map wall -- its ends, and the rejected vertices and the other map vertices (with
// detections, more than 'tolerance' from the wall's ends) within 'tolerance' of it (a wall drawn past a corner of
// the map: often the jamb of the opening it covers) -- between 'min_width' and 'max_width' apart, with at least
// one rejected vertex of the two or two such corners.
std::vector<Doorway> DoorwayHypotheses(const mapping::MapView& view, double tolerance, double min_width,
                                       double max_width);

// Openings 'width' wide (or the whole wall where it is shorter) on each of the view's first 'num_walls' walls
// within 'reach' of 'at', centred on the wall's point nearest 'at' as far as the wall's ends allow: where the
// map seals the goal off and the agent stands at the place its recovery leads it to, a wall beside it may be
// one drawn across the way (its evidence from far views, which the near ones do not overturn).
std::vector<Doorway> OpeningsNear(const mapping::MapView& view, size_t num_walls, const core::Vec2& at,
                                  double reach, double width);

// The doorway a-b on the first of the view's first 'num_walls' walls that passes within 'tolerance' of both
// ends, if any: a doorway found on an earlier view, on this one's walls, its ends put on the wall in the
// wall's direction (as WithDoorway needs them).
std::optional<Doorway> Anchored(const mapping::MapView& view, size_t num_walls, const Doorway& doorway,
                                double tolerance);

// The view with the doorway's piece of its wall removed (the jambs become vertices of the two pieces left).
mapping::MapView WithDoorway(const mapping::MapView& view, const Doorway& doorway);

}  // namespace toponav::planning

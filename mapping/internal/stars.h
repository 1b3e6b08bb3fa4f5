#pragma once
// Star polygons of observations: the real one (what its detections show, at the vertices' current
// positions) and the hypothetical one (what the map says it should have shown).
#include <cstdint>
#include <vector>

#include "mapping/internal/map_core.h"

namespace toponav::mapping::internal {

constexpr double kOpenSampleStep = 0.1;  // radians between the rays that trace an open gap's far side

// The star polygon of an observation's real detections at the vertices' current positions; in an open
// region the detections' labels say where sight passes a vertex (no wall on that side).
core::Ring RealStar(const MapCore& m, const Obs& ob);
// Rebuilds observation i's star polygon and box from the vertices' current positions.
void RefreshStar(MapCore* m, size_t i);
// Rebuilds the star polygons whose vertices moved more than 'tolerance'.
void RefreshStars(MapCore* m, double tolerance);

// Open worlds: obstacles are closed polygons, so a chain of map walls that is still open (its last wall not
// seen well enough yet) is closed between its two ends for the sight lines of known space -- otherwise the
// hypothetical observation would see through the building to the chain's far vertices.  Planning and the
// posterior use the map's walls only.  A chain whose closed polygon holds an observation's pose is a recess
// seen from within, not a building, and stays open.  Closed worlds: none.
std::vector<Wall> ClosingWalls(const MapCore& m, const MapState& ms);

// The star polygon of a hypothetical observation H (vertex ids by bearing) from 'ob's pose: in an open region,
// sight passes a mapped vertex on a side where the map has no wall, and rays stop at the map's walls and the
// closing walls.  *hit_walls receives what the polygon was built from (the walls that stopped rays, and each
// vertex's open sides), so a cache can tell whether it must be rebuilt.
core::Ring HypotheticalStar(const MapCore& m, const Obs& ob, const std::vector<int>& H, const MapState& ms,
                            const std::vector<Wall>& closing, std::vector<uint64_t>* hit_walls);

}  // namespace toponav::mapping::internal

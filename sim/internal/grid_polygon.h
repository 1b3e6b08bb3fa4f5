#pragma once
// Boundary rings of the free cells of a rectilinear grid with arbitrary (sorted) line coordinates.
#include <vector>

#include "core/geometry.h"

namespace toponav::sim::internal {

// xs has nx+1 sorted coordinates, ys has ny+1; free[iy * nx + ix] marks free cells.  Returns every boundary
// ring of the free region with free space on its left (outer rings counter-clockwise, holes clockwise),
// with collinear points removed.
std::vector<core::Ring> TraceFreeRegion(const std::vector<double>& xs, const std::vector<double>& ys,
                                        const std::vector<char>& free);

// Splits the rings from TraceFreeRegion into one outer boundary and obstacle rings (counter-clockwise).
// Returns false if the free region is not one connected piece.
bool SplitBoundaryAndObstacles(std::vector<core::Ring> rings, core::Ring* boundary,
                               std::vector<core::Ring>* obstacles);

// Number of 4-connected components of free cells.
int CountComponents(int nx, int ny, const std::vector<char>& free);

}  // namespace toponav::sim::internal

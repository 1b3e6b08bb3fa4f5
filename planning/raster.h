#pragma once
// A square-cell raster over a region, for the grid questions of Learned Subgoal Planning: which cells a
// polygon set covers (scanline fill), and shortest distances through some of the cells (8-connected
// Dijkstra with octile steps).  Cell i covers [origin + (x, y) * cell, origin + (x + 1, y + 1) * cell).
#include <vector>

#include "core/geometry.h"

namespace toponav::planning {

struct Raster {
  core::Vec2 origin;   // the lower-left corner of cell (0, 0)
  double cell = 1.0;   // side length, world units
  int width = 0, height = 0;

  // Cells covering 'box' grown by 'margin' on every side.
  static Raster Covering(const core::Aabb2& box, double cell, double margin = 0.0);
  size_t size() const { return size_t(width) * size_t(height); }
  int Index(int x, int y) const { return y * width + x; }
  // The cell holding p, or -1 outside the raster.
  int CellOf(const core::Vec2& p) const;
  core::Vec2 Center(int index) const;
};

// One byte a cell: nonzero where the cell's centre lies inside 'polygons' (outer rings minus holes; the
// polygons must not overlap, as in a union).
std::vector<char> FillPolygons(const Raster& raster, const std::vector<core::Polygon>& polygons);

// The cells whose centres lie within 'radius' of the polyline.
std::vector<int> CellsNear(const Raster& raster, const std::vector<core::Vec2>& polyline, double radius);

// Shortest 8-connected distances (world units) from the 'sources' (distance 0) through the cells with
// passable != 0; a diagonal step needs both cells beside it passable (no cutting a wall's corner).
// Infinity where unreachable; sources that are not passable are ignored.  With 'until', the search stops
// once every cell of it is settled: the distances there are exact, and other cells' may be left too high
// (infinity where the search did not get to them).
std::vector<double> CellDistances(const Raster& raster, const std::vector<char>& passable,
                                  const std::vector<int>& sources, const std::vector<int>* until = nullptr);

}  // namespace toponav::planning

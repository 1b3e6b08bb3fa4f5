#pragma once
// Exact polygon Booleans for known space (CGAL Epeck Polygon_set_2; deps.md §7 explains why neither the
// inexact kernel nor Boost.Geometry).  Inputs and outputs are plain core polygons in double precision; the
// exact representation stays inside, so repeated operations do not accumulate rounding.
#include <memory>
#include <string>
#include <vector>

#include "core/geometry.h"

namespace toponav::mapping {

class PolygonSet {
 public:
  PolygonSet();
  ~PolygonSet();
  PolygonSet(const PolygonSet& other);
  PolygonSet& operator=(const PolygonSet& other);
  PolygonSet(PolygonSet&&) noexcept;
  PolygonSet& operator=(PolygonSet&&) noexcept;

  // A simple polygon (either orientation) or a polygon with holes (outer counter-clockwise, holes clockwise;
  // other orientations are fixed).  Throws core::DataError for fewer than 3 points or a non-simple ring.
  static PolygonSet FromRing(const core::Ring& ring);
  // 'check_simple' false accepts CGAL's own output back (its boundaries may touch themselves at a vertex).
  static PolygonSet FromPolygon(const core::Polygon& polygon, bool check_simple = true);

  void Join(const PolygonSet& other);        // this = this ∪ other
  void Intersect(const PolygonSet& other);   // this = this ∩ other
  void Difference(const PolygonSet& other);  // this = this \ other
  // Joins many sets at once (divide and conquer, much faster than joining one by one).  The pointer form
  // joins sets that live elsewhere without copying them first (null pointers are skipped).
  static PolygonSet JoinAll(const std::vector<PolygonSet>& sets);
  static PolygonSet JoinAll(const std::vector<const PolygonSet*>& sets);

  // The bounded regions the set encloses without covering them (the holes of its polygons), exactly.
  PolygonSet Holes() const;
  bool empty() const;
  double Area() const;
  std::vector<core::Polygon> Polygons() const;
  // Each connected polygon (with its holes) as a set of its own, exactly.
  std::vector<PolygonSet> Components() const;
  // True if p lies in the interior or on the boundary.
  bool Contains(const core::Vec2& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Intersection over union of two regions (0 when both are empty).
double IoU(const PolygonSet& a, const PolygonSet& b);

std::string PolygonLibraryInfo();  // "CGAL x.y"

}  // namespace toponav::mapping

#pragma once
// Walls from a range scan: what an agent's own range sensing (the one its motion already avoids obstacles with)
// says lies round it.  A held agent (experiments/navigation_trial.h, navigation.scan_when_held) plans with these
// besides its map, so a true wall the map lacks stops drawing its way into it.
#include <vector>

#include "core/geometry.h"

namespace toponav::planning {

// One ray of a scan: from the scan's origin along 'angle' (world frame, radians), the first hit at 'range'
// (max_range or more: nothing within reach).
struct ScanRay {
  double angle = 0.0;
  double range = 0.0;
};

// The wall segments a scan from 'origin' shows: the hit points of consecutive rays (in the order given, the last
// one next to the first: a full turn) that lie within 'link' of each other form one chain, and each chain of at
// least two points is simplified to segments no hit point of it lies farther than 'tolerance' from.  Rays with
// no hit (range >= max_range) break chains, and so do consecutive hits farther than 'link' apart (an occluding
// edge, or a wall seen so nearly edge-on that its hits spread out).
std::vector<core::Segment2> ScanWalls(const core::Vec2& origin, const std::vector<ScanRay>& rays, double max_range,
                                      double link, double tolerance);

// The walls of many scans, merged: a segment whose ends both lie within 'tolerance' of a kept segment's line,
// overlapping it or 'link' or less beyond its end, lengthens the first such kept segment instead of adding
// another, so scans of the same walls add little (kept segments are not merged with each other).
class ScanWallSet {
 public:
  ScanWallSet(double link, double tolerance) : link_(link), tolerance_(tolerance) {}
  void Add(const std::vector<core::Segment2>& walls);
  const std::vector<core::Segment2>& walls() const { return walls_; }

 private:
  bool Merge(const core::Segment2& s);
  double link_, tolerance_;
  std::vector<core::Segment2> walls_;
};

}  // namespace toponav::planning

#pragma once
// Planning test fixtures: an open, fully known 100 x 100 square without walls (every path is straight), and
// frontier targets placed by hand.
#include "mapping/mapping.h"
#include "planning/navigation.h"

namespace toponav::planning::testing {

inline mapping::MapView OpenSquare() {
  mapping::MapView v;
  v.known_space.push_back({core::Ring{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}});
  return v;
}

inline FrontierTarget Target(int id, core::Vec2 p, core::Vec2 outward = {1, 0}) { return {id, p, 10.0, outward}; }

}  // namespace toponav::planning::testing

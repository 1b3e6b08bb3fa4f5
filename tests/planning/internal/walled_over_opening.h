#pragma once
// A map for the straight-vertex tests (planning/internal/straight_vertices.h, planning/internal/vertex_inspector.h): known space
// 100 x 60; along its north edge a wall from (10, 60) to (90, 60) drawn through two vertices that it runs
// straight through (40 and 60: the jambs of an opening it covers), then south along x = 90 (a corner).
#include <vector>

#include "mapping/mapping.h"

namespace toponav::planning::testing {

inline mapping::MapView WalledOverOpening() {
  mapping::MapView v;
  v.known_space.push_back({core::Ring{{0, 0}, {100, 0}, {100, 60}, {0, 60}}, {}});
  const std::vector<core::Vec2> at = {{10, 60}, {40, 60}, {60, 60.5}, {90, 60}, {90, 20}};
  for (size_t i = 0; i < at.size(); ++i) v.vertices.push_back({int(i), at[i], {}, 10});
  for (int i = 0; i + 1 < int(at.size()); ++i) v.walls.push_back({i, i + 1, at[size_t(i)], at[size_t(i) + 1], 0.9});
  return v;
}

}  // namespace toponav::planning::testing

#pragma once
// The dead-end maze (testing::DeadEndMaze) as the agent's map after looking around at its start: the stem
// and the bottom corridor are known; frontier 1 where the bottom corridor goes on into the dead end (to the
// right of the start), frontier 2 at the top of the stem (the way to the goal).
#include <utility>
#include <vector>

#include "mapping/mapping.h"

namespace toponav::planning::testing {

inline mapping::MapView DeadEndSeenFromStart() {
  using core::Vec2;
  mapping::MapView v;
  const Vec2 a{0, 0}, b{36, 0}, c{36, 14}, d{14, 14}, e{14, 60}, f{0, 60};
  v.known_space.push_back({{a, b, c, d, e, f}, {}});
  const std::vector<Vec2> corners{a, b, c, d, e, f};
  for (size_t i = 0; i < corners.size(); ++i) v.vertices.push_back({int(i), corners[i], {}, 5});
  for (auto [i, j] : {std::pair{0, 1}, {2, 3}, {3, 4}, {5, 0}})
    v.walls.push_back({i, j, corners[size_t(i)], corners[size_t(j)], 0.9});
  v.frontiers.push_back({1, {b, c}, (b + c) * 0.5, 14.0});
  v.frontiers.push_back({2, {e, f}, (e + f) * 0.5, 14.0});
  return v;
}

// Pointers to the view's frontiers, in order (SubgoalGrid's input).
inline std::vector<const mapping::Frontier*> FrontiersOf(const mapping::MapView& v) {
  std::vector<const mapping::Frontier*> out;
  for (const auto& f : v.frontiers) out.push_back(&f);
  return out;
}

}  // namespace toponav::planning::testing

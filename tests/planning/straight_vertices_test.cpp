#include "planning/straight_vertices.h"

#include <gtest/gtest.h>

namespace toponav::planning {
namespace {

using core::Vec2;

// Known space 100 x 60; along its north edge a wall from (10, 60) to (90, 60) drawn through two vertices
// that it runs straight through (40 and 60: the jambs of an opening it covers), then south along x = 90
// (a corner).
mapping::MapView WalledOverOpening() {
  mapping::MapView v;
  v.known_space.push_back({core::Ring{{0, 0}, {100, 0}, {100, 60}, {0, 60}}, {}});
  const std::vector<Vec2> at = {{10, 60}, {40, 60}, {60, 60.5}, {90, 60}, {90, 20}};
  for (size_t i = 0; i < at.size(); ++i) v.vertices.push_back({int(i), at[i], {}, 10});
  for (int i = 0; i + 1 < int(at.size()); ++i) v.walls.push_back({i, i + 1, at[size_t(i)], at[size_t(i) + 1], 0.9});
  return v;
}

TEST(StraightVertices, VerticesWallsRunStraightThroughAreFoundWithLookoutsOnTheKnownSide) {
  const auto found = StraightVertices(WalledOverOpening(), 0.3, 10.0);
  ASSERT_EQ(found.size(), 2u);  // not the wall's end (one wall) nor the corner at (90, 60)
  EXPECT_EQ(found[0].id, 1);
  EXPECT_EQ(found[1].id, 2);
  ASSERT_EQ(found[0].lookouts.size(), 1u);  // north of the wall is unknown
  EXPECT_NEAR(found[0].lookouts[0].x, 40.0, 0.2);
  EXPECT_NEAR(found[0].lookouts[0].y, 50.0, 0.01);
  // (40, 60) bends by 0.025 rad and (60, 60.5) by 0.042.
  EXPECT_EQ(StraightVertices(WalledOverOpening(), 0.03, 10.0).size(), 1u);
  EXPECT_TRUE(StraightVertices(WalledOverOpening(), 0.02, 10.0).empty());
}

}  // namespace
}  // namespace toponav::planning

#include "planning/internal/straight_vertices.h"

#include <gtest/gtest.h>

#include "tests/planning/internal/walled_over_opening.h"

namespace toponav::planning {
namespace {

using core::Vec2;

using testing::WalledOverOpening;

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

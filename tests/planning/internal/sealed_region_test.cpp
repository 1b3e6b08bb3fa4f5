#include "planning/internal/sealed_region.h"

#include <gtest/gtest.h>

namespace toponav::planning {
namespace {

const core::Aabb2 kBounds{{-100, -50}, {100, 50}};

core::Polygon Box(double x0, double y0, double x1, double y1) {
  return {core::Ring{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

TEST(SealedRegion, KnownSpaceReachingEverySideOfTheBoundsLeavesNoneUnreached) {
  // An L of two known pieces that together come within 10 units of all four sides.
  const std::vector<core::Polygon> known{Box(-95, -45, 0, 0), Box(0, 0, 92, 41)};
  EXPECT_FALSE(UnreachedSide(known, kBounds, 10.0, {0, 0}));
  EXPECT_FALSE(UnreachedSide({}, kBounds, 10.0, {0, 0})) << "no known space: nothing to judge by";
}

TEST(SealedRegion, TheNearestSideKnownSpaceStopsShortOfIsReturnedAtThePointNearestTheAgent) {
  // A room in the west half: the east side is 60 units off, the north one 15.
  const std::vector<core::Polygon> known{Box(-98, -48, 40, 35)};
  const auto side = UnreachedSide(known, kBounds, 10.0, {30, 20});
  ASSERT_TRUE(side);
  EXPECT_DOUBLE_EQ(side->x, 30.0);
  EXPECT_DOUBLE_EQ(side->y, 50.0) << "the north side (30 away) is nearer the agent than the east one (70)";
  // A larger reach takes the north side for reached; the east one is left.
  const auto east = UnreachedSide(known, kBounds, 20.0, {30, 20});
  ASSERT_TRUE(east);
  EXPECT_DOUBLE_EQ(east->x, 100.0);
  EXPECT_DOUBLE_EQ(east->y, 20.0);
}

}  // namespace
}  // namespace toponav::planning

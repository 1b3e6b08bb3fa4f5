#include "core/geometry.h"

#include <gtest/gtest.h>

#include "tests/testing/worlds.h"

namespace toponav::core {
namespace {

TEST(Geometry, SignedAreaIsPositiveForCounterClockwiseRings) {
  const Ring r = testing::Rect(0, 0, 2, 3);
  EXPECT_DOUBLE_EQ(SignedArea(r), 6.0);
  Ring cw = r;
  Reverse(cw);
  EXPECT_DOUBLE_EQ(SignedArea(cw), -6.0);
}

TEST(Geometry, PolygonAreaSubtractsHoles) {
  Polygon p{testing::Rect(0, 0, 10, 10), {}};
  Ring hole = testing::Rect(2, 2, 4, 4);
  Reverse(hole);
  p.holes.push_back(hole);
  EXPECT_DOUBLE_EQ(Area(p), 96.0);
  EXPECT_TRUE(Contains(p, {1, 1}));
  EXPECT_FALSE(Contains(p, {3, 3}));
  EXPECT_FALSE(Contains(p, {11, 1}));
}

TEST(Geometry, IsSimpleRejectsBowtieAndDegenerateRings) {
  EXPECT_TRUE(IsSimple(testing::Rect(0, 0, 1, 1)));
  EXPECT_FALSE(IsSimple({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));           // bow tie
  EXPECT_FALSE(IsSimple({{0, 0}, {1, 0}}));                           // too few points
  EXPECT_FALSE(IsSimple({{0, 0}, {1, 0}, {2, 0}}));                   // zero area
  EXPECT_FALSE(IsSimple({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}));   // touches itself
}

TEST(Geometry, RemoveCollinearDropsMidEdgePoints) {
  const Ring r{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {2, 2}, {0, 2}, {0, 1}};
  const Ring s = RemoveCollinear(r);
  EXPECT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(SignedArea(s), 4.0);
}

TEST(Geometry, RingDistanceIsZeroForOverlapAndContainment) {
  EXPECT_DOUBLE_EQ(RingDistance(testing::Rect(0, 0, 1, 1), testing::Rect(3, 0, 4, 1)), 2.0);
  EXPECT_DOUBLE_EQ(RingDistance(testing::Rect(0, 0, 2, 2), testing::Rect(1, 1, 3, 3)), 0.0);
  EXPECT_DOUBLE_EQ(RingDistance(testing::Rect(0, 0, 10, 10), testing::Rect(4, 4, 5, 5)), 0.0);
}

TEST(Geometry, WrapAngleMapsIntoHalfOpenRange) {
  EXPECT_NEAR(WrapAngle(3 * kPi), -kPi, 1e-12);
  EXPECT_NEAR(WrapAngle(-kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(WrapAngle(2 * kPi + 0.1), 0.1, 1e-12);
}

}  // namespace
}  // namespace toponav::core

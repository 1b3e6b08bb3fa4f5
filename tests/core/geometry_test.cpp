#include "core/geometry.h"

#include <gtest/gtest.h>

#include "core/rng.h"
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

TEST(Geometry, NearRingAgreesWithDistanceToRing) {
  const Ring ring{{0, 0}, {10, 0}, {10, 4}, {3, 7}, {0, 4}};
  Rng rng(3);
  int near = 0;
  for (int i = 0; i < 2000; ++i) {
    // Points on, near and away from the boundary.
    const Vec2 p = i % 2 ? Vec2{rng.Uniform(-2, 12), rng.Uniform(-2, 9)}
                         : ring[size_t(i / 2) % ring.size()] + Vec2{rng.Uniform(-0.5, 0.5), rng.Uniform(-0.5, 0.5)};
    for (double tol : {1e-6, 0.1, 0.5}) {
      const bool expect = DistanceToRing(p, ring) < tol;
      EXPECT_EQ(NearRing(p, ring, tol), expect) << p.x << "," << p.y << " tol " << tol;
      near += expect;
    }
  }
  EXPECT_TRUE(NearRing({5, 0}, ring, 1e-6)) << "a point on an edge";
  EXPECT_GT(near, 100);
}

TEST(Geometry, NearSegmentInteriorHoldsBesideTheSegmentAndNotPastItsEnds) {
  const Segment2 s{{0, 0}, {10, 0}};
  EXPECT_TRUE(NearSegmentInterior({5, 1.9}, s, 2.0));
  EXPECT_TRUE(NearSegmentInterior({0.1, -1.9}, s, 2.0));
  EXPECT_FALSE(NearSegmentInterior({5, 2.1}, s, 2.0));
  EXPECT_FALSE(NearSegmentInterior({-0.1, 0}, s, 2.0));  // within 2 of the segment, but past its end
  EXPECT_FALSE(NearSegmentInterior({10.5, 0.5}, s, 2.0));
  EXPECT_FALSE(NearSegmentInterior({0, 0}, {{3, 3}, {3, 3}}, 2.0));
}

TEST(Geometry, PolylineLengthSumsSegments) {
  EXPECT_EQ(PolylineLength({}), 0.0);
  EXPECT_EQ(PolylineLength({{1, 1}}), 0.0);
  EXPECT_DOUBLE_EQ(PolylineLength({{0, 0}, {3, 4}, {3, 10}}), 11.0);
}

TEST(Geometry, PointAlongAndSubPolylineFollowArcLengthRoundTurns) {
  const std::vector<Vec2> l{{0, 0}, {3, 4}, {3, 10}};  // 5 then 6 long
  EXPECT_NEAR(Distance(PointAlong(l, 2.5), {1.5, 2}), 0, 1e-12);
  EXPECT_NEAR(Distance(PointAlong(l, 8), {3, 7}), 0, 1e-12);
  EXPECT_NEAR(Distance(PointAlong(l, -1), {0, 0}), 0, 1e-12) << "clamped to the ends";
  EXPECT_NEAR(Distance(PointAlong(l, 99), {3, 10}), 0, 1e-12);
  const std::vector<Vec2> mid = SubPolyline(l, 2.5, 8);
  ASSERT_EQ(mid.size(), 3u) << "keeps the turn";
  EXPECT_NEAR(Distance(mid[0], {1.5, 2}), 0, 1e-12);
  EXPECT_NEAR(Distance(mid[1], {3, 4}), 0, 1e-12);
  EXPECT_NEAR(Distance(mid[2], {3, 7}), 0, 1e-12);
  EXPECT_NEAR(PolylineLength(SubPolyline(l, 0, 11)), 11.0, 1e-12);
  EXPECT_TRUE(SubPolyline(l, 12, 13).empty());
}

TEST(Geometry, WrapAngleMapsIntoHalfOpenRange) {
  EXPECT_NEAR(WrapAngle(3 * kPi), -kPi, 1e-12);
  EXPECT_NEAR(WrapAngle(-kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(WrapAngle(2 * kPi + 0.1), 0.1, 1e-12);
}

}  // namespace
}  // namespace toponav::core

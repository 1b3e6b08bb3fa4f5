#include "sim/raycast.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/rng.h"
#include "sim/worlds.h"
#include "tests/testing/worlds.h"

namespace toponav::sim {
namespace {

using core::VertexLabel;

std::map<VertexLabel, int> LabelCounts(const std::vector<VisibleVertex>& v) {
  std::map<VertexLabel, int> counts;
  for (const auto& x : v) counts[x.label]++;
  return counts;
}

// vertexnav.md §8, test_vertexnav.py: a square obstacle (1,1)-(2,2).
TEST(RayCaster, SquareSeenFromOutsideCornerShowsThreeVerticesOneOfEachLabel) {
  const RayCaster rc(testing::SquareWorld());
  const auto v = rc.VisibleVertices({0, 0, 0});
  ASSERT_EQ(v.size(), 3u);
  auto c = LabelCounts(v);
  EXPECT_EQ(c[VertexLabel::kCorner], 1);
  EXPECT_EQ(c[VertexLabel::kLeftGap], 1);
  EXPECT_EQ(c[VertexLabel::kRightGap], 1);
  for (const auto& x : v) EXPECT_FALSE(x.position.x == 2 && x.position.y == 2) << "the far corner is hidden";
}

TEST(RayCaster, SquareSeenFromBelowShowsTwoVerticesOneLeftOneRightGap) {
  const RayCaster rc(testing::SquareWorld());
  const auto v = rc.VisibleVertices({1.5, 0, 0});
  ASSERT_EQ(v.size(), 2u);
  auto c = LabelCounts(v);
  EXPECT_EQ(c[VertexLabel::kLeftGap], 1);
  EXPECT_EQ(c[VertexLabel::kRightGap], 1);
}

TEST(RayCaster, SquareSeenFromInsideShowsFourCorners) {
  const RayCaster rc(testing::SquareWorld());
  const auto v = rc.VisibleVertices({1.5, 1.5, 0});
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(LabelCounts(v)[VertexLabel::kCorner], 4);
}

TEST(RayCaster, TwoSquaresVisibleCountsMatchReference) {
  const RayCaster rc(testing::TwoSquaresWorld());
  EXPECT_EQ(rc.VisibleVertices({0, 0, 0}).size(), 4u);
  EXPECT_EQ(rc.VisibleVertices({1.5, 0, 0}).size(), 5u);
  EXPECT_EQ(rc.VisibleVertices({1.5, 1.5, 0}).size(), 4u);
}

// vertexnav.md §8: unit square, max-range filtering happens before labelling.
TEST(RayCaster, MaxRangeFiltersBeforeLabelling) {
  const RayCaster rc(testing::SquareWorld(0, 0, 1, 1));
  EXPECT_EQ(rc.VisibleVertices({0.5, 0.5, 0}, 0.1).size(), 0u);
  EXPECT_EQ(rc.VisibleVertices({0.5, 0.5, 0}, 1.0).size(), 4u);
  const auto one = rc.VisibleVertices({-1, -1, 0}, std::sqrt(2.5));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].label, VertexLabel::kPoint);
  const auto three = rc.VisibleVertices({-1, -1, 0}, std::sqrt(8.0));
  ASSERT_EQ(three.size(), 3u);
  EXPECT_EQ(LabelCounts(three)[VertexLabel::kPoint], 0);
  const auto side = rc.VisibleVertices({-0.5, 0.5, 0});
  ASSERT_EQ(side.size(), 2u);
  auto c = LabelCounts(side);
  EXPECT_EQ(c[VertexLabel::kLeftGap], 1);
  EXPECT_EQ(c[VertexLabel::kRightGap], 1);
}

TEST(RayCaster, BearingsAreRelativeToHeadingAndSorted) {
  const RayCaster rc(testing::SquareWorld());
  const auto a = rc.VisibleVertices({0, 0, 0});
  const auto b = rc.VisibleVertices({0, 0, core::kPi / 4});
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(core::WrapAngle(a[i].bearing - core::kPi / 4 - b[i].bearing), 0.0, 1e-12);
    EXPECT_NEAR(a[i].range, core::Norm(a[i].position), 1e-12);
    if (i > 0) {
      EXPECT_LT(a[i - 1].bearing, a[i].bearing);
    }
  }
}

TEST(RayCaster, VisibilityPolygonOfEmptyRoomIsTheRoom) {
  const core::World w = testing::RoomWorld(10, 6);
  const RayCaster rc(w);
  const core::Ring poly = rc.VisibilityPolygon({3, 2});
  EXPECT_NEAR(core::SignedArea(poly), 60.0, 1e-9);
  EXPECT_EQ(poly.size(), 4u);
}

TEST(RayCaster, VisibilityPolygonBehindPillarIsExact) {
  // Room [0,10]x[0,10] with a pillar (4,4)-(6,6); from (5,1) the pillar shadows a trapezoid up to the wall.
  core::World w = testing::RoomWorld(10, 10);
  w.obstacles.push_back(testing::Rect(4, 4, 6, 6));
  const RayCaster rc(w);
  const core::Ring poly = rc.VisibilityPolygon({5, 1});
  // Shadow: rays through (4,4) and (6,4) from (5,1) hit y=10 at x = 5 -+ 3 = 2 and 8.
  // Visible area = 100 - pillar front region - shadow = 100 - [trapezoid (4,4),(6,4),(8,10),(2,10)].
  const double shadow = 0.5 * (2 + 6) * 6;
  EXPECT_NEAR(core::SignedArea(poly), 100.0 - shadow, 1e-9);
  bool has_exact_point = false;
  for (const auto& p : poly)
    has_exact_point = has_exact_point || (std::abs(p.x - 2) < 1e-12 && std::abs(p.y - 10) < 1e-12);
  EXPECT_TRUE(has_exact_point) << "shadow edge meets the far wall exactly at (2, 10)";
}

TEST(RayCaster, VisibilityPolygonContainsOnlyFreeSpaceInLabyrinths) {
  const core::World w = GenerateLabyrinth({}, 3);
  const RayCaster rc(w);
  core::Rng rng(1);
  for (int k = 0; k < 20;) {
    const core::Vec2 p{rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
    if (!core::IsFree(w, p, false)) continue;
    ++k;
    const core::Ring poly = rc.VisibilityPolygon(p);
    ASSERT_GE(poly.size(), 3u);
    EXPECT_GT(core::SignedArea(poly), 0.0);
    // Points between the agent and the polygon's vertices are free space.
    for (const auto& v : poly) {
      const core::Vec2 mid = p + (v - p) * rng.Uniform(0.05, 0.95);
      EXPECT_TRUE(core::IsFree(w, mid, false)) << mid.x << "," << mid.y;
    }
  }
}

TEST(RayCaster, DepthScanSeesWallsAndClutter) {
  core::World w = testing::RoomWorld(20, 20);
  const RayCaster walls_only(w);
  w.clutter.push_back({core::ClutterShape::kCylinder, {15, 10}, 1.0, 0.0, 2.0});
  const RayCaster with_clutter(w);
  const core::Pose2 pose{10, 10, 0};
  const auto d0 = walls_only.DepthScan(pose, 512, 100);
  const auto d1 = with_clutter.DepthScan(pose, 512, 100);
  // Column 256 looks straight ahead (+x): the wall at x = 20 is 10 away; the cylinder's face at x = 14.
  EXPECT_NEAR(d0[256], 10.0, 1e-3);
  EXPECT_NEAR(d1[256], 4.0, 0.01);
  EXPECT_NEAR(with_clutter.DepthScan(pose, 512, 100, false)[256], 10.0, 1e-3);
  // Column 0 looks backward (-x): wall at x = 0.
  EXPECT_NEAR(d0[0], 10.0, 1e-3);
  EXPECT_NEAR(walls_only.DepthScan(pose, 512, 5)[256], 5.0, 1e-12) << "misses read max_range";
}

TEST(RayCaster, VisibleVerticesAreUnoccludedInGeneratedWorlds) {
  // Every visible vertex must be reachable by a straight free segment (checked by sampling).
  for (auto kind : {core::WorldKind::kLabyrinth, core::WorldKind::kGuidedMaze, core::WorldKind::kOfficePark}) {
    const core::World w = GenerateWorld(kind, {}, 5);
    const RayCaster rc(w);
    const auto vis = rc.VisibleVertices(w.start);
    EXPECT_GE(vis.size(), 2u) << core::ToString(kind);
    for (const auto& v : vis)
      for (int k = 1; k < 50; ++k) {
        const core::Vec2 p = w.start.position() + (v.position - w.start.position()) * (k / 50.0);
        ASSERT_GT(core::SignedDistance(w, p, false), -1e-6) << core::ToString(kind);
      }
  }
}

}  // namespace
}  // namespace toponav::sim

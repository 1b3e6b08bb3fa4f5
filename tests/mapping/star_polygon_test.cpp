// Star polygons of observations (mapping/star_polygon.cpp) and frontier splitting at turns
// (mapping/internal/frontiers.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "mapping/mapping.h"

namespace toponav::mapping {
namespace {

using core::Vec2;

TEST(StarPolygon, InsertsTheCentreAcrossWideGapsAndDropsHiddenPoints) {
  EXPECT_TRUE(StarPolygon({0, 0}, {{1, 0}}).empty());
  const core::Ring fan = StarPolygon({0, 0}, {{1, 0}, {0, 1}});  // 90 degrees apart: the centre closes it
  ASSERT_EQ(fan.size(), 3u);
  EXPECT_NEAR(core::SignedArea(fan), 0.5, 1e-12);
  const core::Ring square = StarPolygon({0, 0}, {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}, {2, 2}});  // (2,2) is behind (1,1)
  EXPECT_EQ(square.size(), 4u);
  EXPECT_NEAR(core::SignedArea(square), 4.0, 1e-12);
}

TEST(OpenStarPolygon, OpenGapsReachTheRegionEdgeAndClosedOnesAreChords) {
  const core::Aabb2 region{{-10, -10}, {10, 10}};
  // A and B 90 degrees apart above the centre, C below.
  std::vector<StarPoint> pts{{{2, 2}, true, false}, {{-2, 2}, false, true}, {{0, -2}, false, false}};
  const core::Ring open = OpenStarPolygon({0, 0}, pts, OpenSpace{region, 100.0, 0.1, {}});
  ASSERT_FALSE(open.empty());
  EXPECT_TRUE(core::IsSimple(open));
  EXPECT_TRUE(core::Contains(open, {0, 9.5})) << "sight through the gap reaches the region's edge";
  EXPECT_FALSE(core::Contains(open, {0, 10.5}));
  // Same points, no open sides: the plain star polygon (the chord closes the gap).
  for (auto& p : pts) p.open_ccw = p.open_cw = false;
  const core::Ring closed = OpenStarPolygon({0, 0}, pts, OpenSpace{region, 100.0, 0.1, {}});
  EXPECT_FALSE(core::Contains(closed, {0, 3}));
  EXPECT_NEAR(core::SignedArea(closed), core::SignedArea(StarPolygon({0, 0}, {{2, 2}, {-2, 2}, {0, -2}})), 1e-12);
}

TEST(OpenStarPolygon, RangeAndBlockersStopSightLines) {
  const core::Aabb2 region{{-50, -50}, {50, 50}};
  const std::vector<StarPoint> pts{{{2, 2}, true, false}, {{-2, 2}, false, true}, {{0, -2}, false, false}};
  const core::Ring ranged = OpenStarPolygon({0, 0}, pts, OpenSpace{region, 6.0, 0.05, {}});
  EXPECT_TRUE(core::Contains(ranged, {0, 5.5}));
  EXPECT_FALSE(core::Contains(ranged, {0, 6.5})) << "no farther than max_range";
  std::vector<int> hit;
  const core::Ring blocked = OpenStarPolygon({0, 0}, pts, OpenSpace{region, 100.0, 0.05, {{{-30, 5}, {1, 5}}}}, &hit);
  EXPECT_TRUE(core::Contains(blocked, {-1, 4.5}));
  EXPECT_FALSE(core::Contains(blocked, {-1, 5.5})) << "a blocker stops the rays behind it";
  EXPECT_FALSE(core::Contains(blocked, {0.9, 5.1})) << "the corner at the blocker's end is kept";
  EXPECT_TRUE(core::Contains(blocked, {5, 20})) << "rays past the blocker's end go on";
  EXPECT_EQ(hit, (std::vector<int>{0}));
  // A blocker inside the triangle under a closed chord cuts it too.
  const std::vector<StarPoint> closed{{{4, 4}, false, false}, {{-4, 4}, false, false}, {{0, -4}, false, false}};
  const core::Ring clipped = OpenStarPolygon({0, 0}, closed, OpenSpace{region, 100.0, 0.05, {{{-1, 2}, {1, 2}}}});
  EXPECT_FALSE(core::Contains(clipped, {0, 3}));
  EXPECT_TRUE(core::Contains(clipped, {0, 1.5}));
  EXPECT_TRUE(core::Contains(clipped, {3, 3.5}));
}

// A square building [-5,5] x [0,10] seen from below (20 poses along y = -20): its front corners, labelled with
// the wall on their building side; then one MCMC call.

TEST(SplitAtTurns, SplitsAnLAtItsCornerOnly) {
  const std::vector<Vec2> l{{0, 0}, {10, 0}, {10, 10}};
  const auto pieces = SplitAtTurns(l, 0.3, 8.0);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0], (std::vector<Vec2>{{0, 0}, {10, 0}}));
  EXPECT_EQ(pieces[1], (std::vector<Vec2>{{10, 0}, {10, 10}}));
  EXPECT_EQ(SplitAtTurns(l, 0.3, 12.0).size(), 1u) << "pieces shorter than the minimum are not made";
  EXPECT_EQ(SplitAtTurns(l, 2.0, 8.0).size(), 1u) << "a right angle is no turn past 2 rad";
}

TEST(SplitAtTurns, TinyEdgesOnAStraightLineAreNoTurn) {
  // A straight chain with a 1e-4 zig-zag in it, as exact-to-double conversion leaves them.
  const std::vector<Vec2> line{{0, 0}, {10, 0}, {10.0001, 0.0001}, {10.0002, 0}, {20, 0}};
  EXPECT_EQ(SplitAtTurns(line, 0.3, 8.0).size(), 1u);
}

TEST(SplitAtTurns, ARingIsSplitAtItsCornersWhereverItStarts) {
  // A 20 x 20 square ring starting at a corner, and the same ring starting halfway along a side.
  const std::vector<Vec2> at_corner{{0, 0}, {20, 0}, {20, 20}, {0, 20}, {0, 0}};
  const std::vector<Vec2> mid_side{{10, 0}, {20, 0}, {20, 20}, {0, 20}, {0, 0}, {10, 0}};
  for (const auto* ring : {&at_corner, &mid_side}) {
    const auto pieces = SplitAtTurns(*ring, 0.3, 8.0);
    ASSERT_EQ(pieces.size(), 4u);
    for (const auto& piece : pieces) {
      double length = 0;
      for (size_t i = 1; i < piece.size(); ++i) length += core::Distance(piece[i - 1], piece[i]);
      EXPECT_NEAR(length, 20.0, 1e-9) << "each piece is one side, none cut at the ring's start";
    }
  }
}

// Three free-standing points seen from the origin: known space is the fan A-B-C plus the origin, all of its
// boundary frontier (a ring with no wall), turning sharply at A, B and C and not at all at the origin, between
// C and A.  Split there, each opening gets its own frontier (a target at the middle of one long chain would
// sit in the corner at B) -- three whatever point the ring starts at.

}  // namespace
}  // namespace toponav::mapping

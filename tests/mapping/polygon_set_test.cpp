#include "mapping/polygon_set.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "sim/raycast.h"
#include "sim/worlds.h"

#include <cmath>
#include "tests/testing/worlds.h"

namespace toponav::mapping {
namespace {

TEST(PolygonSet, UnionOfOverlappingSquaresHasExactArea) {
  PolygonSet a = PolygonSet::FromRing(testing::Rect(0, 0, 2, 2));
  a.Join(PolygonSet::FromRing(testing::Rect(1, 1, 3, 3)));
  EXPECT_DOUBLE_EQ(a.Area(), 7.0);
  EXPECT_EQ(a.Polygons().size(), 1u);
}

TEST(PolygonSet, DifferenceMakesAHole) {
  PolygonSet a = PolygonSet::FromRing(testing::Rect(0, 0, 10, 10));
  a.Difference(PolygonSet::FromRing(testing::Rect(4, 4, 6, 6)));
  EXPECT_DOUBLE_EQ(a.Area(), 96.0);
  const auto polys = a.Polygons();
  ASSERT_EQ(polys.size(), 1u);
  EXPECT_EQ(polys[0].holes.size(), 1u);
  EXPECT_FALSE(a.Contains({5, 5}));
  EXPECT_TRUE(a.Contains({1, 1}));
}

TEST(PolygonSet, JoinAllMatchesSequentialJoins) {
  std::vector<PolygonSet> sets;
  PolygonSet seq;
  for (int i = 0; i < 20; ++i) {
    sets.push_back(PolygonSet::FromRing(testing::Rect(i * 0.7, (i % 3) * 0.5, i * 0.7 + 1, (i % 3) * 0.5 + 1)));
    seq.Join(sets.back());
  }
  EXPECT_NEAR(PolygonSet::JoinAll(sets).Area(), seq.Area(), 1e-9);
}

TEST(PolygonSet, JoinAllOfPointersSkipsNullAndEmptyAndLeavesTheInputsAlone) {
  std::vector<PolygonSet> sets;
  for (int i = 0; i < 7; ++i) sets.push_back(PolygonSet::FromRing(testing::Rect(i * 2.0, 0, i * 2.0 + 3, 1)));
  const PolygonSet empty;
  std::vector<const PolygonSet*> ptrs{nullptr, &empty};
  for (const auto& s : sets) ptrs.push_back(&s);
  const PolygonSet all = PolygonSet::JoinAll(ptrs);
  EXPECT_NEAR(all.Area(), 15.0, 1e-9);  // [0, 15] x [0, 1]
  EXPECT_NEAR(PolygonSet::JoinAll(sets).Area(), 15.0, 1e-9);
  for (const auto& s : sets) EXPECT_NEAR(s.Area(), 3.0, 1e-9);  // joined into copies, not into the inputs
  EXPECT_TRUE(PolygonSet::JoinAll(std::vector<const PolygonSet*>{nullptr, &empty}).empty());
}

TEST(PolygonSet, HolesAreTheEnclosedRegionsOnly) {
  // A ring with two holes (one of them holding an island) beside an open notch that is not enclosed.
  PolygonSet a = PolygonSet::FromRing(testing::Rect(0, 0, 20, 10));
  a.Difference(PolygonSet::FromRing(testing::Rect(2, 2, 8, 8)));
  a.Difference(PolygonSet::FromRing(testing::Rect(10, 2, 13, 5)));
  a.Difference(PolygonSet::FromRing(testing::Rect(15, 0, 18, 6)));  // touches the outer edge: open
  a.Join(PolygonSet::FromRing(testing::Rect(4, 4, 5, 5)));          // island inside the first hole
  const PolygonSet holes = a.Holes();
  EXPECT_DOUBLE_EQ(holes.Area(), 36.0 - 1.0 + 9.0);
  EXPECT_TRUE(holes.Contains({3, 3}));
  EXPECT_FALSE(holes.Contains({4.5, 4.5}));
  EXPECT_FALSE(holes.Contains({16, 3}));
  EXPECT_TRUE(PolygonSet::FromRing(testing::Rect(0, 0, 1, 1)).Holes().empty());
  EXPECT_TRUE(PolygonSet().Holes().empty());
}

TEST(PolygonSet, IoUOfIdenticalAndDisjointRegions) {
  const PolygonSet a = PolygonSet::FromRing(testing::Rect(0, 0, 1, 1));
  const PolygonSet b = PolygonSet::FromRing(testing::Rect(5, 5, 6, 6));
  EXPECT_DOUBLE_EQ(IoU(a, a), 1.0);
  EXPECT_DOUBLE_EQ(IoU(a, b), 0.0);
  EXPECT_DOUBLE_EQ(IoU(a, PolygonSet::FromRing(testing::Rect(0, 0, 1, 2))), 0.5);
}

TEST(PolygonSet, SelfIntersectingInputIsADataError) {
  EXPECT_THROW(PolygonSet::FromRing({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), core::DataError);
}

// Acceptance: every labyrinth and maze has one connected free space (checked with exact Booleans).
TEST(GeneratedWorlds, LabyrinthAndMazeFreeSpaceIsOneConnectedPiece) {
  for (auto kind : {core::WorldKind::kLabyrinth, core::WorldKind::kGuidedMaze})
    for (uint64_t seed = 0; seed < 30; ++seed) {
      const core::World w = sim::GenerateWorld(kind, {}, seed);
      const PolygonSet free = PolygonSet::FromPolygon(core::FreeSpacePolygon(w));
      EXPECT_EQ(free.Polygons().size(), 1u) << core::ToString(kind) << " seed " << seed;
      EXPECT_NEAR(free.Area(), core::Area(core::FreeSpacePolygon(w)), 1e-6);
    }
}

}  // namespace
}  // namespace toponav::mapping

namespace toponav::mapping {
namespace {

// The exact visibility polygon lies inside true free space and matches a dense ray fan.
TEST(GeneratedWorlds, VisibilityPolygonIsFreeSpaceAndMatchesDenseRayFan) {
  for (auto kind : {core::WorldKind::kLabyrinth, core::WorldKind::kGuidedMaze, core::WorldKind::kOfficePark})
    for (uint64_t seed = 0; seed < 5; ++seed) {
      const core::World w = sim::GenerateWorld(kind, {}, seed);
      const sim::RayCaster rc(w);
      const core::Ring vis = rc.VisibilityPolygon(w.start.position());
      ASSERT_GE(vis.size(), 3u);
      PolygonSet outside = PolygonSet::FromRing(vis);
      outside.Difference(PolygonSet::FromPolygon(core::FreeSpacePolygon(w)));
      const double area = core::SignedArea(vis);
      if (!w.has_boundary()) {
        // Open worlds: the polygon reaches the far box; inside the region it must still be free space.
        PolygonSet in_region = PolygonSet::FromRing(vis);
        in_region.Intersect(PolygonSet::FromPolygon({core::FreeSpacePolygon(w).outer, {}}));
        in_region.Difference(PolygonSet::FromPolygon(core::FreeSpacePolygon(w)));
        EXPECT_LT(in_region.Area(), 1e-6 * area) << core::ToString(kind) << " seed " << seed;
        EXPECT_GT(area, w.bounds.width() * w.bounds.height()) << "the far box closes the polygon";
        continue;
      }
      EXPECT_LT(outside.Area(), 1e-6 * area) << core::ToString(kind) << " seed " << seed;
      // Dense fan of 20000 rays (walls only): its polygon area converges to the exact one from below-ish.
      const int n = 20000;
      const double range = 1e4;
      const auto depth = rc.DepthScan({w.start.x, w.start.y, 0.0}, n, range, false);
      core::Ring fan;
      for (int j = 0; j < n; ++j) {
        const double a = core::ColumnToBearing(j, n);
        fan.push_back(w.start.position() + core::Vec2{std::cos(a), std::sin(a)} * depth[size_t(j)]);
      }
      EXPECT_NEAR(core::SignedArea(fan) / area, 1.0, 0.01) << core::ToString(kind) << " seed " << seed;
    }
}

}  // namespace
}  // namespace toponav::mapping

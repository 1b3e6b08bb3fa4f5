#include "planning/internal/scan_walls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace toponav::planning {
namespace {

using core::Segment2;
using core::Vec2;

constexpr double kMaxRange = 12.0;

// A full turn of 360 rays from 'origin' against 'walls' (nearest hit; kMaxRange where none is nearer).
std::vector<ScanRay> Scan(const Vec2& origin, const std::vector<Segment2>& walls) {
  std::vector<ScanRay> rays;
  for (int j = 0; j < 360; ++j) {
    const double angle = 2.0 * core::kPi * j / 360;
    const Vec2 d{std::cos(angle), std::sin(angle)};
    double range = kMaxRange;
    for (const auto& w : walls) {
      const Vec2 e = w.b - w.a;
      const double den = core::Cross(d, e);
      if (std::abs(den) < 1e-12) continue;
      const double t = core::Cross(w.a - origin, e) / den, u = core::Cross(w.a - origin, d) / den;
      if (t > 0 && u >= 0 && u <= 1) range = std::min(range, t);
    }
    rays.push_back({angle, range});
  }
  return rays;
}

double TotalLength(const std::vector<Segment2>& walls) {
  double sum = 0;
  for (const auto& w : walls) sum += core::Distance(w.a, w.b);
  return sum;
}

// The room x, y in [-5, 5]; with a doorway, the west side is open for |y| < 2 (the scan's first ray points
// east, so the walk round the scan starts at the doorway's edge and crosses from the last ray to the first on
// the east wall).
std::vector<Segment2> Room(bool doorway) {
  std::vector<Segment2> walls{{{-5, -5}, {5, -5}}, {{5, 5}, {-5, 5}}, {{5, -5}, {5, 5}}};
  if (!doorway) {
    walls.push_back({{-5, 5}, {-5, -5}});
  } else {
    walls.push_back({{-5, 5}, {-5, 2}});
    walls.push_back({{-5, -2}, {-5, -5}});
  }
  return walls;
}

TEST(ScanWalls, AClosedRoomSeenFromInsideGivesItsFourSidesWhole) {
  const std::vector<Segment2> walls = ScanWalls({0, 0}, Scan({0, 0}, Room(false)), kMaxRange, 2.0, 0.3);
  EXPECT_LE(walls.size(), 5u) << "four sides, the one the walk round starts on perhaps in two";
  EXPECT_NEAR(TotalLength(walls), 40.0, 0.05) << "the ring closed: no gap between the last ray and the first";
  for (const auto& w : walls)
    for (const Vec2& p : {w.a, w.b})
      EXPECT_NEAR(std::max(std::abs(p.x), std::abs(p.y)), 5.0, 0.3) << "(" << p.x << ", " << p.y << ") off the walls";
}

TEST(ScanWalls, RaysWithNoHitAndJumpsInRangeBreakTheWalls) {
  // Through the doorway nothing is within range: no wall spans it, and the east wall, where the last ray
  // meets the first, comes out whole.
  const std::vector<Segment2> walls = ScanWalls({0, 0}, Scan({0, 0}, Room(true)), kMaxRange, 2.0, 0.3);
  EXPECT_EQ(walls.size(), 5u) << "two stubs beside the doorway, and the north, east and south sides";
  EXPECT_NEAR(TotalLength(walls), 36.0, 0.2);
  for (const auto& w : walls)
    for (double t = 0; t <= 1; t += 0.05) {
      const Vec2 p = w.a + (w.b - w.a) * t;
      EXPECT_FALSE(p.x < -4.5 && std::abs(p.y) < 1.5) << "a wall across the doorway at (" << p.x << ", " << p.y << ")";
    }
  // A pillar in front of the west wall: its near face and the wall behind it are separate walls, not joined.
  std::vector<Segment2> pillar = Room(false);
  pillar.push_back({{-2, -1}, {-2, 1}});
  const std::vector<Segment2> seen = ScanWalls({0, 0}, Scan({0, 0}, pillar), kMaxRange, 2.0, 0.3);
  for (const auto& w : seen) {
    const bool on_pillar = std::abs(w.a.x + 2) < 0.3, ends_on_pillar = std::abs(w.b.x + 2) < 0.3;
    EXPECT_EQ(on_pillar, ends_on_pillar) << "a wall from the pillar to the room's side";
  }
}

TEST(ScanWallSet, ScansOfOneWallMergeIntoOneSegmentAndOtherWallsStaySeparate) {
  ScanWallSet set(2.0, 0.3);
  set.Add({{{0, 0}, {5, 0}}});
  set.Add({{{4, 0.1}, {9, 0.1}}});  // overlapping, 0.1 off the line
  ASSERT_EQ(set.walls().size(), 1u);
  set.Add({{{10.5, 0}, {12, 0}}});  // 1.5 past the end: within link
  ASSERT_EQ(set.walls().size(), 1u);
  EXPECT_NEAR(set.walls()[0].a.x, 0.0, 1e-9);
  EXPECT_NEAR(set.walls()[0].b.x, 12.0, 1e-9);
  set.Add({{{0, 3}, {5, 3}}});    // parallel, 3 away
  set.Add({{{20, 0}, {22, 0}}});  // on the line, 8 past the end
  set.Add({{{3, -2}, {3, 2}}});   // across it
  EXPECT_EQ(set.walls().size(), 4u);
}

}  // namespace
}  // namespace toponav::planning

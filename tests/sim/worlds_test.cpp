#include "sim/worlds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "sim/internal/labyrinth_rooms.h"
#include "sim/world_io.h"

namespace toponav::sim {
namespace {

using core::WorldKind;

class EveryKind : public ::testing::TestWithParam<WorldKind> {};

TEST_P(EveryKind, SameSeedGivesByteIdenticalJson) {
  const WorldOptions o;
  EXPECT_EQ(WorldToJson(GenerateWorld(GetParam(), o, 17)), WorldToJson(GenerateWorld(GetParam(), o, 17)));
}

TEST_P(EveryKind, DifferentSeedsGiveDifferentWorlds) {
  const WorldOptions o;
  EXPECT_NE(WorldToJson(GenerateWorld(GetParam(), o, 1)), WorldToJson(GenerateWorld(GetParam(), o, 2)));
}

TEST_P(EveryKind, StartIsFreeAndWorldValidates) {
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const core::World w = GenerateWorld(GetParam(), {}, seed);
    EXPECT_NO_THROW(ValidateWorld(w, "generated")) << seed;
    EXPECT_TRUE(core::IsFree(w, w.start.position())) << seed;
    EXPECT_GE(core::SignedDistance(w, w.start.position()), 1.0) << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(Worlds, EveryKind,
                         ::testing::Values(WorldKind::kLabyrinth, WorldKind::kOfficePark, WorldKind::kGuidedMaze),
                         [](const auto& info) { return std::string(core::ToString(info.param)); });

// Width of free space across a point, measured along an axis (to the walls on either side).
double FreeWidth(const core::World& w, core::Vec2 p, core::Vec2 axis) {
  auto reach = [&](core::Vec2 dir) {
    double t = 0;
    while (core::IsFree(w, p + dir * (t + 0.01), false) && t < 500) t += 0.01;
    return t;
  };
  return reach(axis) + reach(axis * -1.0);
}

// Rooms are as far apart as the reference's: two empty cells between them on one axis are enough (their edge
// cells' centres 3 apart, past 2.05), one is not; on a diagonal the two axes' gaps add up.
TEST(Labyrinth, RoomsTwoEmptyCellsApartAreFarEnough) {
  using internal::GridRoom;
  using internal::RoomGap;
  const LabyrinthOptions o;
  const GridRoom a{0, 0, 2, 2};  // cells 0..2
  EXPECT_GT(RoomGap(a, {5, 0, 2, 2}), o.room_separation_cells) << "cells 3 and 4 empty";
  EXPECT_LE(RoomGap(a, {4, 1, 3, 2}), o.room_separation_cells) << "cell 3 empty";
  EXPECT_LE(RoomGap(a, {3, 3, 2, 2}), o.room_separation_cells) << "corner cells touching diagonally";
  EXPECT_GT(RoomGap(a, {3, 4, 2, 2}), o.room_separation_cells) << "diagonal, one empty row between";
  EXPECT_EQ(RoomGap(a, {1, 1, 3, 3}), 0.0) << "overlapping";
  EXPECT_EQ(RoomGap(a, {5, 0, 2, 2}), RoomGap({5, 0, 2, 2}, a));
}

TEST(Labyrinth, CorridorsAreHallWidthWide) {
  // Along a wall edge, the free space measured perpendicular to the edge is either a corridor (exactly 20 wide)
  // or a room (wider).  At least some edges must border corridors.
  const LabyrinthOptions o;
  int corridors = 0;
  for (uint64_t seed = 0; seed < 10; ++seed) {
    const core::World w = GenerateLabyrinth(o, seed);
    for (size_t i = 0; i < w.boundary.size(); ++i) {
      const core::Vec2 a = w.boundary[i], b = w.boundary[(i + 1) % w.boundary.size()];
      const core::Vec2 mid = (a + b) * 0.5;
      const core::Vec2 along = (b - a) / core::Distance(a, b);
      const core::Vec2 inward{-along.y, along.x};  // boundary is counter-clockwise: free space on the left
      const double width = FreeWidth(w, mid + inward * 0.5, inward);
      EXPECT_GE(width + 0.05, o.hall_width) << "seed " << seed;
      if (std::abs(width - o.hall_width) < 0.05) ++corridors;
    }
  }
  EXPECT_GT(corridors, 10);
}

TEST(Labyrinth, NoStraightWallLongerThanTheRunLimit) {
  // The generator rejects straight runs of more than 11 free cells, so no wall is longer than 11 grown cells.
  const LabyrinthOptions o;
  const double s = o.hall_width / (1 + o.inflate_ratio), d = s * o.inflate_ratio / 2;
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const core::World w = GenerateLabyrinth(o, seed);
    for (const auto& wall : core::MapWalls(w))
      EXPECT_LE(core::Distance(wall.a, wall.b), o.max_straight_run_cells * s + 2 * d + 1e-9) << "seed " << seed;
    const double area = core::Area(core::FreeSpacePolygon(w));
    // 4 rooms of 3-4 cells per side plus corridors: between 4 * 9 and 4 * 16 + 60 grown cells.
    EXPECT_GT(area, 4 * 9 * s * s) << "seed " << seed;
    EXPECT_LT(area, (4 * 16 + 60) * (s + 2 * d) * (s + 2 * d)) << "seed " << seed;
  }
}

TEST(Labyrinth, ClutterHugsWallsInsideFreeSpace) {
  const LabyrinthOptions o;
  const core::World w = GenerateLabyrinth(o, 4);
  EXPECT_EQ(int(w.clutter.size()), o.num_clutter);
  core::World walls_only = w;
  walls_only.clutter.clear();
  for (const auto& c : w.clutter) {
    const double d = core::SignedDistance(walls_only, c.center);
    EXPECT_GE(d, c.BoundingRadius());
    EXPECT_LE(d, c.BoundingRadius() + o.clutter_max_wall_gap + 1e-9);
  }
}

TEST(OfficePark, BuildingsAre25To40Apart) {
  const OfficeParkOptions o;
  for (uint64_t seed = 0; seed < 10; ++seed) {
    const core::World w = GenerateOfficePark(o, seed);
    ASSERT_EQ(int(w.obstacles.size()), o.num_buildings);
    for (size_t i = 0; i < w.obstacles.size(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < w.obstacles.size(); ++j)
        if (i != j) nearest = std::min(nearest, core::RingDistance(w.obstacles[i], w.obstacles[j]));
      EXPECT_GT(nearest, o.min_building_gap) << "seed " << seed;
      EXPECT_LT(nearest, o.max_building_gap) << "seed " << seed;
    }
    for (const auto& b : w.obstacles)
      for (const auto& p : b) EXPECT_TRUE(w.bounds.Contains(p));
    EXPECT_EQ(int(w.clutter.size()), o.num_trees);
  }
}

TEST(GuidedMaze, GuidePathRunsInsideCorridorsFromStartToGoal) {
  const GuidedMazeOptions o;
  for (uint64_t seed = 0; seed < 10; ++seed) {
    const core::World w = GenerateGuidedMaze(o, seed);
    ASSERT_GE(w.guide_path.size(), 2u);
    EXPECT_NEAR(core::Distance(w.guide_path.front(), w.start.position()), 0.0, 1e-9);
    EXPECT_NEAR(core::Distance(w.guide_path.back(), w.goal), 0.0, 1e-9);
    for (size_t i = 0; i + 1 < w.guide_path.size(); ++i)
      for (int k = 0; k <= 20; ++k) {
        const core::Vec2 p = w.guide_path[i] + (w.guide_path[i + 1] - w.guide_path[i]) * (k / 20.0);
        EXPECT_GE(core::SignedDistance(w, p, false), o.corridor_width / 2 - 1e-9) << "seed " << seed;
      }
    // A spanning-tree maze is simply connected: one boundary ring and no free-standing obstacles.
    EXPECT_TRUE(w.obstacles.empty());
    // The bounds are the free space's extent (the outer border is wall, not part of the region agents map).
    EXPECT_NEAR(w.bounds.width(), (o.cells_x - 1) * (o.corridor_width + o.wall_thickness) + o.corridor_width, 1e-9);
  }
}

TEST(WorldOptions, ValidateRejectsOutOfRangeValues) {
  WorldOptions o;
  o.labyrinth.num_rooms = 1;
  try {
    o.Validate();
    FAIL() << "no throw";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "labyrinth.num_rooms");
  }
}

}  // namespace
}  // namespace toponav::sim

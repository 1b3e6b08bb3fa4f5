#include "planning/internal/dropped_walls.h"

#include <gtest/gtest.h>

namespace toponav::planning {
namespace {

mapping::Frontier MakeFrontier(std::vector<core::Vec2> points) {
  mapping::Frontier f;
  f.points = std::move(points);
  f.midpoint = (f.points.front() + f.points.back()) * 0.5;
  return f;
}

mapping::MapWall Wall(core::Vec2 a, core::Vec2 b) {
  mapping::MapWall w;
  w.pa = a;
  w.pb = b;
  return w;
}

TEST(DroppedWalls, AFrontierAlongAWallTheMapHeldLongEnoughAndCorneredAtBothEndsIsTakenForIt) {
  // A room's side (0, 0)-(0, 90) between two corners; the map held it for 50 updates, then left it out.
  const mapping::MapWall top = Wall({0, 90}, {40, 90}), bottom = Wall({40, 0}, {0, 0});
  DroppedWalls d;
  for (int i = 0; i < 50; ++i) d.Update({Wall({0, 0}, {0, 90}), top, bottom});
  d.Update({top, bottom});
  EXPECT_EQ(d.size(), 3u);
  const mapping::Frontier along = MakeFrontier({{0.8, 2}, {0.6, 88}});  // known space ends on the wall's line
  EXPECT_DOUBLE_EQ(d.ShareAlong(along, 50), 1.0);
  EXPECT_TRUE(d.TakenForWall(along, {top, bottom}, 50));
  EXPECT_FALSE(d.TakenForWall(along, {top, bottom}, 51)) << "held for 50 updates, not 51";
  EXPECT_FALSE(d.TakenForWall(along, {top}, 50)) << "no map wall at its lower end: nothing says it is a corner";
}

TEST(DroppedWalls, AFrontierThatRunsStraightOnFromAMapWallMayBeADoorwayAndIsNotTakenForAWall) {
  // A room's side along y = 90 with a false wall across a doorway (40..60), held for 60 updates, then left out.
  const mapping::MapWall left = Wall({0, 90}, {40, 90}), right = Wall({60, 90}, {100, 90});
  DroppedWalls d;
  for (int i = 0; i < 60; ++i) d.Update({left, Wall({40, 90}, {60, 90}), right});
  const mapping::Frontier doorway = MakeFrontier({{41, 90.5}, {59, 90.5}});
  EXPECT_TRUE(d.ShareAlong(doorway, 50) >= DroppedWalls::kAlongShare);
  EXPECT_FALSE(d.TakenForWall(doorway, {left, right}, 50));
  EXPECT_FALSE(d.TakenForWall(doorway, {left, Wall({60, 90}, {60, 130})}, 50)) << "straight on at one end is enough";
}

TEST(DroppedWalls, AWallThatDriftsALittleIsTheSameWallAndOneThatMovesFarIsAnother) {
  DroppedWalls d;
  for (int i = 0; i < 30; ++i) d.Update({Wall({0.02 * i, 0}, {0.02 * i, 90})});  // 0.6 units over 30 updates
  EXPECT_EQ(d.size(), 1u);
  EXPECT_DOUBLE_EQ(d.ShareAlong(MakeFrontier({{0.6, 0}, {0.6, 90}}), 30), 1.0);
  d.Update({Wall({5, 0}, {5, 90})});
  EXPECT_EQ(d.size(), 2u) << "5 units off: another wall";
  EXPECT_DOUBLE_EQ(d.ShareAlong(MakeFrontier({{5, 0}, {5, 90}}), 2), 0.0);
}

TEST(DroppedWalls, AFrontierAcrossOrPastAHeldWallDoesNotLieAlongIt) {
  DroppedWalls d;
  for (int i = 0; i < 60; ++i) d.Update({Wall({0, 0}, {0, 40})});
  EXPECT_LT(d.ShareAlong(MakeFrontier({{-10, 20}, {10, 20}}), 50), 0.2) << "a corridor's mouth across the wall";
  const mapping::Frontier half = MakeFrontier({{0, 20}, {0, 60}});  // runs on 20 units past the wall's end
  EXPECT_NEAR(d.ShareAlong(half, 50), 0.55, 0.05);
  EXPECT_LT(d.ShareAlong(half, 50), DroppedWalls::kAlongShare) << "the part past the wall's end may be an opening";
  EXPECT_DOUBLE_EQ(DroppedWalls().ShareAlong(MakeFrontier({{0, 0}, {0, 40}}), 1), 0.0) << "nothing held";
}

}  // namespace
}  // namespace toponav::planning

#include "planning/internal/motion_blocks.h"

#include <gtest/gtest.h>

#include "planning/navigation.h"

namespace toponav::planning {
namespace {

using core::Vec2;

TEST(MotionBlocks, StepsWithoutHeadwayAlongThePathAddABlockAcrossTheWay) {
  MotionBlocks blocks(1, 3, 2.0, 4.0, 2.0);
  const std::vector<Vec2> east{{0, 0}, {20, 0}};
  // Sliding sideways (north) half a unit a step: no headway east.
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {0, 0.5}));
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {0.2, 0.5}));
  EXPECT_TRUE(blocks.Record(0, east, {0, 0}, {0, -0.5}));
  ASSERT_EQ(blocks.blocks().size(), 1u);
  const auto& [a, b] = blocks.blocks()[0];
  EXPECT_NEAR(a.x, 2.0, 1e-9);  // 'ahead' in front of the agent, 2 * half_width long, across the heading
  EXPECT_NEAR(b.x, 2.0, 1e-9);
  EXPECT_NEAR(std::abs(a.y - b.y), 8.0, 1e-9);
  EXPECT_NEAR(a.y + b.y, 0.0, 1e-9);
}

TEST(MotionBlocks, AStepWithHeadwayRestartsTheCount) {
  MotionBlocks blocks(2, 3, 2.0, 4.0, 2.0);
  const std::vector<Vec2> east{{0, 0}, {20, 0}};
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {0, 0.5}));
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {0, 0.5}));
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {1.5, 0}));  // 1.5 east: headway
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {0, 0.5}));
  EXPECT_FALSE(blocks.Record(1, east, {0, 0}, {0, 0.5}));  // agents count apart
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {0, 0.5}));
  EXPECT_TRUE(blocks.blocks().empty());
  // Short of a waypoint 0.6 away, 0.3 of progress is headway.
  EXPECT_FALSE(blocks.Record(0, {{0, 0}, {0.6, 0}}, {0, 0}, {0.3, 0}));
  EXPECT_FALSE(blocks.Record(0, east, {0, 0}, {0, 0.5}));
  EXPECT_TRUE(blocks.blocks().empty());
}

TEST(MotionBlocks, BlockPutsOneAcrossTheWayTowardAPointAndNoneWhereThePointsCoincide) {
  MotionBlocks blocks(1, 3, 2.0, 4.0, 2.0);
  EXPECT_TRUE(blocks.Block({10, 10}, {10, 30}));  // heading north
  ASSERT_EQ(blocks.blocks().size(), 1u);
  const auto& [a, b] = blocks.blocks()[0];
  EXPECT_NEAR(a.y, 12.0, 1e-9);  // 'ahead' in front, 2 * half_width long, across the heading
  EXPECT_NEAR(b.y, 12.0, 1e-9);
  EXPECT_NEAR(std::abs(a.x - b.x), 8.0, 1e-9);
  EXPECT_NEAR(a.x + b.x, 20.0, 1e-9);
  EXPECT_FALSE(blocks.Block({10, 10}, {10, 10}));
  EXPECT_EQ(blocks.blocks().size(), 1u);
}

TEST(MotionBlocks, ClearTakesTheBlocksBackAndTheHistoryKeepsThem) {
  MotionBlocks blocks(1, 3, 2.0, 4.0, 2.0);
  ASSERT_TRUE(blocks.Block({10, 10}, {10, 30}));
  blocks.Clear();
  EXPECT_TRUE(blocks.blocks().empty());
  ASSERT_TRUE(blocks.Block({10, 10}, {30, 10}));
  EXPECT_EQ(blocks.blocks().size(), 1u);
  ASSERT_EQ(blocks.added().size(), 2u) << "every block ever added, the one taken back too";
  EXPECT_NEAR(blocks.added()[0].a.y, 12.0, 1e-9);
  EXPECT_NEAR(blocks.added()[1].a.x, 12.0, 1e-9);
}

TEST(MotionBlocks, PlannersGoRoundABlock) {
  mapping::MapView view;
  view.known_space.push_back({core::Ring{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}});
  MotionBlocks blocks(1, 1, 2.0, 10.0, 2.0);
  ASSERT_TRUE(blocks.Record(0, {{50, 50}, {80, 50}}, {50, 50}, {50, 50}));
  const mapping::MapView blocked = blocks.With(view);
  ASSERT_EQ(blocked.walls.size(), 1u);
  ASSERT_EQ(blocked.vertices.size(), 2u);
  EXPECT_NE(blocked.vertices[0].id, blocked.vertices[1].id);
  const Path straight = VisibilityGraph(view, {}, false).Plan({50, 50}, {80, 50});
  const Path round = VisibilityGraph(blocked, {}, false).Plan({50, 50}, {80, 50});
  ASSERT_TRUE(straight && round);
  EXPECT_NEAR(straight.cost, 30.0, 1e-9);
  EXPECT_GT(round.cost, 32.0);  // round one end of the 20-long block 2 ahead
}

}  // namespace
}  // namespace toponav::planning

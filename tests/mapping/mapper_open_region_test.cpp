// Open worlds (MapperOptions::open_region): what known space the map makes around buildings.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "mapping/mapping.h"
#include "mapping/polygon_set.h"
#include "tests/testing/square_room.h"

namespace toponav::mapping {
namespace {

using core::Vec2;
using testing::Det;
using testing::Obs;

MapView MapOfBuildingSeenFromBelow(const MapperOptions& o) {
  Mapper m(o);
  core::Rng rng(3);
  for (int i = 0; i < 20; ++i) {
    const core::Pose2 pose{-3.0 + 0.3 * i, -20, 0.0};
    m.AddObservation(
        Obs(pose, {Det(pose, {5, 0}, core::VertexLabel::kRightGap), Det(pose, {-5, 0}, core::VertexLabel::kLeftGap)}));
  }
  m.SampleMostLikelyMap(rng);
  return m.View();
}

TEST(Mapper, OpenRegionMakesGroundBeyondGapsKnownButNotTheBuildingInside) {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-50, -50}, {50, 50}};
  o.open_region = o.world_bounds;
  const MapView view = MapOfBuildingSeenFromBelow(o);
  ASSERT_EQ(view.walls.size(), 1u);
  ASSERT_TRUE(view.known_set);
  EXPECT_TRUE(view.known_set->Contains({20, 20})) << "open ground beside the building is seen";
  EXPECT_TRUE(view.known_set->Contains({0, -40}));
  EXPECT_FALSE(view.known_set->Contains({0, 5})) << "the building's inside is not";
  for (const auto& f : view.frontiers)
    for (const auto& p : f.points)
      EXPECT_TRUE(std::abs(p.x) < 49.99 || std::abs(p.y) < 49.99) << "the region's edge is no frontier";
  // Without the open region only the fans between the two corners are known.
  MapperOptions closed = o;
  closed.open_region.reset();
  EXPECT_FALSE(MapOfBuildingSeenFromBelow(closed).known_set->Contains({20, 20}));
}

// An agent standing in a V-shaped recess of a building (walls C-B and B-A) sees out of it through the gap
// between the recess's ends: a chain of walls around the agent's own pose is not closed like a building.
TEST(Mapper, OpenRegionChainAroundTheAgentIsARecessNotABuilding) {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-50, -50}, {50, 50}};
  o.open_region = o.world_bounds;
  Mapper m(o);
  core::Rng rng(3);
  const Vec2 a{-10, 0}, b{0, 8}, c{10, 0};
  for (int i = 0; i < 20; ++i) {
    const core::Pose2 pose{-1.0 + 0.1 * i, 3, 0.0};
    m.AddObservation(Obs(pose, {Det(pose, c, core::VertexLabel::kRightGap), Det(pose, b, core::VertexLabel::kCorner),
                                Det(pose, a, core::VertexLabel::kLeftGap)}));
  }
  m.SampleMostLikelyMap(rng);
  const MapView view = m.View();
  ASSERT_EQ(view.walls.size(), 2u);
  ASSERT_TRUE(view.known_set);
  EXPECT_TRUE(view.known_set->Contains({0, 5})) << "the recess";
  EXPECT_TRUE(view.known_set->Contains({0, -20})) << "the open ground the recess opens onto";
  EXPECT_FALSE(view.known_set->Contains({0, 15})) << "behind the recess's walls";
}

// Open ground far from every vertex is where an open-world search ends, not a frontier (open_frontier_reach).
TEST(Mapper, OpenGroundFarFromEveryVertexIsNoFrontier) {
  auto frontier_edges_far = [](double reach) {
    MapperOptions o;
    o.world_bounds = core::Aabb2{{-150, -150}, {150, 150}};  // larger than the sensor's 100: sight ends inside it
    o.open_region = o.world_bounds;
    o.open_frontier_reach = reach;
    const MapView view = MapOfBuildingSeenFromBelow(o);
    int near = 0, far = 0;
    for (const auto& f : view.frontiers)
      for (size_t i = 1; i < f.points.size(); ++i) {
        const core::Segment2 e{f.points[i - 1], f.points[i]};
        const bool close = core::DistanceToSegment({5, 0}, e) <= 60 || core::DistanceToSegment({-5, 0}, e) <= 60;
        (close ? near : far) += 1;
      }
    return std::make_pair(near, far);
  };
  const auto [near, far] = frontier_edges_far(60.0);
  EXPECT_GT(near, 0) << "the unknown space behind the building is still a frontier";
  EXPECT_EQ(far, 0);
  EXPECT_GT(frontier_edges_far(0.0).second, 0) << "without the reach the far edge of sight is frontier";
}

}  // namespace
}  // namespace toponav::mapping

#include "planning/internal/doorways.h"

#include <gtest/gtest.h>

#include "planning/navigation.h"
#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

// A closed room [0, 60] x [0, 40] (walls between its corners, ids 0-3), known inside; 'rejected' vertices
// the posterior left out.
mapping::MapView ClosedRoom(const std::vector<Vec2>& rejected) {
  mapping::MapView v;
  const std::vector<Vec2> c{{0, 0}, {60, 0}, {60, 40}, {0, 40}};
  for (size_t i = 0; i < c.size(); ++i) v.vertices.push_back({int(i), c[i], {}, 5});
  for (int i = 0; i < 4; ++i) v.walls.push_back({i, (i + 1) % 4, c[size_t(i)], c[size_t((i + 1) % 4)], 0.9});
  v.known_space.push_back({testing::Rect(0, 0, 60, 40), {}});
  for (size_t i = 0; i < rejected.size(); ++i) v.rejected.push_back({int(10 + i), rejected[i], {}, 6});
  return v;
}

TEST(Doorways, TwoRejectedVerticesOnAWallAnOpeningApartAreADoorway) {
  // Jambs 14 apart on the bottom wall (a little off it, as estimates are), one far off any wall.
  const auto view = ClosedRoom({{20, 0.5}, {34, -0.5}, {30, 20}});
  const auto doors = DoorwayHypotheses(view, 2.0, 8.0, 16.0);
  ASSERT_EQ(doors.size(), 1u);
  EXPECT_EQ(doors[0].wall, 0);
  EXPECT_NEAR(doors[0].a.x, 20.0, 1e-9);
  EXPECT_NEAR(doors[0].b.x, 34.0, 1e-9);
  EXPECT_NEAR(doors[0].a.y, 0.0, 1e-9) << "the jambs are put on the wall";
  // From a jamb to the wall's end counts too (here 20 wide: within a 24 bound, not a 16 one).
  EXPECT_EQ(DoorwayHypotheses(view, 2.0, 8.0, 24.0).size(), 2u);
  EXPECT_TRUE(DoorwayHypotheses(ClosedRoom({}), 2.0, 8.0, 100.0).empty()) << "nothing on the walls, no doorway";
  EXPECT_TRUE(DoorwayHypotheses(ClosedRoom({{20, 3}, {34, 3}}), 2.0, 8.0, 16.0).empty())
      << "vertices farther than the tolerance from the wall are not on it";
}

TEST(Doorways, AMapCornerOnAWallIsAJambBesideARejectedVertex) {
  // The bottom wall drawn past a corner of the map at (20, 0.5) (a wall meeting it from below) and over the
  // opening beside it, whose other jamb the posterior rejected.
  mapping::MapView view = ClosedRoom({{34, -0.5}});
  view.vertices.push_back({4, {20, 0.5}, {}, 5});
  view.vertices.push_back({5, {20, -30}, {}, 5});
  view.walls.push_back({4, 5, {20, 0.5}, {20, -30}, 0.9});
  const auto doors = DoorwayHypotheses(view, 2.0, 8.0, 16.0);
  ASSERT_EQ(doors.size(), 1u);
  EXPECT_EQ(doors[0].wall, 0);
  EXPECT_NEAR(doors[0].a.x, 20.0, 1e-9);
  EXPECT_NEAR(doors[0].b.x, 34.0, 1e-9);
  view.rejected.clear();
  EXPECT_TRUE(DoorwayHypotheses(view, 2.0, 8.0, 16.0).empty()) << "one map corner and the wall's ends make no doorway";
}

TEST(Doorways, TwoMapCornersAWallWasDrawnPastAnOpeningApartAreADoorway) {
  // Tuning maze 9077: a side corridor's jambs seen down the corridor, both in the map as corners with no walls
  // of their own, and the corridor's wall drawn on past both, across the side corridor's mouth.
  mapping::MapView view = ClosedRoom({});
  view.vertices.push_back({4, {20, 0.5}, {}, 7});
  view.vertices.push_back({5, {36, -0.3}, {}, 7});
  const auto doors = DoorwayHypotheses(view, 2.0, 8.0, 24.0);
  ASSERT_EQ(doors.size(), 1u) << "not from a corner to the wall's end (20 and 24 wide)";
  EXPECT_EQ(doors[0].wall, 0);
  EXPECT_NEAR(doors[0].a.x, 20.0, 1e-9);
  EXPECT_NEAR(doors[0].b.x, 36.0, 1e-9);
  EXPECT_TRUE(DoorwayHypotheses(view, 2.0, 8.0, 15.0).empty()) << "16 apart: wider than a 15 bound";
  // Neither the end of a wall a policy added (no detections) nor a corner at the wall's end is a jamb.
  mapping::MapView added = ClosedRoom({});
  added.vertices.push_back({4, {20, 0.5}, {}, 7});
  added.vertices.push_back({5, {36, -0.3}, {}, 0});
  added.vertices.push_back({6, {1, 0.5}, {}, 7});
  EXPECT_TRUE(DoorwayHypotheses(added, 2.0, 8.0, 24.0).empty());
}

TEST(Doorways, APathLeadsThroughTheDoorwayOutOfASealedRoom) {
  const auto view = ClosedRoom({{20, 0.5}, {34, -0.5}});
  PlannerOptions o;
  o.inflation_radius = 2.0;
  o.clearance = 1.0;
  const Vec2 agent{27, 20}, goal{27, -30};
  EXPECT_FALSE(VisibilityGraph(view, o, false).Plan(agent, goal)) << "the room is sealed";
  const auto doors = DoorwayHypotheses(view, 2.0, 8.0, 16.0);
  ASSERT_EQ(doors.size(), 1u);
  const mapping::MapView open = WithDoorway(view, doors[0]);
  EXPECT_EQ(open.walls.size(), view.walls.size() + 1) << "the wall split in two around the doorway";
  const Path p = VisibilityGraph(open, o, false).Plan(agent, goal);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p.cost, 50.0, 1.0) << "straight down through the doorway";
}

TEST(Doorways, TheWallsBesideAnAgentOpenAtTheirNearestPointsWithinTheirEnds) {
  const auto view = ClosedRoom({});
  // 3 from the bottom wall, 5 from the left one, 37 from the top: two openings, each 8 wide.
  const auto near = OpeningsNear(view, view.walls.size(), {5, 3}, 8.0, 8.0);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_EQ(near[0].wall, 0);
  EXPECT_NEAR(near[0].a.x, 1.0, 1e-9) << "centred on the wall's point nearest the agent, (5, 0)";
  EXPECT_NEAR(near[0].b.x, 9.0, 1e-9);
  EXPECT_NEAR(near[0].a.y, 0.0, 1e-9);
  EXPECT_EQ(near[1].wall, 3);
  EXPECT_NEAR(near[1].middle().y, 4.0, 1e-9) << "moved up from (0, 3) so that the opening stays on the wall";
  EXPECT_NEAR(core::Distance(near[1].a, near[1].b), 8.0, 1e-9);
  EXPECT_EQ(OpeningsNear(view, 1, {5, 3}, 8.0, 8.0).size(), 1u) << "only the first walls (the map's own)";
  EXPECT_TRUE(OpeningsNear(view, view.walls.size(), {30, 20}, 8.0, 8.0).empty()) << "no wall within reach";
}

TEST(Doorways, AnOpeningIsFoundAgainOnTheWallThatStillRunsThroughItsEnds) {
  mapping::MapView view = ClosedRoom({});
  const Doorway opening{{20, 0.5}, {28, 0.5}, 0};
  std::swap(view.walls[0], view.walls[2]);  // the wall's index changed between views
  const auto again = Anchored(view, view.walls.size(), opening, 1.0);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->wall, 2);
  EXPECT_NEAR(again->a.y, 0.0, 1e-9) << "the ends put on the wall";
  EXPECT_FALSE(Anchored(view, 2, opening, 1.0)) << "only the first walls (the map's own) are searched";
  // The same wall the other way round: the ends follow it, so that WithDoorway opens the piece between them.
  std::swap(view.walls[2].pa, view.walls[2].pb);
  std::swap(view.walls[2].a, view.walls[2].b);
  const auto reversed = Anchored(view, view.walls.size(), opening, 1.0);
  ASSERT_TRUE(reversed);
  EXPECT_NEAR(reversed->a.x, 28.0, 1e-9);
  EXPECT_NEAR(reversed->b.x, 20.0, 1e-9);
  PlannerOptions o;
  o.inflation_radius = 2.0;
  o.clearance = 1.0;
  EXPECT_TRUE(VisibilityGraph(WithDoorway(view, *reversed), o, false).Plan({24, 20}, {24, -30}))
      << "a way out through the opening";
  view.walls[2].pa.y = view.walls[2].pb.y = -3;  // the wall moved away
  EXPECT_FALSE(Anchored(view, view.walls.size(), opening, 1.0));
}

}  // namespace
}  // namespace toponav::planning

#include "planning/internal/map_suspects.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

// A closed room [0, 60] x [0, 40] split by an inner wall x = 30 from y = 0 to 30 (both halves known and
// joined above it); 'rejected' vertices the posterior left out.  Nothing outside is known.
mapping::MapView SealedRoom(const std::vector<Vec2>& rejected) {
  mapping::MapView v;
  const std::vector<Vec2> c{{0, 0}, {60, 0}, {60, 40}, {0, 40}, {30, 0}, {30, 30}};
  for (size_t i = 0; i < c.size(); ++i) v.vertices.push_back({int(i), c[i], {}, 5});
  for (auto [a, b] : {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}})
    v.walls.push_back({a, b, c[size_t(a)], c[size_t(b)], 0.9});
  v.known_space.push_back({testing::Rect(0, 0, 60, 40), {}});
  for (size_t i = 0; i < rejected.size(); ++i) v.rejected.push_back({int(10 + i), rejected[i], {}, 6});
  return v;
}

PlannerOptions Options() {
  PlannerOptions o;
  o.inflation_radius = 2.0;
  o.clearance = 1.0;
  return o;
}

TEST(SuspectInspector, LooksFirstAtTheWallOnTheWayToTheGoal) {
  const auto view = SealedRoom({});
  const VisibilityGraph graph(view, Options(), false);
  SuspectInspector inspector(8.0, 5.0, 8.0);
  const Vec2 agent{10, 10}, goal{45, 80};  // beyond the top wall
  const FrontierChoice c = inspector.Choose(view, graph, agent, goal, {});
  ASSERT_EQ(c.status, PlanStatus::kFound);
  EXPECT_EQ(c.frontier_id, -1);
  EXPECT_GT(c.path.points.back().y, 40.0 - 5.0 - 1e-6) << "a lookout by the top wall";
  EXPECT_LT(c.path.points.back().y, 40.0) << "on the agent's side";
  // The same room with the goal to the left: the left wall.
  SuspectInspector left(8.0, 5.0, 8.0);
  EXPECT_LT(left.Choose(view, graph, agent, {-40, 20}, {}).path.points.back().x, 5.0 + 1e-6);
}

TEST(SuspectInspector, AWallBetweenTwoReachablePlacesIsNoSuspect) {
  // Everything suspect lies on the inner wall: both its sides are reachable, so no way would open there.
  const auto view = SealedRoom({{30, 15}});
  const VisibilityGraph graph(view, Options(), false);
  SuspectInspector inspector(8.0, 5.0, 8.0);
  const FrontierChoice c = inspector.Choose(view, graph, {45, 20}, {100, 15}, {});
  ASSERT_EQ(c.status, PlanStatus::kFound) << "the outer walls are still suspect";
  EXPECT_GT(c.path.points.back().x, 45.0) << "the right wall, nearest the goal";
  for (const auto& s : inspector.Suspects(view))
    EXPECT_FALSE(std::abs(s.x - 30.0) < 1e-9 && s.y > 0.5 && s.y < 35.0) << "the inner wall's points were dropped";
}

TEST(SuspectInspector, EachSuspectIsLookedAtOnce) {
  const auto view = SealedRoom({});
  const VisibilityGraph graph(view, Options(), false);
  SuspectInspector inspector(8.0, 5.0, 8.0);
  const Vec2 goal{100, 20};
  const size_t before = inspector.Suspects(view).size();
  ASSERT_GT(before, 0u);
  // Standing by the right wall's middle inspects the points within reach.
  const FrontierChoice c = inspector.Choose(view, graph, {56, 20}, goal, {});
  EXPECT_LT(inspector.Suspects(view).size(), before);
  ASSERT_EQ(c.status, PlanStatus::kFound);
  EXPECT_GT(core::Distance(c.path.points.back(), {60, 20}), 5.0 + 1e-6) << "not a lookout of the one inspected";
}

TEST(SuspectInspector, FrontiersAreWeighedWithTheSuspects) {
  mapping::MapView open;
  open.known_space.push_back({testing::Rect(0, 0, 60, 40), {}});
  const VisibilityGraph graph(open, Options(), false);
  SuspectInspector inspector(8.0, 5.0, 8.0);
  const std::vector<FrontierTarget> targets{{7, {10, 38}, 10.0, {0, 1}}, {8, {58, 20}, 10.0, {1, 0}}};
  EXPECT_EQ(inspector.Choose(open, graph, {30, 20}, {100, 20}, targets).frontier_id, 8);
  EXPECT_EQ(inspector.Choose(open, graph, {30, 20}, {10, 100}, targets).frontier_id, 7);
  EXPECT_EQ(inspector.Choose(open, graph, {30, 20}, {10, 100}, {}).status, PlanStatus::kNothingToExplore);
}

}  // namespace
}  // namespace toponav::planning

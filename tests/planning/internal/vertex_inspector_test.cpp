#include "planning/internal/vertex_inspector.h"

#include <gtest/gtest.h>

#include "tests/planning/internal/walled_over_opening.h"

#include "core/error.h"

namespace toponav::planning {
namespace {

using core::Vec2;

using testing::WalledOverOpening;

// Straight vertices within 0.3 rad, looked at from 10 units, reach 4, after 'looks' calls.
VertexInspectionOptions Straight(int looks) {
  VertexInspectionOptions o;
  o.max_bend = 0.3;
  o.standoff = 10.0;
  o.reach = 4.0;
  o.looks = looks;
  return o;
}

TEST(VertexInspector, AgentsAreSentToEachUninspectedVertexUntilOneHasLookedLongEnough) {
  const mapping::MapView view = WalledOverOpening();
  const VisibilityGraph graph(view, {}, false);
  VertexInspector inspector(Straight(2));
  std::vector<FrontierTarget> targets = inspector.Targets(view, graph, {{20, 20}});
  ASSERT_EQ(targets.size(), 2u);
  EXPECT_EQ(targets[0].frontier_id, VertexInspector::kIdBase - 1);
  EXPECT_TRUE(VertexInspector::IsInspection(targets[0].frontier_id));
  EXPECT_NEAR(targets[0].point.y, 50.0, 0.01);
  // An agent beside the first lookout: one look leaves it a target, the second makes it done, for good.
  EXPECT_EQ(inspector.Targets(view, graph, {{41, 48}}).size(), 2u);
  targets = inspector.Targets(view, graph, {{41, 48}});
  ASSERT_EQ(targets.size(), 1u);
  EXPECT_EQ(targets[0].frontier_id, VertexInspector::kIdBase - 2);
  EXPECT_EQ(inspector.inspected(), 1);
  EXPECT_EQ(inspector.targeted(), 2);
  EXPECT_EQ(inspector.Targets(view, graph, {{20, 20}}).size(), 1u);
}

TEST(VertexInspector, VerticesNoAgentCanGetToAreGivenUp) {
  mapping::MapView view = WalledOverOpening();
  AddWalls(&view, {{15, 15}, {25, 15}, {25, 25}, {15, 25}}, true);  // a box round the agent
  const VisibilityGraph graph(view, {}, false);
  VertexInspector inspector(Straight(1));
  EXPECT_TRUE(inspector.Targets(view, graph, {{20, 20}}).empty());
  EXPECT_EQ(inspector.inspected(), 2);
  VertexInspectionOptions nothing = Straight(1);
  nothing.max_bend = 0;  // and no unwalled vertices either
  EXPECT_THROW(VertexInspector{nothing}, core::InternalError);
  EXPECT_THROW(VertexInspector{Straight(0)}, core::InternalError);
}

TEST(VertexInspector, VerticesFartherThanTheRunHasLeftAreNotStartedFor) {
  const mapping::MapView view = WalledOverOpening();
  const VisibilityGraph graph(view, {}, false);
  const Vec2 agent{20, 20};
  std::vector<FrontierTarget> all = VertexInspector(Straight(1)).Targets(view, graph, {agent});
  ASSERT_EQ(all.size(), 2u);
  std::vector<double> cost;
  for (const auto& t : all) cost.push_back(graph.Plan(agent, t.point).cost);
  const size_t near = cost[0] < cost[1] ? 0 : 1;
  ASSERT_GT(cost[1 - near], cost[near] + 1.0);
  VertexInspector inspector(Straight(1));
  const std::vector<FrontierTarget> left = inspector.Targets(view, graph, {agent}, cost[near] + 0.5);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].frontier_id, all[near].frontier_id);
  EXPECT_EQ(inspector.inspected(), 1) << "the far vertex is done with";
  EXPECT_TRUE(inspector.Targets(view, graph, {agent}, 0.0).empty());
}

TEST(VertexInspector, AVertexGivenUpIsNoTargetAgain) {
  const mapping::MapView view = WalledOverOpening();
  const VisibilityGraph graph(view, {}, false);
  VertexInspector inspector(Straight(1));
  ASSERT_EQ(inspector.Targets(view, graph, {{20, 20}}).size(), 2u);
  inspector.GiveUp(VertexInspector::kIdBase - 2);  // e.g. the agent made no headway toward it
  const std::vector<FrontierTarget> left = inspector.Targets(view, graph, {{20, 20}});
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].frontier_id, VertexInspector::kIdBase - 1);
  EXPECT_EQ(inspector.inspected(), 1);
}

TEST(VertexInspector, TheCornersOfAHollowBuildingAreLookedAtFromOutside) {
  // Open known space round a 20 x 20 building whose corners are mapped without walls (hollow).
  mapping::MapView view;
  view.known_space.push_back({core::Ring{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}});
  const std::vector<Vec2> corners = {{40, 40}, {60, 40}, {60, 60}, {40, 60}};
  for (size_t i = 0; i < corners.size(); ++i) view.vertices.push_back({int(i), corners[i], {}, 10});
  const VisibilityGraph graph(view, {}, false);
  VertexInspectionOptions o;
  o.unwalled_detections = 5;
  o.unwalled_standoff = 14.0;
  VertexInspector inspector(o);
  const std::vector<FrontierTarget> targets = inspector.Targets(view, graph, {{40, 5}});
  ASSERT_EQ(targets.size(), 4u);
  for (size_t i = 0; i < targets.size(); ++i) {
    EXPECT_NEAR(core::Distance(targets[i].point, corners[i]), 14.0, 1e-9);
    EXPECT_GT(core::Distance(targets[i].point, {50, 50}), core::Distance(corners[i], {50, 50}))
        << "lookout " << i << " is outside the building";
  }
  EXPECT_NEAR(targets[0].point.x, 40.0, 1e-9)
      << "of (40, 40)'s lookouts (south, south-west, west) the southern one is nearest the agent";
  EXPECT_NEAR(targets[0].point.y, 26.0, 1e-9);
}

}  // namespace
}  // namespace toponav::planning

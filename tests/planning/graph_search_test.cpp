#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "planning/planning.h"

namespace toponav::planning {
namespace {

TEST(ShortestPath, FindsCheapestRouteNotFewestEdges) {
  Graph g(4);
  g.AddEdge(0, 3, 10.0);
  g.AddEdge(0, 1, 1.0);
  g.AddEdge(1, 2, 1.0);
  g.AddEdge(2, 3, 1.0);
  const GraphPath p = ShortestPath(g, 0, 3);
  ASSERT_TRUE(p);
  EXPECT_EQ(p.nodes, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_DOUBLE_EQ(p.cost, 3.0);
}

TEST(ShortestPath, DisconnectedTargetIsNoPathNotAMagicCost) {
  Graph g(3);
  g.AddEdge(0, 1, 1.0);
  const GraphPath p = ShortestPath(g, 0, 2);
  EXPECT_FALSE(p);
  EXPECT_EQ(p.status, PlanStatus::kNoPath);
  EXPECT_STREQ(ToString(p.status), "no_path");
  EXPECT_TRUE(std::isinf(ShortestCosts(g, 0)[2]));
}

TEST(ShortestPath, RejectsNegativeCostsAndUnknownNodes) {
  Graph g(2);
  EXPECT_THROW(g.AddEdge(0, 1, -1.0), core::InternalError);
  EXPECT_THROW(g.AddEdge(0, 5, 1.0), core::InternalError);
}

}  // namespace
}  // namespace toponav::planning

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

// Points on a line: the start at 0, nodes at 'xs'; costs are distances (infinity to and from 'cut').
void LineCosts(const std::vector<double>& xs, int cut, std::vector<double>* first,
               std::vector<std::vector<double>>* between) {
  const double inf = std::numeric_limits<double>::infinity();
  first->clear();
  between->assign(xs.size(), std::vector<double>(xs.size(), inf));
  for (size_t i = 0; i < xs.size(); ++i) {
    first->push_back(int(i) == cut ? inf : std::abs(xs[i]));
    for (size_t j = 0; j < xs.size(); ++j)
      if (int(i) != cut && int(j) != cut) (*between)[i][j] = std::abs(xs[i] - xs[j]);
  }
}

TEST(ShortestOpenTour, TakesTheShortSideFirstNotTheNearestNode) {
  // From 0: nodes at 1, 5 and -2.  Nearest first (1, 5, -2) costs 12, the tour (-2, 1, 5) 9.
  std::vector<double> first;
  std::vector<std::vector<double>> between;
  LineCosts({1, 5, -2}, -1, &first, &between);
  EXPECT_EQ(ShortestOpenTour(first, between), (std::vector<int>{2, 0, 1}));
  EXPECT_EQ(ShortestOpenTour(first, between, 0), (std::vector<int>{2, 0, 1})) << "nearest neighbour + 2-opt";
}

TEST(ShortestOpenTour, LeavesOutNodesTheStartCannotReach) {
  std::vector<double> first;
  std::vector<std::vector<double>> between;
  LineCosts({1, 5, -2, 3}, 1, &first, &between);
  EXPECT_EQ(ShortestOpenTour(first, between), (std::vector<int>{2, 0, 3}));
  EXPECT_EQ(ShortestOpenTour(first, between, 0).size(), 3u);
  LineCosts({4}, 0, &first, &between);
  EXPECT_TRUE(ShortestOpenTour(first, between).empty());
}

TEST(ShortestOpenTour, ExactAndHeuristicAgreeOnAGrid) {
  // Twelve nodes on a 4 x 3 grid, start beside a corner: both visit all, the exact tour is never longer.
  std::vector<std::pair<double, double>> p;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 3; ++y) p.push_back({10.0 * x, 10.0 * y});
  std::vector<double> first;
  std::vector<std::vector<double>> between(p.size(), std::vector<double>(p.size()));
  for (size_t i = 0; i < p.size(); ++i) {
    first.push_back(std::hypot(p[i].first + 5, p[i].second));
    for (size_t j = 0; j < p.size(); ++j)
      between[i][j] = std::hypot(p[i].first - p[j].first, p[i].second - p[j].second);
  }
  auto length = [&](const std::vector<int>& t) {
    double c = first[size_t(t[0])];
    for (size_t k = 1; k < t.size(); ++k) c += between[size_t(t[k - 1])][size_t(t[k])];
    return c;
  };
  const auto exact = ShortestOpenTour(first, between, 12), heuristic = ShortestOpenTour(first, between, 0);
  ASSERT_EQ(exact.size(), 12u);
  ASSERT_EQ(heuristic.size(), 12u);
  EXPECT_NEAR(length(exact), 5 + 11 * 10, 1e-9) << "a serpentine through every node";
  EXPECT_LE(length(exact), length(heuristic) + 1e-9);
}

}  // namespace
}  // namespace toponav::planning

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/geometry.h"
#include "core/rng.h"
#include "planning/subgoal_ordering.h"

namespace toponav::planning {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// n frontiers at random places on a 100 x 100 field: distances are Euclidean (so they obey the triangle
// inequality like real path costs), properties random in their ranges, some Ps exactly 0 or 1.
OrderingProblem RandomProblem(core::Rng& rng, int n) {
  OrderingProblem p;
  const core::Vec2 robot{rng.Uniform(0, 100), rng.Uniform(0, 100)}, goal{rng.Uniform(0, 100), rng.Uniform(0, 100)};
  std::vector<core::Vec2> at;
  for (int i = 0; i < n; ++i) at.push_back({rng.Uniform(0, 100), rng.Uniform(0, 100)});
  for (int i = 0; i < n; ++i) {
    const double u = rng.Uniform();
    const double ps = u < 0.1 ? 0.0 : u < 0.2 ? 1.0 : rng.Uniform();
    p.properties.push_back({ps, rng.Uniform(0, 80), rng.Uniform(0, 200)});
    p.robot_cost.push_back(core::Distance(robot, at[size_t(i)]));
    p.goal_cost.push_back(core::Distance(at[size_t(i)], goal));
    std::vector<double> row;
    for (int j = 0; j < n; ++j) row.push_back(core::Distance(at[size_t(i)], at[size_t(j)]));
    p.between.push_back(row);
  }
  return p;
}

TEST(SubgoalOrdering, CostOfAnOrderWeighsEachTryByTheChanceEveryEarlierOneFailed) {
  OrderingProblem p;
  p.properties = {{0.25, 4.0, 20.0}, {0.5, 0.0, 6.0}};
  p.robot_cost = {3.0, 7.0};
  p.goal_cost = {10.0, 12.0};
  p.between = {{0.0, 5.0}, {5.0, 0.0}};
  // 3 + 0.25 * 14 + 0.75 * 20, then 0.75 * (5 + 0.5 * 12 + 0.5 * 6)
  EXPECT_DOUBLE_EQ(OrderingCost(p, {0, 1}), 3 + 3.5 + 15 + 0.75 * (5 + 6 + 3));
  EXPECT_DOUBLE_EQ(OrderingCost(p, {1}), 7 + 6 + 3);
  EXPECT_THROW(OrderingCost(p, {2}), core::InternalError);
}

TEST(SubgoalOrdering, DynamicProgrammingEqualsEveryPermutationOn300RandomInstances) {
  core::Rng rng(8616);
  for (int trial = 0; trial < 300; ++trial) {
    const OrderingProblem p = RandomProblem(rng, 1 + trial % 8);
    const Ordering dp = BestOrdering(p), all = BestOrderingByEnumeration(p);
    ASSERT_EQ(dp.order.size(), size_t(p.size())) << "trial " << trial;
    EXPECT_NEAR(dp.cost, all.cost, 1e-9 * all.cost) << "trial " << trial;
    EXPECT_NEAR(OrderingCost(p, dp.order), dp.cost, 1e-9 * dp.cost) << "trial " << trial;
  }
}

TEST(SubgoalOrdering, ALikelyFrontierFartherAwayGoesBeforeANearDeadEnd) {
  OrderingProblem p;
  p.properties = {{0.05, 0.0, 100.0}, {0.95, 0.0, 100.0}};
  p.robot_cost = {5.0, 30.0};
  p.goal_cost = {40.0, 40.0};
  p.between = {{0.0, 35.0}, {35.0, 0.0}};
  EXPECT_EQ(BestOrdering(p).order, (std::vector<int>{1, 0}));
  // Certain success behind the near one: it goes first.
  p.properties[0].ps = 1.0;
  EXPECT_EQ(BestOrdering(p).order.front(), 0);
}

TEST(SubgoalOrdering, ClampedPutsEstimatesInTheirRanges) {
  const SubgoalProperties c = Clamped({1.7, -3.0, -0.5});
  EXPECT_EQ(c.ps, 1.0);
  EXPECT_EQ(c.delta_success, 0.0);
  EXPECT_EQ(c.exploration, 0.0);
  EXPECT_EQ(Clamped({-0.2, 5.0, 9.0}).ps, 0.0);
  const SubgoalProperties n = Clamped({std::nan(""), std::nan(""), 12.0});
  EXPECT_EQ(n.ps, 1.0);
  EXPECT_EQ(n.delta_success, 0.0);
  EXPECT_EQ(n.exploration, 12.0);
}

TEST(SubgoalOrdering, SelectionDropsUnreachableAndHopelessFrontiersThenKeepsCheapAndLikelyOnes) {
  core::Rng rng(3);
  OrderingProblem p = RandomProblem(rng, 8);
  for (auto& s : p.properties) s.ps = 0.5;
  p.robot_cost[2] = kInf;
  p.goal_cost[5] = kInf;
  p.properties[6].ps = 0.0;
  EXPECT_EQ(SelectFrontiers(p, 12), (std::vector<int>{0, 1, 3, 4, 7}));
  // At most 3: the 2 cheapest (optimistic cost), then the likeliest.
  for (int f : {0, 1, 3, 4, 7})
    p.robot_cost[size_t(f)] = 0.0, p.goal_cost[size_t(f)] = 10.0 * f, p.properties[size_t(f)].delta_success = 0;
  p.properties[7].ps = 0.9;
  EXPECT_EQ(SelectFrontiers(p, 3), (std::vector<int>{0, 1, 7}));
  const OrderingProblem r = Restrict(p, {0, 7});
  ASSERT_EQ(r.size(), 2);
  EXPECT_EQ(r.goal_cost[1], 70.0);
  EXPECT_EQ(r.between[0][1], p.between[0][7]);
}

TEST(SubgoalOrdering, TooManyFrontiersForTheExactTableIsAnError) {
  core::Rng rng(5);
  EXPECT_THROW(BestOrdering(RandomProblem(rng, kMaxExactFrontiers + 1)), core::InternalError);
  EXPECT_TRUE(BestOrdering(OrderingProblem{}).order.empty());
}

}  // namespace
}  // namespace toponav::planning

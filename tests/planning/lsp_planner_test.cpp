#include "planning/lsp_planner.h"

#include <gtest/gtest.h>

#include "planning/subgoal_grid.h"
#include "tests/planning/dead_end_view.h"
#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

// Returns fixed estimates (one per frontier, in the grid's order).
class FixedEstimator : public SubgoalEstimator {
 public:
  explicit FixedEstimator(std::vector<SubgoalProperties> p) : p_(std::move(p)) {}
  std::vector<SubgoalProperties> Estimate(const SubgoalGrid&, const OrderingProblem&) override { return p_; }

 private:
  std::vector<SubgoalProperties> p_;
};

PlannerOptions MazeOptions() {
  PlannerOptions o;
  o.frontier_row_gap = 10.0;  // below the 14-wide openings (configs/maze)
  return o;
}

struct Scene {
  core::World world = ::toponav::testing::DeadEndMaze();
  mapping::MapView view = testing::DeadEndSeenFromStart();
  PlannerOptions options = MazeOptions();
  std::vector<FrontierTarget> targets = FrontierTargets(view, options);
};

std::vector<FrontierChoice> PlanWith(Scene& s, std::unique_ptr<SubgoalEstimator> e,
                                     const Planner** planner_out = nullptr) {
  static std::unique_ptr<Planner> planner;
  planner = CreateLspPlanner(std::move(e), {}, s.options, s.world.bounds, "test");
  const VisibilityGraph graph(s.view, s.options, false);
  const PlanningProblem p{&s.view, &graph, &s.targets, {s.world.start.position()}, s.world.goal};
  if (planner_out) *planner_out = planner.get();
  return planner->Plan(p);
}

TEST(LspPlanner, TheOracleHeadsUpTheStemNotIntoTheDeadEndTheOptimisticPlannerTakes) {
  Scene s;
  ASSERT_EQ(s.targets.size(), 2u);
  const Planner* planner = nullptr;
  const auto oracle = PlanWith(s, CreateOracleEstimator(s.world, 1.0, 1.0), &planner);
  ASSERT_EQ(oracle[0].status, PlanStatus::kFound);
  EXPECT_EQ(oracle[0].frontier_id, 2);
  const LspDecision* d = LastDecision(*planner);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->frontier_ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(d->properties[0].ps, 0.0);
  EXPECT_EQ(d->order, (std::vector<int>{1})) << "the dead end (Ps 0) is not worth ordering";
  // The optimistic planner's straight way to the goal goes into the bottom corridor.
  const VisibilityGraph graph(s.view, s.options, false);
  const PlanningProblem p{&s.view, &graph, &s.targets, {s.world.start.position()}, s.world.goal};
  const auto optimistic = CreatePlanner(PlannerKind::kOptimistic)->Plan(p);
  ASSERT_EQ(optimistic[0].status, PlanStatus::kFound);
  EXPECT_LT(optimistic[0].path.points[1].y, 20.0) << "along the bottom corridor";
  EXPECT_GT(oracle[0].path.points[1].y, 20.0) << "up the stem";
}

TEST(LspPlanner, EstimatesOutsideTheirRangesAreClampedBeforeOrdering) {
  Scene s;
  const Planner* planner = nullptr;
  PlanWith(s, std::make_unique<FixedEstimator>(std::vector<SubgoalProperties>{{1.8, -20, -5}, {-0.3, 10, 10}}),
           &planner);
  const LspDecision* d = LastDecision(*planner);
  ASSERT_NE(d, nullptr);
  ASSERT_EQ(d->frontier_ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(d->order, (std::vector<int>{0})) << "Ps below 0 becomes 0: not worth ordering";
  EXPECT_EQ(d->properties[1].ps, 0.0);
  EXPECT_EQ(d->properties[0].ps, 1.0);
  EXPECT_EQ(d->properties[0].delta_success, 0.0);
  EXPECT_EQ(d->properties[0].exploration, 0.0);
  EXPECT_EQ(LastDecision(*CreatePlanner(PlannerKind::kOptimistic)), nullptr);
}

}  // namespace
}  // namespace toponav::planning

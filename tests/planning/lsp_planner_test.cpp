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

std::vector<int> Ids(const LspDecision& d) {
  std::vector<int> out;
  for (const auto& piece : d.pieces) out.push_back(piece.id);
  return out;
}

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
                                     const LspPlanner** planner_out = nullptr) {
  static std::unique_ptr<LspPlanner> planner;
  planner = CreateLspPlanner(std::move(e), {}, s.options, s.world.bounds, "test");
  const VisibilityGraph graph(s.view, s.options, false);
  const PlanningProblem p{&s.view, &graph, &s.targets, {s.world.start.position()}, s.world.goal};
  if (planner_out) *planner_out = planner.get();
  return planner->Plan(p);
}

TEST(LspPlanner, TheOracleHeadsUpTheStemNotIntoTheDeadEndTheOptimisticPlannerTakes) {
  Scene s;
  ASSERT_EQ(s.targets.size(), 2u);
  const LspPlanner* planner = nullptr;
  const auto oracle = PlanWith(s, CreateOracleEstimator(s.world, 1.0, 1.0), &planner);
  ASSERT_EQ(oracle[0].status, PlanStatus::kFound);
  EXPECT_EQ(oracle[0].frontier_id, 2);
  const LspDecision* d = &planner->decision();
  EXPECT_EQ(Ids(*d), (std::vector<int>{1, 2}));
  EXPECT_EQ(d->properties[0].ps, 0.0);
  EXPECT_EQ(d->order, (std::vector<int>{1})) << "the dead end (Ps 0) is not worth ordering";
  const std::vector<FrontierEstimate> e = Estimates(*d);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_FALSE(e[0].subgoal);
  EXPECT_TRUE(e[1].subgoal) << "the stem begins the order";
  EXPECT_EQ(e[1].frontier_id, 2);
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
  const LspPlanner* planner = nullptr;
  PlanWith(s, std::make_unique<FixedEstimator>(std::vector<SubgoalProperties>{{1.8, -20, -5}, {-0.3, 10, 10}}),
           &planner);
  const LspDecision* d = &planner->decision();
  ASSERT_EQ(Ids(*d), (std::vector<int>{1, 2}));
  EXPECT_EQ(d->order, (std::vector<int>{0})) << "Ps below 0 becomes 0: not worth ordering";
  EXPECT_EQ(d->properties[1].ps, 0.0);
  EXPECT_EQ(d->properties[0].ps, 1.0);
  EXPECT_EQ(d->properties[0].delta_success, 0.0);
  EXPECT_EQ(d->properties[0].exploration, 0.0);
}

TEST(LspPlanner, FrontierPiecesCutALongFrontierIntoEqualPiecesThatJoinUp) {
  mapping::Frontier f{7, {{0, 0}, {30, 0}, {30, 30}}, {30, 0}, 60.0, 0.4, 0.2};
  const std::vector<mapping::Frontier> pieces = FrontierPieces(f, 25.0);
  ASSERT_EQ(pieces.size(), 3u) << "60 long in pieces of at most 25: three of 20";
  for (size_t k = 0; k < pieces.size(); ++k) {
    EXPECT_EQ(pieces[k].id, 7);
    EXPECT_NEAR(pieces[k].length, 20.0, 1e-9);
    EXPECT_NEAR(core::PolylineLength(pieces[k].points), 20.0, 1e-9);
    if (k > 0) {
      EXPECT_NEAR(core::Distance(pieces[k - 1].points.back(), pieces[k].points.front()), 0.0, 1e-9);
    }
  }
  EXPECT_NEAR(core::Distance(pieces[0].points.front(), {0, 0}), 0.0, 1e-9);
  EXPECT_NEAR(core::Distance(pieces[1].midpoint, {30, 0}), 0.0, 1e-9) << "the middle piece turns the corner";
  EXPECT_NEAR(core::Distance(pieces[2].points.back(), {30, 30}), 0.0, 1e-9);
  EXPECT_EQ(pieces[0].front_turn, 0.4);
  EXPECT_EQ(pieces[0].back_turn, 0.0) << "a cut end is no turn";
  EXPECT_EQ(pieces[2].back_turn, 0.2);
  EXPECT_EQ(FrontierPieces(f, 0.0).size(), 1u) << "0: not cut";
  EXPECT_EQ(FrontierPieces(f, 60.0).size(), 1u);
}

// A room (known, 60 wide) whose whole top side is one frontier (from its right end): above its left end a
// corridor leads round to the goal; above the rest lies a closed pocket, which the straight way to the goal
// crosses.
TEST(LspPlanner, TheOracleCrossesALongFrontierWhereTheWayGoesOnNotWhereTheStraightLineMeetsIt) {
  Scene s;
  s.world.boundary = {{0, 0},   {60, 0},    {60, 40},   {22, 40},  {22, 20}, {14, 20},
                      {14, 60}, {120, 60}, {120, 0}, {134, 0}, {134, 74}, {0, 74}};
  s.world.start = {30, 10, 0};
  const Vec2 a{0, 0}, b{60, 0}, c{60, 20}, d{0, 20};
  s.view = {};
  s.view.known_space.push_back({{a, b, c, d}, {}});
  const std::vector<Vec2> corners{a, b, c, d};
  for (size_t i = 0; i < corners.size(); ++i) s.view.vertices.push_back({int(i), corners[i], {}, 5});
  for (auto [i, j] : {std::pair{3, 0}, {0, 1}, {1, 2}})
    s.view.walls.push_back({i, j, corners[size_t(i)], corners[size_t(j)], 0.9});
  s.view.frontiers.push_back({5, {a, Vec2{4, 0}}, {2, 0}, 4.0});  // a sliver, no target: pieces and targets differ
  s.view.frontiers.push_back({1, {c, d}, (c + d) * 0.5, 60.0});
  s.targets = FrontierTargets(s.view, s.options);
  ASSERT_EQ(s.targets.size(), 1u);
  const VisibilityGraph graph(s.view, s.options, false);
  const PlanningProblem p{&s.view, &graph, &s.targets, {s.world.start.position()}, s.world.goal};
  for (double piece_length : {0.0, LspOptions{}.piece_length}) {
    LspOptions o;
    o.piece_length = piece_length;
    const auto planner = CreateLspPlanner(CreateOracleEstimator(s.world, 1.0, 1.0), o, s.options, s.world.bounds, "t");
    const FrontierChoice choice = planner->Plan(p).at(0);
    ASSERT_EQ(choice.status, PlanStatus::kFound);
    EXPECT_EQ(choice.frontier_id, 1);
    const LspDecision* d = &planner->decision();
    ASSERT_GE(choice.path.points.size(), 2u);
    if (piece_length == 0) {
      EXPECT_GT(choice.path.points[1].x, 50.0) << "the whole frontier: over it by the pocket's corner";
    } else {
      ASSERT_GE(d->pieces.size(), 2u);
      EXPECT_EQ(d->properties.front().ps, 0.0) << "the piece by the pocket's corner opens on the closed pocket only";
      EXPECT_LT(choice.path.points[1].x, 25.0) << "in pieces: over the one the corridor goes on from";
    }
  }
}

}  // namespace
}  // namespace toponav::planning

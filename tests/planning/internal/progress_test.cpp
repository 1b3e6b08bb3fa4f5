#include "planning/internal/progress.h"

#include <gtest/gtest.h>

#include "planning/planner.h"
#include "core/error.h"
#include "tests/planning/open_square_view.h"

namespace toponav::planning {
namespace {

using core::Vec2;
using testing::OpenSquare;
using testing::Target;

FrontierChoice Choice(const VisibilityGraph& g, int id, Vec2 from, Vec2 to) {
  FrontierChoice c;
  c.status = PlanStatus::kFound;
  c.frontier_id = id;
  c.path = g.Plan(from, to);
  return c;
}

TEST(FrontierCommitment, AnAgentKeepsItsFrontierUnlessANewOneIsMuchCheaper) {
  const mapping::MapView view = OpenSquare();
  const VisibilityGraph g(view, {}, false);
  FrontierCommitment commitment(1, 1.5, 10.0);
  const Vec2 agent{50, 50};
  std::vector<FrontierTarget> targets{Target(1, {80, 50}), Target(2, {50, 75})};
  std::vector<FrontierChoice> choices{Choice(g, 1, agent, {80, 50})};
  commitment.Apply(g, targets, {agent}, &choices);
  EXPECT_EQ(commitment.committed(0), 1);
  // Frontier 2 (25 away) is now the planner's choice, frontier 1 costs 30 <= 1.5 * 25 + 10: it is kept.
  choices = {Choice(g, 2, agent, {50, 75})};
  commitment.Apply(g, targets, {agent}, &choices);
  EXPECT_EQ(choices[0].frontier_id, 1);
  EXPECT_NEAR(choices[0].path.cost, 30.0, 1e-9);
  // Frontier 2 at 5 away: 30 > 1.5 * 5 + 10, the agent switches (and commits to it).
  targets[1] = Target(2, {50, 55});
  choices = {Choice(g, 2, agent, {50, 55})};
  commitment.Apply(g, targets, {agent}, &choices);
  EXPECT_EQ(choices[0].frontier_id, 2);
  EXPECT_EQ(commitment.committed(0), 2);
  // A committed frontier that is no target any more is let go.
  choices = {Choice(g, 1, agent, {80, 50})};
  commitment.Apply(g, {Target(1, {80, 50})}, {agent}, &choices);
  EXPECT_EQ(choices[0].frontier_id, 1);
}

// Targets other than frontiers carry negative ids (the straight-vertex inspector's, -1000 and below); only
// -1 means "none".
TEST(FrontierCommitment, AnAgentKeepsATargetWithANegativeId) {
  const mapping::MapView view = OpenSquare();
  const VisibilityGraph g(view, {}, false);
  FrontierCommitment commitment(1, 1.5, 10.0);
  const Vec2 agent{50, 50};
  const std::vector<FrontierTarget> targets{Target(-1003, {80, 50}), Target(2, {50, 75})};
  std::vector<FrontierChoice> choices{Choice(g, -1003, agent, {80, 50})};
  commitment.Apply(g, targets, {agent}, &choices);
  EXPECT_EQ(commitment.committed(0), -1003);
  choices = {Choice(g, 2, agent, {50, 75})};
  commitment.Apply(g, targets, {agent}, &choices);
  EXPECT_EQ(choices[0].frontier_id, -1003);
}

TEST(FrontierCommitment, ATeamMateHoldingTheFrontierBreaksTheCommitment) {
  const mapping::MapView view = OpenSquare();
  const VisibilityGraph g(view, {}, false);
  FrontierCommitment commitment(2, 1.5, 10.0);
  const std::vector<Vec2> agents{{50, 50}, {70, 50}};
  const std::vector<FrontierTarget> targets{Target(1, {80, 50}), Target(2, {50, 75})};
  std::vector<FrontierChoice> choices{Choice(g, 1, agents[0], {80, 50}), Choice(g, 2, agents[1], {50, 75})};
  commitment.Apply(g, targets, agents, &choices);
  // The assignment swaps them: agent 1 now holds frontier 1, so agent 0 cannot keep it.
  choices = {Choice(g, 2, agents[0], {50, 75}), Choice(g, 1, agents[1], {80, 50})};
  commitment.Apply(g, targets, agents, &choices);
  EXPECT_EQ(choices[0].frontier_id, 2);
  EXPECT_EQ(choices[1].frontier_id, 1);
}

TEST(FrontierDwell, StandingAgentsNextToAFrontierGiveItUpAfterGiveUpSteps) {
  FrontierDwell dwell(4, 4.0);
  const std::vector<FrontierTarget> targets{Target(1, {10, 10}), Target(2, {40, 10})};
  const std::vector<Vec2> agents{{11, 10}};
  for (int step = 1; step <= 4; ++step) EXPECT_TRUE(dwell.CountStanding(targets, targets, agents, {1}).empty());
  EXPECT_EQ(dwell.CountStanding(targets, targets, agents, {1}), std::vector<size_t>{0}) << "the 5th step is over 4";
  EXPECT_EQ(dwell.steps(2), 0) << "frontier 2 is far from the agent";
  dwell.Reset(1);
  EXPECT_EQ(dwell.steps(1), 0);
  EXPECT_TRUE(dwell.CountStanding(targets, targets, agents, {0}).empty()) << "a walking agent does not count";
  EXPECT_EQ(dwell.steps(1), 0);
  // Near the target's point before it was pushed counts too.
  std::vector<FrontierTarget> pushed = targets;
  pushed[0].point = {30, 30};
  dwell.CountStanding(pushed, targets, agents, {1});
  EXPECT_EQ(dwell.steps(1), 1);
}

TEST(FrontierDwell, AnAgentStandsWhenItsLastStepWasUnderHalfAStep) {
  EXPECT_TRUE(FrontierDwell::Standing({{0, 0}}, 2.0)) << "not moved yet";
  EXPECT_TRUE(FrontierDwell::Standing({{0, 0}, {0.9, 0}}, 2.0));
  EXPECT_FALSE(FrontierDwell::Standing({{0, 0}, {1.1, 0}}, 2.0));
}

TEST(FrontierDwell, TargetsDweltAtPastHalfTheStepsArePushedThroughButNotOutOfTheRegion) {
  FrontierDwell dwell(4, 4.0);
  for (int k = 0; k < 3; ++k) dwell.Count(1);
  for (int k = 0; k < 2; ++k) dwell.Count(2);
  dwell.Count(3), dwell.Count(3), dwell.Count(3);
  std::vector<FrontierTarget> targets{Target(1, {10, 10}, {0, 1}), Target(2, {40, 10}, {0, 1}),
                                      Target(3, {50, 98}, {0, 1})};
  dwell.PushThrough(&targets, 8.0, core::Aabb2{{0, 0}, {100, 100}});
  EXPECT_EQ(targets[0].point, (Vec2{10, 18})) << "3 steps > 4 / 2: pushed along its outward normal";
  EXPECT_EQ(targets[1].point, (Vec2{40, 10})) << "2 steps: not yet";
  EXPECT_EQ(targets[2].point, (Vec2{50, 98})) << "pushing would leave the region";
  dwell.PushThrough(&targets, 8.0, std::nullopt);
  EXPECT_EQ(targets[2].point, (Vec2{50, 106})) << "no region: no limit";
}

TEST(FrontierDwell, APushedTargetLandsTheSameDistanceBeyondItsFrontierHoweverDeepItStood) {
  FrontierDwell dwell(4, 4.0);
  for (int k = 0; k < 3; ++k) dwell.Count(1), dwell.Count(2);
  std::vector<FrontierTarget> targets{Target(1, {10, 10}, {0, 1}), Target(2, {40, 3}, {0, 1})};
  targets[0].depth = 0.0;  // the frontier runs along y = 10
  targets[1].depth = 7.0;  // a target standing 7 back from its frontier along y = 10
  dwell.PushThrough(&targets, 6.0, std::nullopt);
  EXPECT_EQ(targets[0].point, (Vec2{10, 16}));
  EXPECT_EQ(targets[1].point, (Vec2{40, 16}));
}

TEST(StuckMonitor, NoHeadwayIsNoMotionOnAPathNoPathOrPacing) {
  const StuckMonitor m(1, 3, 2.0);
  const std::vector<Vec2> trail{{0, 0}, {2, 0}, {4, 0}, {6, 0}, {8, 0}, {10, 0}, {12, 0}};
  EXPECT_FALSE(m.NoHeadway(trail, true, false, {14, 0}, 2.0));
  EXPECT_TRUE(m.NoHeadway(trail, true, false, {12.1, 0}, 0.1)) << "a path but no motion";
  EXPECT_FALSE(m.NoHeadway(trail, false, false, {12, 0}, 0.0)) << "nothing to do: standing is fine";
  EXPECT_TRUE(m.NoHeadway(trail, false, true, {12, 0}, 0.0)) << "no path although there are targets";
  const std::vector<Vec2> pacing{{0, 0}, {2, 0}, {0, 0}, {2, 0}, {0, 0}, {2, 0}, {0, 0}};
  EXPECT_TRUE(m.NoHeadway(pacing, true, false, {1, 0}, 2.0)) << "back and forth: within a step of 6 steps ago";
}

TEST(StuckMonitor, AnAgentIsDueForANudgeAfterStuckStepsWithoutHeadway) {
  StuckMonitor m(2, 3, 2.0);
  EXPECT_FALSE(m.Record(0, true));
  EXPECT_FALSE(m.Record(0, true));
  EXPECT_FALSE(m.Record(1, true)) << "counted per agent";
  EXPECT_TRUE(m.Record(0, true));
  EXPECT_FALSE(m.Record(0, true)) << "the count restarts after a nudge";
  EXPECT_FALSE(m.Record(0, false));
  EXPECT_FALSE(m.Record(0, true)) << "a step with headway restarts it too";
  EXPECT_FALSE(m.Record(0, true));
  EXPECT_TRUE(m.Record(0, true));
}

TEST(PacedForthAndBack, TwoFullStepsForthAndBackArePacingSlowPressesAndWalkingOnAreNot) {
  // Steps of 2; the 7071 pattern: 1.7 forward, 1.5 back.
  EXPECT_TRUE(PacedForthAndBack({{0, 0}, {1.7, 0}}, {0.2, 0}, 2.0));
  EXPECT_FALSE(PacedForthAndBack({{0, 0}, {1.7, 0}}, {3.4, 0}, 2.0)) << "walking on";
  EXPECT_FALSE(PacedForthAndBack({{0, 0}, {1.7, 0}}, {0.2, 1.4}, 2.0)) << "back, but 1.4 to the side";
  EXPECT_FALSE(PacedForthAndBack({{0, 0}, {0.3, 0}}, {0.1, 0}, 2.0)) << "pressing with short steps";
  EXPECT_FALSE(PacedForthAndBack({{0, 0}, {1.7, 0}}, {1.2, 0}, 2.0)) << "a short step back";
  EXPECT_FALSE(PacedForthAndBack({{1.7, 0}}, {0, 0}, 2.0)) << "one step is no pacing yet";
  EXPECT_FALSE(PacedForthAndBack({}, {0, 0}, 2.0));
}

TEST(HeldInPlace, ALoopOfStepsAcrossLessThanTheSpanIsHeldWalkingOnAndShortTrailsAreNot) {
  // Steps of 1.8; the tuning maze 7367 pattern, five steps a loop: 1.8 out, 1.2 and 0.8 back, two presses.
  const std::vector<core::Vec2> loop{{0, 0}, {-0.7, 1.7}, {0, 0.8}, {0, 0}, {0, 0.04}};
  std::vector<core::Vec2> trail;
  for (int i = 0; i < 12; ++i) trail.push_back(loop[size_t(i) % loop.size()]);
  EXPECT_TRUE(HeldInPlace(trail, {-0.7, 1.7}, 12, 3.6));
  EXPECT_FALSE(HeldInPlace(trail, {-0.7, 1.7}, 13, 3.6)) << "a trail shorter than the window";
  EXPECT_FALSE(HeldInPlace(trail, {0, 4.0}, 12, 3.6)) << "this step left the loop";
  EXPECT_TRUE(HeldInPlace({{0, 0}, {0, 1}}, {0, 3.6}, 2, 3.6)) << "a distance equal to the span is within it";
  trail[0] = {4, 0};
  EXPECT_FALSE(HeldInPlace(trail, {-0.7, 1.7}, 12, 3.6)) << "the window's first position lies outside the span";
  EXPECT_TRUE(HeldInPlace(trail, {-0.7, 1.7}, 11, 3.6)) << "the window starts after it";
  std::vector<core::Vec2> walking;
  for (int i = 0; i < 12; ++i) walking.push_back({0.5 * i, 0});  // slow, but on its way
  EXPECT_FALSE(HeldInPlace(walking, {6.0, 0}, 12, 3.6));
}

TEST(RepeatedStep, TheThirdLapOfTheSameLoopRepeatsItsStepsWalkingBackAndStandingDoNot) {
  // A loop of six steps 5 units across (wider than HeldInPlace's two steps), each lap 0.01 off the one before,
  // as an agent pressing into a corner the map lacks walks it (simulated-sensor tuning maze 5769).
  const std::vector<core::Vec2> loop{{0, 0}, {1.8, 0}, {3.6, 0}, {5.0, 0.5}, {3.4, 1.2}, {1.6, 1.0}};
  std::vector<core::Vec2> trail{{-9, -9}, {-8, -8}, {-7, -7}};  // walking up to it
  for (int i = 0; i < 12; ++i) trail.push_back(loop[size_t(i) % 6] + core::Vec2{0.01 * (i / 6), 0});
  trail.push_back({0.02, 0});
  const core::Vec2 next{1.82, 0};  // the third lap's first step
  EXPECT_TRUE(RepeatedStep(trail, next, 24, 2, 0.09));
  EXPECT_TRUE(RepeatedStep(trail, next, 6, 2, 0.09)) << "a loop as long as the longest period";
  EXPECT_FALSE(RepeatedStep(trail, next, 5, 2, 0.09)) << "a loop longer than the longest period";
  EXPECT_FALSE(RepeatedStep(trail, next, 24, 3, 0.09)) << "no fourth lap yet";
  EXPECT_FALSE(RepeatedStep(trail, {1.82, 0.2}, 24, 2, 0.09)) << "ending 0.2 from where the laps' steps ended";
  std::vector<core::Vec2> detour = trail;
  detour[detour.size() - 6] = {0.5, -0.5};  // the second lap's first step went elsewhere
  EXPECT_TRUE(RepeatedStep(detour, next, 24, 1, 0.09)) << "it repeats the first lap's step";
  EXPECT_FALSE(RepeatedStep(detour, next, 24, 2, 0.09)) << "but not the second lap's";
  // Walking up a corridor and back down it the same way: the same positions, each step reversed.
  std::vector<core::Vec2> corridor;
  for (int i = 0; i <= 6; ++i) corridor.push_back({0, 1.8 * i});
  for (int i = 5; i > 0; --i) corridor.push_back({0, 1.8 * i});
  EXPECT_FALSE(RepeatedStep(corridor, {0, 0}, 24, 1, 0.09)) << "walking back";
  EXPECT_FALSE(RepeatedStep({{0, 0}, {0, 0}, {0, 0}}, {0, 0}, 24, 1, 0.09)) << "standing repeats no step";
  EXPECT_FALSE(RepeatedStep({}, {0, 0}, 24, 1, 0.09));
}


TEST(Planner, SearchPlannersAreTheNearestFrontierForOneAgentAndTheAssignmentForATeam) {
  const mapping::MapView view = OpenSquare();
  const VisibilityGraph g(view, {}, false);
  const std::vector<FrontierTarget> targets{Target(1, {80, 50}), Target(2, {55, 50})};
  PlanningProblem p{&view, &g, &targets, {{50, 50}}, std::nullopt};
  auto one = CreateSearchPlanner(1);
  EXPECT_EQ(one->name(), "nearest_frontier");
  EXPECT_EQ(one->Plan(p)[0].frontier_id, 2);
  auto team = CreateSearchPlanner(2);
  EXPECT_EQ(team->name(), "team_frontiers");
  p.agents = {{50, 50}, {52, 50}};
  const auto both = team->Plan(p);
  EXPECT_NE(both[0].frontier_id, both[1].frontier_id) << "a team spreads over distinct frontiers";
  p.agents = {{50, 50}, {52, 50}};
  const auto each = CreatePlanner(PlannerKind::kNearestFrontier)->Plan(p);
  EXPECT_EQ(each[0].frontier_id, each[1].frontier_id) << "each agent alone takes its nearest";
  const std::vector<FrontierTarget> none;
  p.targets = &none;
  EXPECT_EQ(one->Plan(p)[0].status, PlanStatus::kNothingToExplore);
}

TEST(Planner, OptimisticPlannerHeadsForTheGoalThroughUnknownSpaceAndNeedsAGoal) {
  const mapping::MapView view = OpenSquare();
  const VisibilityGraph g(view, {}, false);
  const std::vector<FrontierTarget> targets{Target(1, {80, 50})};
  PlanningProblem p{&view, &g, &targets, {{50, 50}}, std::nullopt};
  auto optimistic = CreatePlanner(PlannerKind::kOptimistic);
  EXPECT_EQ(optimistic->name(), "optimistic");
  EXPECT_THROW(optimistic->Plan(p), core::InternalError);
  p.goal = core::Vec2{50, 150};  // beyond the known square
  const auto c = optimistic->Plan(p);
  ASSERT_EQ(c.size(), 1u);
  ASSERT_EQ(c[0].status, PlanStatus::kFound);
  EXPECT_EQ(c[0].frontier_id, -1);
  EXPECT_NEAR(c[0].path.cost, 100.0, 1e-6) << "straight through unknown space";
}

}  // namespace
}  // namespace toponav::planning

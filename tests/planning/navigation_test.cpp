#include "planning/navigation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

// A hand-built map view: vertices (id = index), walls between listed pairs, known space = 'known' rings.
mapping::MapView View(const std::vector<Vec2>& vertices, const std::vector<std::pair<int, int>>& walls,
                      const std::vector<core::Ring>& known) {
  mapping::MapView v;
  for (size_t i = 0; i < vertices.size(); ++i) v.vertices.push_back({int(i), vertices[i], {}, 5});
  for (const auto& [a, b] : walls) v.walls.push_back({a, b, vertices[size_t(a)], vertices[size_t(b)], 0.9});
  for (const auto& r : known) v.known_space.push_back({r, {}});
  return v;
}

PlannerOptions Fine() {
  PlannerOptions o;
  o.inflation_radius = 0.1;
  o.clearance = 0.05;
  return o;
}

// vertexnav.md §8 test_noisy_navigation: around a wall (0,-1)-(0,1) from (-1,0) to (1,0).
TEST(VisibilityGraph, PathGoesAroundAWallEnd) {
  const auto view = View({{0, -1}, {0, 1}}, {{0, 1}}, {testing::Rect(-10, -10, 10, 10)});
  const VisibilityGraph g(view, Fine(), false);
  const Path p = g.Plan({-1, 0}, {1, 0});
  ASSERT_TRUE(p);
  EXPECT_GE(p.cost, 2 * std::sqrt(2.0));
  EXPECT_LE(p.cost, 2 * std::sqrt(2.0) + 0.25);
  for (size_t i = 1; i < p.points.size(); ++i) EXPECT_TRUE(g.Clear(p.points[i - 1], p.points[i]));
}

TEST(VisibilityGraph, LongerWallGivesLongerDetour) {
  const auto view = View({{0, -2}, {0, 1}, {0, 5}}, {{0, 1}, {1, 2}}, {testing::Rect(-10, -10, 10, 10)});
  const Path p = VisibilityGraph(view, Fine(), false).Plan({-1, 0}, {1, 0});
  ASSERT_TRUE(p);
  EXPECT_GE(p.cost, 2 * std::sqrt(5.0));
  EXPECT_LE(p.cost, 2 * std::sqrt(5.0) + 0.25);
}

TEST(VisibilityGraph, EmptyWorldPathIsStraight) {
  const auto view = View({}, {}, {testing::Rect(-20, -20, 20, 20)});
  const Path p = VisibilityGraph(view, Fine(), true).Plan({-5, 0}, {5, 0});
  ASSERT_TRUE(p);
  EXPECT_DOUBLE_EQ(p.cost, 10.0);
}

TEST(VisibilityGraph, ClosedWallMeansNoPathNotAMagicCost) {
  // A closed box around the goal.
  const auto view = View({{2, -2}, {6, -2}, {6, 2}, {2, 2}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
                         {testing::Rect(-10, -10, 10, 10)});
  const Path p = VisibilityGraph(view, Fine(), false).Plan({-5, 0}, {4, 0});
  EXPECT_FALSE(p);
  EXPECT_EQ(p.status, PlanStatus::kNoPath);
}

TEST(VisibilityGraph, AWayThroughAClosedBoxCrossesItsLeastCertainWallAtThePriceOfItsOdds) {
  // The box round the goal of ClosedWallMeansNoPathNotAMagicCost, its west wall (x = 2) less certain.
  auto view = View({{2, -2}, {6, -2}, {6, 2}, {2, 2}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
                   {testing::Rect(-10, -10, 10, 10)});
  view.walls[3].probability = 0.6;
  PlannerOptions o = Fine();
  o.wall_crossing_cost = 10.0;
  const Path p = VisibilityGraph(view, o, false).Plan({-5, 0}, {4, 0});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p.cost, 9.0 + 10.0 * 0.6 / 0.4, 1e-9) << "straight through the west wall: 9 long, price 15";
  const VisibilityGraph g(view, o, false);
  EXPECT_NEAR(g.Crossing({-5, 0}, {4, 0}, true, true), 15.0, 1e-9);
  EXPECT_FALSE(g.Clear({-5, 0}, {4, 0})) << "Clear: without crossing anything";
  o.wall_crossing_cost = 0.0;
  EXPECT_FALSE(VisibilityGraph(view, o, false).Plan({-5, 0}, {4, 0})) << "0: walls are never crossed";
}

TEST(VisibilityGraph, ACertainWallIsNeverCrossedAndADetourCheaperThanThePriceIsTaken) {
  PlannerOptions o = Fine();
  o.wall_crossing_cost = 10.0;
  mapping::MapView box = View({}, {}, {testing::Rect(-10, -10, 10, 10)});
  AddWalls(&box, {{2, -2}, {6, -2}, {6, 2}, {2, 2}}, /*closed=*/true);  // the planner's own walls: certain
  EXPECT_FALSE(VisibilityGraph(box, o, false).Plan({-5, 0}, {4, 0}));
  // A wall 2 long across the way, p 0.9 (price 90): going round its end costs about 2 * sqrt(2) - 2 more.
  const auto wall = View({{0, -1}, {0, 1}}, {{0, 1}}, {testing::Rect(-10, -10, 10, 10)});
  const Path p = VisibilityGraph(wall, o, false).Plan({-1, 0}, {1, 0});
  ASSERT_TRUE(p);
  EXPECT_LE(p.cost, 2 * std::sqrt(2.0) + 0.25) << "round, not through";
}

TEST(VisibilityGraph, AFreeStandingWallHasNodesToGoRoundItsEndsAPlainAddedWallHasNone) {
  // A motion block or a given-up frontier piece across the way: the way round it turns at one of its ends.
  // Walls added with AddWalls (a region's edge, masked frontiers) get no graph nodes, so a way that must turn
  // at their end is not found.
  const core::Segment2 wall{{0, -5}, {0, 5}};
  mapping::MapView free_standing = View({}, {}, {testing::Rect(-20, -20, 20, 20)});
  mapping::MapView plain = free_standing;
  AddFreeStandingWall(&free_standing, wall);
  AddWalls(&plain, {wall.a, wall.b});
  const Path round = VisibilityGraph(free_standing, Fine(), false).Plan({-1, 0}, {1, 0});
  ASSERT_TRUE(round);
  EXPECT_NEAR(round.cost, 2 * std::sqrt(26.0), 0.3);
  EXPECT_FALSE(VisibilityGraph(plain, Fine(), false).Plan({-1, 0}, {1, 0}));
}

TEST(VisibilityGraph, ExplorationStaysInKnownSpace) {
  // Known space is an L: the straight line from one arm to the other leaves it, so the path bends.
  const core::Ring L{{0, 0}, {10, 0}, {10, 2}, {2, 2}, {2, 10}, {0, 10}};
  const auto view = View({}, {}, {L});
  const Path known = VisibilityGraph(view, Fine(), true).Plan({9, 1}, {1, 9});
  const Path optimistic = VisibilityGraph(view, Fine(), false).Plan({9, 1}, {1, 9});
  ASSERT_TRUE(optimistic);
  EXPECT_NEAR(optimistic.cost, std::sqrt(128.0), 1e-9);
  // Exploration turns at the L's inner corner (a known-space corner, not a map vertex).
  ASSERT_TRUE(known);
  EXPECT_GT(known.cost, optimistic.cost + 1.0);
  EXPECT_LT(known.cost, 16.5);  // about 8 + 8 along the arms
  for (const auto& p : known.points) EXPECT_TRUE(core::Contains(L, p));
}

// A room [0,20]^2 with three openings (frontiers, 16 wide) on three sides.
mapping::MapView ThreeDoorRoom() {
  auto view = View({}, {}, {testing::Rect(0, 0, 20, 20)});
  view.frontiers = {{1, {{20, 2}, {20, 18}}, {20, 10}, 16.0}, {2, {{2, 20}, {18, 20}}, {10, 20}, 16.0},
                    {3, {{0, 18}, {0, 2}}, {0, 10}, 16.0}};
  return view;
}

TEST(Frontiers, TargetsLieInsideKnownSpace) {
  const auto view = ThreeDoorRoom();
  const auto targets = FrontierTargets(view, {});
  ASSERT_EQ(targets.size(), 3u);
  for (const auto& t : targets) EXPECT_TRUE(core::Contains(view.known_space[0], t.point));
  PlannerOptions strict;
  strict.frontier_min_length = 17.0;
  EXPECT_TRUE(FrontierTargets(view, strict).empty());
  PlannerOptions thin;
  thin.frontier_setback = 0.5;  // shallower than the 2-unit probe: exactly that deep
  EXPECT_NEAR(FrontierTargets(view, thin)[0].point.x, 19.5, 1e-12);
}

TEST(Frontiers, ATargetDeeperThanKnownSpaceStepsBackOnlyAsFarAsKnownSpaceGoes) {
  const auto view = ThreeDoorRoom();  // 20 wide: the frontier at x = 20 looks in from x = 0
  PlannerOptions deep;
  deep.frontier_setback = 30.0;  // deeper than the room: its half, 15, is the deepest point inside
  const auto targets = FrontierTargets(view, deep);
  ASSERT_EQ(targets.size(), 3u);
  EXPECT_NEAR(targets[0].point.x, 5.0, 1e-12);
  EXPECT_NEAR(targets[0].point.y, 10.0, 1e-12);
  EXPECT_NEAR(targets[0].outward.x, 1.0, 1e-12) << "outward still points out of the room";
}

TEST(Frontiers, ATargetNeverStepsBackAcrossAWall) {
  // A wall across the room at x = 10: known space goes on behind it, but a target there would be seen from
  // behind the wall; the deepest point on the frontier's side of it is the quarter, 20 - 7.5.
  auto view = ThreeDoorRoom();
  view.walls.push_back({-1, -1, {10, 1}, {10, 19}, 1.0});
  PlannerOptions deep;
  deep.frontier_setback = 30.0;
  EXPECT_NEAR(FrontierTargets(view, deep)[0].point.x, 12.5, 1e-12);
}

// A room [0,40]x[0,20] whose top side y = 20 is a frontier: the map has not accepted the wall there.
mapping::MapView RoomWithAnOpenTop(const std::vector<double>& candidates_at_x) {
  auto view = View({{0, 20}, {40, 20}}, {}, {testing::Rect(0, 0, 40, 20)});
  for (size_t i = 0; i < candidates_at_x.size(); ++i)
    view.rejected.push_back({int(10 + i), {candidates_at_x[i], 20.3}, {}, 3});  // seen, left out by the posterior
  view.frontiers = {{1, {{0, 20}, {40, 20}}, {20, 20}, 40.0}};
  return view;
}

TEST(Frontiers, AStraightFrontierBetweenTheEndsOfAWallChainClosesIt) {
  // A building seen on three sides: walls 0-1-2-3; its fourth side 3 -> 0 is a frontier.  Vertex 4 stands
  // apart (another building's corner).
  const auto view = View({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {30, 10}}, {{0, 1}, {1, 2}, {2, 3}}, {});
  auto frontier = [](std::vector<Vec2> points) { return mapping::Frontier{7, points, points[0], 10.0}; };
  EXPECT_TRUE(ClosesWallChain(frontier({{0, 10}, {0.3, 5}, {0, 0}}), view, {}));
  EXPECT_FALSE(ClosesWallChain(frontier({{0, 10}, {-4, 5}, {0, 0}}), view, {})) << "bent: not a straight side";
  EXPECT_FALSE(ClosesWallChain(frontier({{0, 10}, {30, 10}}), view, {})) << "to a vertex no wall joins";
  EXPECT_FALSE(ClosesWallChain(frontier({{0, 10}, {0, 4}}), view, {})) << "ends at no vertex";
  const auto skew = View({{0, 0}, {10, 0}, {10, 10}, {3, 10}}, {{0, 1}, {1, 2}, {2, 3}}, {});
  EXPECT_FALSE(ClosesWallChain(frontier({{3, 10}, {0, 0}}), skew, {})) << "not square to the walls at its ends";
  const auto triangle = View({{0, 0}, {10, 0}, {0, 10}}, {{0, 1}, {1, 2}}, {});
  EXPECT_FALSE(ClosesWallChain(frontier({{0, 10}, {0, 0}}), triangle, {})) << "a triangle is no building";
  const auto open = View({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{0, 1}, {2, 3}}, {});
  EXPECT_FALSE(ClosesWallChain(frontier({{0, 10}, {0, 0}}), open, {})) << "two walls apart: a gap between them";
}

TEST(Frontiers, AStraightFrontierAlongCloseDetectedVerticesIsAWall) {
  const PlannerOptions o;  // gaps up to 14, within 1 of the chord
  EXPECT_TRUE(FrontierTargets(RoomWithAnOpenTop({6, 13, 20, 27, 34}), o).empty()) << "candidates every 7 units";
  EXPECT_TRUE(AlongVertexRow(RoomWithAnOpenTop({12, 26}).frontiers[0], RoomWithAnOpenTop({12, 26}), o));
  // A gap wider than that in the row: an opening.
  EXPECT_EQ(FrontierTargets(RoomWithAnOpenTop({6, 13}), o).size(), 1u) << "13 .. 40 is 27 units";
  EXPECT_EQ(FrontierTargets(RoomWithAnOpenTop({}), o).size(), 1u);
  // Between two corners: a chord narrower than the gap is a wall, a corridor-wide one (here 16) an opening.
  auto chord = [](double width) {
    auto v = View({{0, 20}, {width, 20}}, {}, {testing::Rect(0, 0, width, 20)});
    v.frontiers = {{1, {{0, 20}, {width, 20}}, {width / 2, 20}, width}};
    return v;
  };
  EXPECT_TRUE(FrontierTargets(chord(12), o).empty());
  EXPECT_EQ(FrontierTargets(chord(16), o).size(), 1u);
  // Candidates off the line (behind the opening) do not count.
  auto behind = RoomWithAnOpenTop({});
  for (double x : {6.0, 13.0, 20.0, 27.0, 34.0}) behind.rejected.push_back({99, {x, 25.0}, {}, 3});
  EXPECT_EQ(FrontierTargets(behind, o).size(), 1u);
  // A bent frontier is no straight wall.
  auto bent = RoomWithAnOpenTop({6, 13, 20, 27, 34});
  bent.frontiers[0].points = {{0, 20}, {20, 24}, {40, 20}};
  EXPECT_EQ(FrontierTargets(bent, o).size(), 1u);
  PlannerOptions off;
  off.frontier_row_gap = 0;
  EXPECT_EQ(FrontierTargets(RoomWithAnOpenTop({6, 13, 20, 27, 34}), off).size(), 1u);
  EXPECT_EQ(FrontierTargets(chord(12), off).size(), 1u);
}

// A frontier cut from a longer chain where it turns gently ends where the opening goes on round the turn: that
// end bounds no row of vertices (a corridor mouth cut into short pieces at a bend keeps its targets).
TEST(Frontiers, AnEndCutAtAGentleTurnBoundsNoRow) {
  const PlannerOptions o;  // gaps up to 14
  auto piece = [](double front_turn) {  // 12 long, a vertex at its back end only
    auto v = View({{12, 20}}, {}, {testing::Rect(0, 0, 12, 20)});
    v.frontiers = {{1, {{0, 20}, {12, 20}}, {6, 20}, 12}};
    v.frontiers[0].front_turn = front_turn;
    return v;
  };
  EXPECT_TRUE(FrontierTargets(piece(0.0), o).empty()) << "a true end: a chord shorter than the gap";
  EXPECT_EQ(FrontierTargets(piece(0.5), o).size(), 1u) << "a gentle turn";
  EXPECT_TRUE(FrontierTargets(piece(2.0), o).empty()) << "a sharp turn (a notch in known space) bounds it";
  auto at_candidate = piece(0.5);
  at_candidate.rejected.push_back({99, {0.0, 20.0}, {}, 3});
  EXPECT_TRUE(FrontierTargets(at_candidate, o).empty()) << "a detected vertex at the cut bounds it";
}

TEST(Frontiers, SingleAgentGoesToTheNearest) {
  const auto view = ThreeDoorRoom();
  const VisibilityGraph g(view, {}, true);
  const auto choice = ChooseNearestFrontier(g, FrontierTargets(view, {}), {17, 10});
  ASSERT_EQ(choice.status, PlanStatus::kFound);
  EXPECT_EQ(choice.frontier_id, 1);
  EXPECT_EQ(ChooseNearestFrontier(g, {}, {17, 10}).status, PlanStatus::kNothingToExplore);
}

TEST(Frontiers, TeamNeverSharesAFrontierWhileEnoughExist) {
  const auto view = ThreeDoorRoom();
  const VisibilityGraph g(view, {}, true);
  const auto targets = FrontierTargets(view, {});
  // All three agents start together next to door 1: still three different doors.
  const auto choices = AssignFrontiers(g, targets, {{17, 10}, {17, 10.5}, {17, 9.5}});
  std::set<int> ids;
  for (const auto& c : choices) {
    ASSERT_EQ(c.status, PlanStatus::kFound);
    ids.insert(c.frontier_id);
  }
  EXPECT_EQ(ids.size(), 3u);
  // Two frontiers for three agents: both are covered, the third agent doubles up.
  const auto two = AssignFrontiers(g, {targets[0], targets[1]}, {{17, 10}, {10, 17}, {3, 10}});
  std::set<int> two_ids;
  for (const auto& c : two) {
    EXPECT_EQ(c.status, PlanStatus::kFound);
    two_ids.insert(c.frontier_id);
  }
  EXPECT_EQ(two_ids, (std::set<int>{1, 2}));
}

TEST(Frontiers, NoAgentIsLeftWithAnUnreachableFrontier) {
  // Four frontiers, two of them behind a closed wall: three agents, every one gets a reachable frontier.
  auto view = ThreeDoorRoom();
  const VisibilityGraph g(view, {}, true);
  auto targets = FrontierTargets(view, {});
  targets.push_back({7, {50, 50}, 10.0});  // outside known space: unreachable when exploring
  const auto choices = AssignFrontiers(g, targets, {{17, 10}, {17, 10.5}, {17, 9.5}, {10, 10}});
  for (const auto& c : choices) {
    EXPECT_EQ(c.status, PlanStatus::kFound);
    EXPECT_NE(c.frontier_id, 7);
  }
}

TEST(HSignature, ReverseCancelsAndALoopWindsOnce) {
  const std::vector<Vec2> obstacles{{0, 0}, {5, 5}};
  const std::vector<Vec2> seg{{-1, -1}, {1, -1}}, rev{{1, -1}, {-1, -1}};
  const auto h1 = HSignature(seg, obstacles), h2 = HSignature(rev, obstacles);
  for (size_t k = 0; k < obstacles.size(); ++k) EXPECT_NEAR(h1[k] + h2[k], 0.0, 1e-12);
  const std::vector<Vec2> loop{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}};
  const auto h = HSignature(loop, obstacles);
  EXPECT_NEAR(h[0], 2 * core::kPi, 1e-9);
  EXPECT_NEAR(h[1], 0.0, 1e-9);
  // Left and right around the obstacle at the origin: same ends, different classes.
  const auto left = HSignature({{-2, 0}, {0, 2}, {2, 0}}, {{0, 0}}),
             right = HSignature({{-2, 0}, {0, -2}, {2, 0}}, {{0, 0}});
  EXPECT_NEAR(std::abs(left[0] - right[0]), 2 * core::kPi, 1e-9);
}

}  // namespace
}  // namespace toponav::planning

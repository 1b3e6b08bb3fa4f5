#include "planning/search_navigator.h"

#include <gtest/gtest.h>

#include "tests/planning/one_agent_step.h"
#include "tests/testing/worlds.h"

namespace toponav::planning {
namespace {

using core::Vec2;

// A map of the west part of a closed world, known space up to x = 'east' and map walls all round it: past
// x = 60 the map's east wall is a false one across the world.
mapping::MapView WalledWest(double east) {
  mapping::MapView v;
  v.known_space.push_back({::toponav::testing::Rect(0, 0, east, 40), {}});
  const std::vector<Vec2> corners{{0, 0}, {east, 0}, {east, 40}, {0, 40}};
  for (int i = 0; i < 4; ++i) v.vertices.push_back({i, corners[size_t(i)], {}, 20});
  for (int i = 0; i < 4; ++i) v.walls.push_back({i, (i + 1) % 4, corners[size_t(i)], corners[size_t(i + 1) % 4], 0.9});
  return v;
}

struct PlanResult {
  bool goes_on = false;
  std::vector<Vec2> path;
  std::string end_reason;
  int frontier = 0;  // the agent's choice's frontier id
};

// One step of 'navigator' from (20, 20) on 'view'.
PlanResult PlanStep(SearchNavigator& navigator, const mapping::MapView& view) {
  testing::OneAgentStep step(view, {20, 20});
  NavigatorInput& state = step.input;
  state.max_steps = 400;
  std::vector<std::vector<Vec2>> paths(1);
  PlanResult r;
  navigator.on_plan = [&](const NavigatorInput&, const std::vector<FrontierTarget>&,
                          const std::vector<FrontierChoice>& choices) { r.frontier = choices[0].frontier_id; };
  r.goes_on = navigator.Plan(state, &paths);
  navigator.on_plan = nullptr;  // it refers to r
  r.path = paths[0];
  r.end_reason = navigator.end_reason();
  return r;
}

// One agent searching a closed world within 'bounds', no simulator linked.
SearchNavigatorSetup OneAgentIn(const core::Aabb2& bounds, const SearchOptions& search = {}) {
  SearchNavigatorSetup s;
  s.bounds = bounds;
  s.search = search;
  return s;
}

PlanResult PlanOnce(const core::Aabb2& bounds, const SearchOptions& search, const mapping::MapView& view) {
  SearchNavigator navigator(OneAgentIn(bounds, search));
  return PlanStep(navigator, view);
}

TEST(SearchNavigator, ASearchWhoseKnownSpaceStopsShortOfASideOfTheBoundsGoesToLookAtTheWallThatSealsIt) {
  const core::Aabb2 bounds{{0, 0}, {140, 40}};
  SearchOptions search;
  search.sealed_reach = 10;
  const PlanResult sealed = PlanOnce(bounds, search, WalledWest(60));
  ASSERT_TRUE(sealed.goes_on) << "no frontier is left, but the map has sealed the east of the world off";
  ASSERT_FALSE(sealed.path.empty());
  EXPECT_GT(sealed.path.back().x, 50.0) << "the false east wall (x = 60) is the suspect nearest the unreached side";
  EXPECT_LT(sealed.path.back().x, 60.0) << "looked at from the known side";

  const PlanResult off = PlanOnce(bounds, {}, WalledWest(60));
  EXPECT_FALSE(off.goes_on) << "without the key no frontier left means the search is over";
  EXPECT_EQ(off.end_reason, "explored");
  const PlanResult whole = PlanOnce(bounds, search, WalledWest(135));
  EXPECT_FALSE(whole.goes_on) << "known space within 10 units of every side: nothing is sealed off";
  EXPECT_EQ(whole.end_reason, "explored");
}

TEST(SearchNavigator, WhenASealedMapHasNothingElseLeftAFrontierAlongADroppedWallIsATargetAgain) {
  // The map held a false east wall at x = 60 for 12 steps, then dropped it: known space still ends on its line,
  // a frontier between two corners, which search.dropped_wall_steps takes for that wall.
  const core::Aabb2 bounds{{0, 0}, {140, 40}};
  mapping::MapView dropped = WalledWest(60);
  dropped.walls.erase(dropped.walls.begin() + 1);
  mapping::Frontier f;
  f.id = 7;
  f.points = {{60, 2}, {60, 38}};
  f.midpoint = {60, 20};
  f.length = 36;
  dropped.frontiers.push_back(f);
  for (const double reach : {0.0, 10.0}) {
    SearchOptions search;
    search.dropped_wall_steps = 10;
    search.sealed_reach = reach;
    SearchNavigator navigator(OneAgentIn(bounds, search));
    for (int step = 0; step < 12; ++step) PlanStep(navigator, WalledWest(60));
    const PlanResult r = PlanStep(navigator, dropped);
    if (reach == 0.0) {
      EXPECT_FALSE(r.goes_on) << "the frontier is taken for the dropped wall: nothing left";
      continue;
    }
    ASSERT_TRUE(r.goes_on) << "the map seals the east off: the frontier along the dropped wall is the way on";
    ASSERT_FALSE(r.path.empty());
    EXPECT_EQ(r.frontier, 7) << "heading for the frontier";
  }
}

}  // namespace
}  // namespace toponav::planning

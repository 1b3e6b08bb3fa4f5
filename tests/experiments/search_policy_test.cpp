#include "experiments/search_policy.h"

#include <gtest/gtest.h>

#include "tests/testing/worlds.h"

namespace toponav::experiments {
namespace {

using core::Vec2;

// A map of the west part of a closed world, known space up to x = 'east' and map walls all round it: past
// x = 60 the map's east wall is a false one across the world.
mapping::MapView WalledWest(double east) {
  mapping::MapView v;
  v.known_space.push_back({testing::Rect(0, 0, east, 40), {}});
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

// One step of 'policy' from (20, 20) on 'view'.
PlanResult PlanStep(SearchPolicy& policy, const core::World& w, const mapping::MapView& view) {
  const std::vector<std::vector<Vec2>> trails{{{20, 20}}};
  const std::vector<core::Observation> observations(1);
  LoopState state;
  state.max_steps = 400;
  state.world = &w;
  state.view = &view;
  state.poses = {{20, 20, 0}};
  state.observations = &observations;
  state.trails = &trails;
  state.step_length = 1.8;
  std::vector<std::vector<Vec2>> paths(1);
  PlanResult r;
  policy.on_plan = [&](const LoopState&, const std::vector<planning::FrontierTarget>&,
                       const std::vector<planning::FrontierChoice>& choices) { r.frontier = choices[0].frontier_id; };
  r.goes_on = policy.Plan(state, &paths);
  policy.on_plan = nullptr;  // it refers to r
  r.path = paths[0];
  r.end_reason = policy.end_reason();
  return r;
}

PlanResult PlanOnce(const core::World& w, const Config& config, const mapping::MapView& view) {
  SearchPolicy policy(w, config, 1);
  return PlanStep(policy, w, view);
}

TEST(SearchPolicy, ASearchWhoseKnownSpaceStopsShortOfASideOfTheBoundsGoesToLookAtTheWallThatSealsIt) {
  const core::World w = testing::RoomWorld(140, 40);
  Config config;
  config.search.sealed_reach = 10;
  const PlanResult sealed = PlanOnce(w, config, WalledWest(60));
  ASSERT_TRUE(sealed.goes_on) << "no frontier is left, but the map has sealed the east of the world off";
  ASSERT_FALSE(sealed.path.empty());
  EXPECT_GT(sealed.path.back().x, 50.0) << "the false east wall (x = 60) is the suspect nearest the unreached side";
  EXPECT_LT(sealed.path.back().x, 60.0) << "looked at from the known side";

  const Config defaults;  // a named Config: GCC 12 warns (falsely) of an uninitialized string in a temporary one
  const PlanResult off = PlanOnce(w, defaults, WalledWest(60));
  EXPECT_FALSE(off.goes_on) << "without the key no frontier left means the search is over";
  EXPECT_EQ(off.end_reason, "explored");
  const PlanResult whole = PlanOnce(w, config, WalledWest(135));
  EXPECT_FALSE(whole.goes_on) << "known space within 10 units of every side: nothing is sealed off";
  EXPECT_EQ(whole.end_reason, "explored");
}

TEST(SearchPolicy, WhenASealedMapHasNothingElseLeftAFrontierAlongADroppedWallIsATargetAgain) {
  // The map held a false east wall at x = 60 for 12 steps, then dropped it: known space still ends on its line,
  // a frontier between two corners, which search.dropped_wall_steps takes for that wall.
  const core::World w = testing::RoomWorld(140, 40);
  mapping::MapView dropped = WalledWest(60);
  dropped.walls.erase(dropped.walls.begin() + 1);
  mapping::Frontier f;
  f.id = 7;
  f.points = {{60, 2}, {60, 38}};
  f.midpoint = {60, 20};
  f.length = 36;
  dropped.frontiers.push_back(f);
  for (const double reach : {0.0, 10.0}) {
    Config config;
    config.search.dropped_wall_steps = 10;
    config.search.sealed_reach = reach;
    SearchPolicy policy(w, config, 1);
    for (int step = 0; step < 12; ++step) PlanStep(policy, w, WalledWest(60));
    const PlanResult r = PlanStep(policy, w, dropped);
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
}  // namespace toponav::experiments

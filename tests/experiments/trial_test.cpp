#include "experiments/trial.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "experiments/draw.h"
#include "sim/worlds.h"

namespace toponav::experiments {
namespace {

core::World SmallLabyrinth(uint64_t seed) {
  sim::LabyrinthOptions o;
  o.num_rooms = 2;
  o.grid_cells = 12;
  o.num_clutter = 10;
  return sim::GenerateLabyrinth(o, seed);
}

TEST(SearchTrial, SmallWorldIsFullyExploredByOneAndByThreeAgents) {
  const Config cfg;
  for (uint64_t seed : {101, 103}) {
    const core::World w = SmallLabyrinth(seed);
    for (int agents : {1, 3}) {
      TrialOptions o;
      o.num_agents = agents;
      const TrialResult r = RunSearchTrial(w, cfg, o, seed);
      EXPECT_TRUE(r.explored) << "seed " << seed << ", " << agents << " agents: " << r.end_reason;
      EXPECT_GT(r.iou, 0.95) << "seed " << seed << ", " << agents << " agents";
      EXPECT_TRUE(r.success);
      EXPECT_EQ(int(r.distance.size()), agents);
    }
  }
}

// Office park metric: a building counts as found when the known space encloses it; open ground the map has
// not seen does not count against it, and a building never walked around does.
TEST(BuildingPlacementIoU, CountsEnclosedBuildingsOnly) {
  core::World w;
  w.kind = core::WorldKind::kOfficePark;
  w.obstacles = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{40, 0}, {50, 0}, {50, 10}, {40, 10}}};
  w.bounds = core::Aabb2{{-20, -20}, {70, 30}};
  auto view_of = [](const std::vector<core::Polygon>& known) {
    mapping::MapView v;
    v.known_space = known;
    return v;
  };
  const core::Ring around_first{{-5, -5}, {15, -5}, {15, 15}, {-5, 15}};
  const core::Ring first{{0, 10}, {10, 10}, {10, 0}, {0, 0}};  // clockwise: a hole
  const core::Ring second{{40, 10}, {50, 10}, {50, 0}, {40, 0}};
  // Both buildings enclosed by known space, unknown ground all around the outside: a perfect score.
  EXPECT_NEAR(BuildingPlacementIoU(w, view_of({{{{-5, -5}, {55, -5}, {55, 15}, {-5, 15}}, {first, second}}})), 1.0, 1e-9);
  // Only the first one walked around: half the building area found.
  EXPECT_NEAR(BuildingPlacementIoU(w, view_of({{around_first, {first}}})), 0.5, 1e-9);
  // A spurious enclosed obstacle counts against it.
  const core::Ring spurious{{22, 8}, {28, 8}, {28, 2}, {22, 2}};
  EXPECT_NEAR(BuildingPlacementIoU(w, view_of({{{{-5, -5}, {55, -5}, {55, 15}, {-5, 15}}, {first, second, spurious}}})),
              200.0 / 236.0, 1e-9);
}

mapping::Frontier MakeFrontier(int id, std::vector<core::Vec2> points) {
  mapping::Frontier f;
  f.id = id;
  f.points = std::move(points);
  f.midpoint = (f.points.front() + f.points.back()) * 0.5;
  return f;
}

TEST(GivenUpFrontiers, TheSamePlaceUnderANewIdStaysGivenUp) {
  GivenUpFrontiers g(3.0);
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 10}}), MakeFrontier(5, {{20, 0}, {20, 10}})});
  EXPECT_TRUE(g.Contains(4));
  EXPECT_FALSE(g.Contains(5)) << "only the frontier named is given up";
  // The map re-creates the wall piece under id 9 (shifted by a unit); an opening 10 units away is new, and
  // so is a frontier that runs on past the given-up piece (an opening beside it) though its middle is close.
  g.Update({MakeFrontier(9, {{1, 2}, {1, 12}}), MakeFrontier(10, {{10, 0}, {10, 10}}),
            MakeFrontier(11, {{0, -8}, {0, 18}})});
  EXPECT_TRUE(g.Contains(9));
  EXPECT_FALSE(g.Contains(10));
  EXPECT_FALSE(g.Contains(11));
  GivenUpFrontiers by_id(0.0);
  by_id.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 10}})});
  by_id.Update({MakeFrontier(9, {{1, 2}, {1, 12}})});
  EXPECT_FALSE(by_id.Contains(9)) << "reach 0: by id only";
}

TEST(GivenUpFrontiers, OnlyThePartProbedOfALongFrontierStaysGivenUpByPlace) {
  // A 100-unit frontier along an unmapped wall, probed near its lower end (the agent stood at (1, 10)).
  GivenUpFrontiers g(3.0, 20.0);
  const core::Vec2 probed{1, 10};
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &probed);
  EXPECT_TRUE(g.Contains(4));
  // Later the map splits it: the piece where the agent stood stays given up, an opening at the far end
  // (never looked through) is a frontier again.
  g.Update({MakeFrontier(7, {{0, 5}, {0, 25}}), MakeFrontier(8, {{0, 70}, {0, 90}})});
  EXPECT_TRUE(g.Contains(7));
  EXPECT_FALSE(g.Contains(8));
  // Probed at its middle: only the middle stays given up; openings towards either end are frontiers again.
  GivenUpFrontiers middle(3.0, 20.0);
  const core::Vec2 at_middle{1, 50};
  middle.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &at_middle);
  middle.Update({MakeFrontier(7, {{0, 35}, {0, 65}}), MakeFrontier(8, {{0, 5}, {0, 25}}), MakeFrontier(9, {{0, 75}, {0, 95}})});
  EXPECT_TRUE(middle.Contains(7));
  EXPECT_FALSE(middle.Contains(8));
  EXPECT_FALSE(middle.Contains(9));
  // Without a probe radius the whole polyline counts.
  GivenUpFrontiers whole(3.0, 0.0);
  whole.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &probed);
  whole.Update({MakeFrontier(8, {{0, 70}, {0, 90}})});
  EXPECT_TRUE(whole.Contains(8));
}

TEST(GivenUpFrontiers, ProbingRecordsThePartNearThePointWithoutGivingTheFrontierUp) {
  GivenUpFrontiers g(3.0, 20.0);
  const core::Vec2 at{1, 50};
  g.Probe(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, at);
  EXPECT_FALSE(g.Contains(4));
  EXPECT_EQ(g.given_up(), 0);
  ASSERT_EQ(g.probed().size(), 1u);
  EXPECT_NEAR(g.probed()[0].a.y, 50.0 - std::sqrt(399.0), 1e-9);  // the part within 20 of (1, 50)
  EXPECT_NEAR(g.probed()[0].b.y, 50.0 + std::sqrt(399.0), 1e-9);
  g.Probe(5, {MakeFrontier(4, {{0, 0}, {0, 100}})}, at);  // no frontier 5 there: nothing recorded
  EXPECT_EQ(g.probed().size(), 1u);
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 100}})}, &at);
  EXPECT_TRUE(g.Contains(4));
  EXPECT_EQ(g.given_up(), 1);
}

TEST(GivenUpFrontiers, AFrontierThatGrowsWellPastWhereItWasGivenUpIsTakenBackOnce) {
  GivenUpFrontiers g(3.0, 20.0);
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 20}})});
  // Wobbling by a few units: still given up.
  EXPECT_TRUE(g.Update({MakeFrontier(4, {{2, -4}, {2, 24}})}).empty());
  EXPECT_TRUE(g.Contains(4));
  // Grown into a long opening under the same id: taken back.
  EXPECT_EQ(g.Update({MakeFrontier(4, {{0, 0}, {0, 75}})}), std::vector<int>{4});
  EXPECT_FALSE(g.Contains(4));
  // One given up by place (a new id where the probed part lay) is taken back when it grows, too.
  g.Update({MakeFrontier(6, {{1, 2}, {1, 18}})});
  EXPECT_TRUE(g.Contains(6));
  EXPECT_EQ(g.Update({MakeFrontier(6, {{1, 2}, {1, 60}})}), std::vector<int>{6});
  EXPECT_FALSE(g.Contains(6));
  // Given up again and grown again: it stays given up (no back and forth).
  g.GiveUp(4, {MakeFrontier(4, {{0, 0}, {0, 20}})});
  EXPECT_TRUE(g.Update({MakeFrontier(4, {{0, 0}, {0, 75}})}).empty());
  EXPECT_TRUE(g.Contains(4));
}

TEST(TrialVideo, HasOneFramePerStepAndTheFinalMap) {
  const Config cfg;
  const core::World w = SmallLabyrinth(101);
  const std::string path = (std::filesystem::temp_directory_path() / "toponav_trial_video_test.mp4").string();
  std::filesystem::remove(path);
  TrialOptions o;
  o.max_steps = 12;
  int frames = 0;
  {
    TrialVideo video(w, cfg.picture, path);
    o.on_step = [&](const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) { video.AddFrame(v, paths); };
    const TrialResult r = RunSearchTrial(w, cfg, o, 101);
    frames = video.frames();
    EXPECT_EQ(frames, r.steps + 1) << "one frame a step and the final map";
  }
  EXPECT_GT(frames, 0);
  EXPECT_GT(std::filesystem::file_size(path), 1000u);
  std::filesystem::remove(path);
}

TEST(TrialVideo, UnknownFormatIsAnErrorNamingTheFile) {
  const core::World w = SmallLabyrinth(101);
  try {
    TrialVideo video(w, {}, "/tmp/trial.gifx");
    FAIL() << "no error";
  } catch (const core::DataError& e) {
    EXPECT_NE(std::string(e.what()).find("/tmp/trial.gifx"), std::string::npos) << e.what();
  }
}

TEST(SearchTrial, SameSeedReproducesTheSameResult) {
  const Config cfg;
  const core::World w = SmallLabyrinth(102);
  TrialOptions o;
  o.num_agents = 3;
  o.max_steps = 60;
  const TrialResult a = RunSearchTrial(w, cfg, o, 7), b = RunSearchTrial(w, cfg, o, 7);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.iou, b.iou);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.paths, b.paths);
}

}  // namespace
}  // namespace toponav::experiments

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
  EXPECT_NEAR(BuildingPlacementIoU(w, view_of({{{{-5, -5}, {55, -5}, {55, 15}, {-5, 15}}, {first, second}}})), 1.0,
              1e-9);
  // Only the first one walked around: half the building area found.
  EXPECT_NEAR(BuildingPlacementIoU(w, view_of({{around_first, {first}}})), 0.5, 1e-9);
  // A spurious enclosed obstacle counts against it.
  const core::Ring spurious{{22, 8}, {28, 8}, {28, 2}, {22, 2}};
  EXPECT_NEAR(BuildingPlacementIoU(w, view_of({{{{-5, -5}, {55, -5}, {55, 15}, {-5, 15}}, {first, second, spurious}}})),
              200.0 / 236.0, 1e-9);
}

// The breakdown says which building the map got wrong and how much enclosed ground is no building.
TEST(BuildingPlacementIoU, BreakdownGivesEachBuildingsIoUAndTheSpuriousArea) {
  core::World w;
  w.kind = core::WorldKind::kOfficePark;
  w.obstacles = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{40, 0}, {50, 0}, {50, 10}, {40, 10}}};
  w.bounds = core::Aabb2{{-20, -20}, {70, 30}};
  mapping::MapView v;
  const core::Ring shifted{{0, 10}, {12, 10}, {12, 0}, {0, 0}};  // the first building 2 units too wide
  const core::Ring spurious{{22, 8}, {28, 8}, {28, 2}, {22, 2}};
  v.known_space = {{{{-5, -5}, {35, -5}, {35, 15}, {-5, 15}}, {shifted, spurious}}};
  const BuildingPlacementBreakdown b = BreakDownBuildingPlacement(w, v);
  ASSERT_EQ(b.building_iou.size(), 2u);
  EXPECT_NEAR(b.building_iou[0], 100.0 / 120.0, 1e-9);
  EXPECT_EQ(b.building_iou[1], 0.0) << "never enclosed";
  EXPECT_NEAR(b.spurious_area, 36.0, 1e-9);
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
    o.on_step = [&](const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) {
      video.AddFrame(v, paths);
    };
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

#include "experiments/world_checks.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"

#include "experiments/draw.h"
#include "sim/raycast.h"
#include "sim/worlds.h"
#include "tests/testing/worlds.h"

namespace toponav::experiments {
namespace {

TEST(WorldChecks, GeneratedWorldsPassTheirChecks) {
  const sim::WorldOptions o;
  for (auto kind : {core::WorldKind::kLabyrinth, core::WorldKind::kOfficePark, core::WorldKind::kGuidedMaze})
    for (uint64_t seed = 100; seed < 105; ++seed) {
      const auto problems = CheckWorld(sim::GenerateWorld(kind, o, seed), o);
      EXPECT_TRUE(problems.empty()) << core::ToString(kind) << " " << seed << ": " << problems.front();
    }
}

TEST(WorldChecks, DisconnectedFreeSpaceIsReported) {
  core::World w = testing::RoomWorld(30, 10);
  w.obstacles.push_back(testing::Rect(10, -1, 12, 11));  // a wall right across the room
  w.kind = core::WorldKind::kCustom;
  const auto s = ComputeWorldStats(w);
  EXPECT_EQ(s.free_components, 2);
  EXPECT_FALSE(CheckWorld(w, {}).empty());
}

TEST(WorldChecks, BuildingsTooCloseAreReported) {
  core::World w;
  w.kind = core::WorldKind::kOfficePark;
  w.obstacles = {testing::Rect(0, 0, 10, 10), testing::Rect(15, 0, 25, 10)};
  w.bounds = {{-30, -30}, {60, 60}};
  w.start = {-20, -20, 0};
  const auto problems = CheckWorld(w, {});
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("only 5"), std::string::npos) << problems.front();
}

TEST(Draw, WritesWorldAndObservationPictures) {
  const core::World w = sim::GenerateGuidedMaze({}, 1);
  const auto dir = std::filesystem::temp_directory_path() / "toponav_draw_test";
  std::filesystem::create_directories(dir);
  const std::string world_png = (dir / "world.png").string(), obs_png = (dir / "obs.png").string();
  DrawWorldPicture(w, {}, world_png);
  const sim::RayCaster rc(w);
  DrawObservationPicture(w, w.start, rc.VisibleVertices(w.start), rc.VisibilityPolygon(w.start.position()), {},
                         obs_png);
  EXPECT_GT(std::filesystem::file_size(world_png), 1000u);
  EXPECT_GT(std::filesystem::file_size(obs_png), 1000u);
  EXPECT_THROW(DrawWorldPicture(w, {}, "/nonexistent/dir/x.png"), core::DataError);
}

}  // namespace
}  // namespace toponav::experiments

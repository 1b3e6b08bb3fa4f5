#include "sim/world_io.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "sim/worlds.h"
#include "tests/testing/worlds.h"

namespace toponav::sim {
namespace {

std::string ErrorOf(const std::string& json) {
  try {
    WorldFromJson(json, "plan.json");
  } catch (const core::DataError& e) {
    return e.what();
  }
  return "";
}

TEST(WorldIo, RoundTripKeepsEveryField) {
  const core::World w = GenerateGuidedMaze({}, 3);
  const core::World back = WorldFromJson(WorldToJson(w), "mem");
  EXPECT_EQ(WorldToJson(back), WorldToJson(w));
  EXPECT_EQ(back.guide_path.size(), w.guide_path.size());
  const core::World lab = GenerateLabyrinth({}, 3);
  EXPECT_EQ(WorldToJson(WorldFromJson(WorldToJson(lab), "mem")), WorldToJson(lab));
}

TEST(WorldIo, HandWrittenFloorPlanWithClockwiseRingsIsNormalised) {
  const std::string plan = R"({
    "boundary": [[0,0],[0,30],[40,30],[40,0]],
    "obstacles": [[[10,10],[10,20],[20,20],[20,10]]],
    "clutter": [{"shape": "box", "center": [30, 5], "size": 1}],
    "start": {"x": 5, "y": 5},
    "goal": [35, 25]
  })";
  const core::World w = WorldFromJson(plan, "plan.json");
  EXPECT_GT(core::SignedArea(w.boundary), 0);
  EXPECT_GT(core::SignedArea(w.obstacles[0]), 0);
  EXPECT_EQ(w.kind, core::WorldKind::kCustom);
  EXPECT_EQ(w.clutter.size(), 1u);
  EXPECT_TRUE(w.bounds.Contains({40, 30}));
}

TEST(WorldIo, MissingKeyIsNamed) {
  const std::string e = ErrorOf(R"({"obstacles": [[[0,0],[1,0],[1,1]]], "goal": [5,5]})");
  EXPECT_NE(e.find("plan.json"), std::string::npos) << e;
  EXPECT_NE(e.find("start"), std::string::npos) << e;
  EXPECT_NE(e.find("missing key"), std::string::npos) << e;
}

TEST(WorldIo, SelfIntersectingPolygonIsNamed) {
  const std::string e = ErrorOf(
      R"({"obstacles": [[[0,0],[2,2],[2,0],[0,2]]], "start": {"x": -3, "y": -3}, "goal": [5,5]})");
  EXPECT_NE(e.find("obstacles[0]"), std::string::npos) << e;
  EXPECT_NE(e.find("self-intersecting"), std::string::npos) << e;
}

TEST(WorldIo, NonNumbersAndOverflowAreRejected) {
  EXPECT_NE(
      ErrorOf(R"({"obstacles": [[[0,0],[1,0],[1,NaN]]], "start": {"x":5,"y":5}, "goal":[1,1]})").find("plan.json"),
      std::string::npos);
  const std::string e = ErrorOf(R"({"obstacles": [[[0,0],[1,0],[1,"a"]]], "start": {"x":5,"y":5}, "goal":[1,1]})");
  EXPECT_NE(e.find("obstacles[0][2][1]"), std::string::npos) << e;
  const std::string big = ErrorOf(R"({"obstacles": [[[0,0],[1,0],[1,1e999]]], "start": {"x":5,"y":5}, "goal":[1,1]})");
  EXPECT_FALSE(big.empty());
}

TEST(WorldIo, ValidateRejectsNaNCoordinatesInWorldsBuiltInCode) {
  core::World w = testing::SquareWorld();
  w.obstacles[0][2].x = std::nan("");
  EXPECT_THROW(ValidateWorld(w, "code"), core::DataError);
}

TEST(WorldIo, UnknownKeyIsRejected) {
  const std::string e =
      ErrorOf(R"({"obstacles": [[[0,0],[1,0],[1,1]]], "start": {"x": 5, "y": 5}, "goal": [1,1], "clutterr": []})");
  EXPECT_NE(e.find("clutterr"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key"), std::string::npos) << e;
}

TEST(WorldIo, OverlappingOrEscapingObstaclesAreRejected) {
  const std::string overlap = ErrorOf(
      R"({"obstacles": [[[0,0],[4,0],[4,4],[0,4]], [[2,2],[6,2],[6,6],[2,6]]])"
      R"(, "start": {"x": -3, "y": -3}, "goal": [9,9]})");
  EXPECT_NE(overlap.find("overlap"), std::string::npos) << overlap;
  const std::string nested = ErrorOf(
      R"({"obstacles": [[[0,0],[10,0],[10,10],[0,10]], [[2,2],[4,2],[4,4],[2,4]]])"
      R"(, "start": {"x": -3, "y": -3}, "goal": [9,9]})");
  EXPECT_NE(nested.find("overlap"), std::string::npos) << nested;
  const std::string outside = ErrorOf(
      R"({"boundary": [[0,0],[20,0],[20,20],[0,20]], "obstacles": [[[15,15],[25,15],[25,25],[15,25]]])"
      R"(, "start": {"x": 5, "y": 5}, "goal": [9,9]})");
  EXPECT_NE(outside.find("inside the boundary"), std::string::npos) << outside;
}

TEST(WorldIo, StartInsideAnObstacleIsRejected) {
  const std::string e =
      ErrorOf(R"({"obstacles": [[[0,0],[4,0],[4,4],[0,4]]], "start": {"x": 2, "y": 2}, "goal": [9,9]})");
  EXPECT_NE(e.find("start"), std::string::npos) << e;
}

TEST(WorldIo, MissingFileIsADataErrorNamingThePath) {
  try {
    LoadWorld("/nonexistent/world.json");
    FAIL();
  } catch (const core::DataError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/world.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace toponav::sim

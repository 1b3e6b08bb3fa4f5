#include "experiments/map_json.h"

#include <gtest/gtest.h>

namespace toponav::experiments {
namespace {

mapping::MapView SquareRoomView() {
  mapping::MapView view;
  view.vertices = {{3, {0, 0}, {0.5, 0.1, 0.25}, 12}, {7, {10, 0}, {0.2, 0.0, 0.2}, 4}};
  view.rejected = {{9, {5, 5}, {1, 0, 1}, 2}};
  view.walls = {{3, 7, {0, 0}, {10, 0}, 0.9}};
  core::Polygon room;
  room.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  room.holes = {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}};
  view.known_space = {room};
  mapping::Frontier f;
  f.id = 21;
  f.points = {{10, 10}, {0, 10}};
  f.length = 10;
  view.frontiers = {f};
  return view;
}

TEST(MapJson, ListsEveryVertexWallKnownSpaceRingAndFrontierWithTheirCoordinates) {
  const nlohmann::json j = MapGeometryJson(SquareRoomView());
  ASSERT_EQ(j.at("vertices").size(), 2u);
  EXPECT_EQ(j["vertices"][1]["id"], 7);
  EXPECT_DOUBLE_EQ(j["vertices"][1]["x"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(j["vertices"][0]["cov"][1].get<double>(), 0.1);
  EXPECT_EQ(j["vertices"][0]["detections"], 12);
  ASSERT_EQ(j.at("rejected").size(), 1u);
  EXPECT_DOUBLE_EQ(j["rejected"][0]["y"].get<double>(), 5.0);
  ASSERT_EQ(j.at("walls").size(), 1u);
  EXPECT_EQ(j["walls"][0]["a"], 3);
  EXPECT_EQ(j["walls"][0]["b"], 7);
  EXPECT_DOUBLE_EQ(j["walls"][0]["to"][0].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(j["walls"][0]["probability"].get<double>(), 0.9);
  ASSERT_EQ(j.at("known_space").size(), 1u);
  EXPECT_EQ(j["known_space"][0]["outer"].size(), 4u);
  ASSERT_EQ(j["known_space"][0]["holes"].size(), 1u);
  EXPECT_DOUBLE_EQ(j["known_space"][0]["holes"][0][2][1].get<double>(), 6.0);
  ASSERT_EQ(j.at("frontiers").size(), 1u);
  EXPECT_EQ(j["frontiers"][0]["id"], 21);
  EXPECT_DOUBLE_EQ(j["frontiers"][0]["points"][1][1].get<double>(), 10.0);
}

TEST(MapJson, AnEmptyMapGivesEmptyListsNotNulls) {
  const nlohmann::json j = MapGeometryJson(mapping::MapView{});
  for (const char* key : {"vertices", "rejected", "walls", "known_space", "frontiers"}) {
    ASSERT_TRUE(j.at(key).is_array()) << key;
    EXPECT_TRUE(j.at(key).empty()) << key;
  }
}

}  // namespace
}  // namespace toponav::experiments

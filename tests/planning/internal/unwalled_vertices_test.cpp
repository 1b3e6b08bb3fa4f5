#include "planning/internal/unwalled_vertices.h"

#include <gtest/gtest.h>

#include <cmath>

namespace toponav::planning {
namespace {

using core::Vec2;

// Known space 100 x 100, through the building.  A building's south and east sides are mapped (vertices 0, 1
// and 7 with two walls); its north-east corner (2) is in the map without walls; the sensor kept detecting
// its north-west corner (3, 12 detections) and a point on the mapped wall (4), which the posterior rejected,
// and once a point far off (5, 2 detections).
mapping::MapView HalfMappedBuilding() {
  mapping::MapView v;
  v.known_space.push_back({core::Ring{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}});
  v.vertices = {{0, {40, 40}, {}, 20}, {1, {60, 40}, {}, 20}, {7, {60, 50}, {}, 20}, {2, {60, 60}, {}, 15}};
  v.walls = {{0, 1, {40, 40}, {60, 40}, 0.9}, {1, 7, {60, 40}, {60, 50}, 0.9}};
  v.rejected = {{3, {40, 60}, {}, 12}, {4, {50, 40.5}, {}, 30}, {5, {90, 90}, {}, 2}};
  return v;
}

const InspectionSite* Find(const std::vector<InspectionSite>& sites, int id) {
  for (const InspectionSite& s : sites)
    if (s.id == id) return &s;
  return nullptr;
}

TEST(UnwalledVertices, MapVerticesWithoutTwoWallsAndRejectedVerticesOffTheWallsAreFound) {
  const std::vector<InspectionSite> found = UnwalledVertices(HalfMappedBuilding(), 10, 14.0);
  ASSERT_EQ(found.size(), 4u);  // not 1 (two walls), 4 (on a wall) nor 5 (too few detections)
  EXPECT_NE(Find(found, 0), nullptr) << "one wall, known space all round: a hollow building's open chain";
  EXPECT_NE(Find(found, 7), nullptr) << "one wall, known space all round: a hollow building's open chain";
  EXPECT_NE(Find(found, 2), nullptr) << "no wall";
  EXPECT_NE(Find(found, 3), nullptr) << "rejected, 12 detections, off the walls";
  EXPECT_EQ(Find(found, 1), nullptr);
  EXPECT_EQ(UnwalledVertices(HalfMappedBuilding(), 13, 14.0).size(), 3u);
  EXPECT_EQ(UnwalledVertices(HalfMappedBuilding(), 2, 14.0).size(), 5u);
}

TEST(UnwalledVertices, AnOpenChainWithUnknownSpaceInsideIsNoHollowBuilding) {
  mapping::MapView v = HalfMappedBuilding();
  v.known_space[0].holes.push_back(core::Ring{{40, 40}, {40, 60}, {60, 60}, {60, 40}});
  const std::vector<InspectionSite> found = UnwalledVertices(v, 10, 14.0);
  EXPECT_EQ(Find(found, 0), nullptr) << "the building's inside is unknown: a side the search took for closed";
  EXPECT_EQ(Find(found, 7), nullptr);
  EXPECT_NE(Find(found, 2), nullptr) << "no wall at all";
  EXPECT_NE(Find(found, 3), nullptr);
}

TEST(UnwalledVertices, AClosedBuildingHasNone) {
  mapping::MapView v = HalfMappedBuilding();
  v.vertices.back() = {2, {40, 50}, {}, 15};
  v.walls.push_back({7, 2, {60, 50}, {40, 50}, 0.9});
  v.walls.push_back({2, 0, {40, 50}, {40, 40}, 0.9});
  v.rejected.clear();
  EXPECT_TRUE(UnwalledVertices(v, 10, 14.0).empty());
}

TEST(UnwalledVertices, LookoutsFaceTheVertexFromOutsideItsBuilding) {
  const std::vector<InspectionSite> found = UnwalledVertices(HalfMappedBuilding(), 10, 14.0);
  const InspectionSite* ne = Find(found, 2);
  ASSERT_NE(ne, nullptr);
  ASSERT_EQ(ne->lookouts.size(), 3u);
  // (60, 60): the map vertices within 45 units are (40, 40), (60, 40) and (60, 50), whose mean is
  // (53.3, 43.3), so out is up and to the right, and its lookouts turn 45 degrees either side of that.
  const Vec2 out = Vec2{20.0 / 3, 50.0 / 3} * (1.0 / std::hypot(20.0 / 3, 50.0 / 3));
  EXPECT_NEAR(ne->lookouts[1].x, 60 + 14 * out.x, 1e-9);
  EXPECT_NEAR(ne->lookouts[1].y, 60 + 14 * out.y, 1e-9);
  for (const Vec2& p : ne->lookouts) {
    EXPECT_NEAR(core::Distance(p, {60, 60}), 14.0, 1e-9);
    EXPECT_GT(p.y, 60.0 - 1e-9) << "never back into the building";
  }
  // Lookouts outside known space are dropped: a vertex near the known space's corner keeps none.
  mapping::MapView corner = HalfMappedBuilding();
  corner.vertices.push_back({6, {95, 95}, {}, 10});
  const auto near_edge = UnwalledVertices(corner, 10, 14.0);
  const InspectionSite* at_edge = Find(near_edge, 6);
  ASSERT_NE(at_edge, nullptr);
  EXPECT_TRUE(at_edge->lookouts.empty());
}

}  // namespace
}  // namespace toponav::planning

#include "planning/unwalled_vertices.h"

#include <gtest/gtest.h>

#include <cmath>

namespace toponav::planning {
namespace {

using core::Vec2;

// Known space 100 x 100.  A building's south side is mapped (vertices 0 and 1 with a wall); its north-east
// corner (2) is in the map without walls; the sensor kept detecting its north-west corner (3, 12
// detections) and a point on the mapped wall (4), which the posterior rejected, and once a point far off
// (5, 2 detections).
mapping::MapView HalfMappedBuilding() {
  mapping::MapView v;
  v.known_space.push_back({core::Ring{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}});
  v.vertices = {{0, {40, 40}, {}, 20}, {1, {60, 40}, {}, 20}, {2, {60, 60}, {}, 15}};
  v.walls = {{0, 1, {40, 40}, {60, 40}, 0.9}};
  v.rejected = {{3, {40, 60}, {}, 12}, {4, {50, 40.5}, {}, 30}, {5, {90, 90}, {}, 2}};
  return v;
}

TEST(UnwalledVertices, MapVerticesWithoutWallsAndRejectedVerticesOffTheWallsAreFound) {
  const std::vector<InspectionSite> found = UnwalledVertices(HalfMappedBuilding(), 10, 14.0);
  ASSERT_EQ(found.size(), 2u);  // not 0 and 1 (walled), 4 (on the wall) nor 5 (too few detections)
  EXPECT_EQ(found[0].id, 2);
  EXPECT_EQ(found[1].id, 3);
  EXPECT_EQ(UnwalledVertices(HalfMappedBuilding(), 13, 14.0).size(), 1u);
  EXPECT_EQ(UnwalledVertices(HalfMappedBuilding(), 2, 14.0).size(), 3u);
}

TEST(UnwalledVertices, LookoutsFaceTheVertexFromOutsideItsBuilding) {
  const std::vector<InspectionSite> found = UnwalledVertices(HalfMappedBuilding(), 10, 14.0);
  ASSERT_EQ(found[0].lookouts.size(), 3u);
  // (60, 60): the map vertices within 45 units are (40, 40) and (60, 40), whose mean is (50, 40), so out is
  // up and to the right, and its lookouts turn 45 degrees either side of that.
  const Vec2 out = Vec2{10, 20} * (1.0 / std::hypot(10.0, 20.0));
  EXPECT_NEAR(found[0].lookouts[1].x, 60 + 14 * out.x, 1e-9);
  EXPECT_NEAR(found[0].lookouts[1].y, 60 + 14 * out.y, 1e-9);
  for (const Vec2& p : found[0].lookouts) {
    EXPECT_NEAR(core::Distance(p, {60, 60}), 14.0, 1e-9);
    EXPECT_GT(p.y, 60.0 - 1e-9) << "never back into the building";
  }
  // Lookouts outside known space are dropped: a vertex near the known space's corner keeps none.
  mapping::MapView corner = HalfMappedBuilding();
  corner.vertices.push_back({6, {95, 95}, {}, 10});
  const auto near_edge = UnwalledVertices(corner, 10, 14.0);
  ASSERT_EQ(near_edge.size(), 3u);
  EXPECT_EQ(near_edge[1].id, 6);
  EXPECT_TRUE(near_edge[1].lookouts.empty());
}

}  // namespace
}  // namespace toponav::planning

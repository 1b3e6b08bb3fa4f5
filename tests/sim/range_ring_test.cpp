#include "sim/range_ring.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "sim/noisy_sensor.h"
#include "tests/testing/worlds.h"

namespace toponav::sim {
namespace {

TEST(RangeRing, AddsAFullTurnScanOfTheWallsInReachToTheVertexSensorsObservation) {
  const core::World w = testing::RoomWorld(60, 30);  // walls at x = 0, 60 and y = 0, 30
  RangeRingOptions o;
  o.rays = 8;
  o.range = 12.0;
  auto sensor = WithRangeRing(w, o, CreateNoisyGroundTruthSensor(w, {}, 7));
  const core::Pose2 pose{10, 8, 0.7};  // the heading does not turn the ring: ray j looks along 2 pi j / 8
  const core::Observation z = sensor->Observe(pose, 0);
  EXPECT_EQ(z.detections.size(), CreateNoisyGroundTruthSensor(w, {}, 7)->Observe(pose, 0).detections.size())
      << "the vertex sensor's detections, as without the ring";
  ASSERT_TRUE(z.scan.has_value());
  ASSERT_EQ(z.scan->ranges.size(), 8u);
  EXPECT_EQ(z.scan->max_range, 12.0);
  EXPECT_NEAR(z.scan->Angle(2), M_PI / 2, 1e-12);
  EXPECT_NEAR(z.scan->ranges[0], 12.0, 1e-6) << "east: the wall at x = 60 is out of reach";
  EXPECT_NEAR(z.scan->ranges[4], 10.0, 1e-3) << "west: the wall at x = 0";
  EXPECT_NEAR(z.scan->ranges[6], 8.0, 1e-3) << "south: the wall at y = 0";
  EXPECT_NEAR(z.scan->ranges[5], 8.0 * std::sqrt(2.0), 1e-3) << "south-west: the wall at y = 0, before x = 0";
  EXPECT_NEAR(z.scan->ranges[2], 12.0, 1e-6) << "north: the wall at y = 30 is 22 away";
}

TEST(RangeRing, ABadRayCountIsAConfigErrorNamingItsKey) {
  const core::World w = testing::RoomWorld(60, 30);
  RangeRingOptions o;
  o.rays = -1;
  try {
    WithRangeRing(w, o, CreateNoisyGroundTruthSensor(w, {}, 7));
    ADD_FAILURE() << "no error";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "sensor.range_ring.rays");
  }
}

}  // namespace
}  // namespace toponav::sim

#include "experiments/sensor_factory.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "experiments/config.h"
#include "sim/worlds.h"

namespace toponav::experiments {
namespace {

TEST(SensorFactory, TheNoisyKindIsTheSimulatedSensorWithItsOptionsAndSeed) {
  const core::World w = sim::GenerateLabyrinth({}, 3);
  SensorConfig config;
  config.noisy.miss_probability = 0.3;
  auto made = CreateSensor(config, {&w, {}, std::nullopt, 77});
  auto direct = sim::CreateNoisyGroundTruthSensor(w, config.noisy, 77);
  for (int k = 0; k < 5; ++k) {
    const core::Pose2 pose{w.start.x, w.start.y, 0.3 * k};
    const core::Observation a = made->Observe(pose, 0), b = direct->Observe(pose, 0);
    ASSERT_EQ(a.detections.size(), b.detections.size());
    for (size_t i = 0; i < a.detections.size(); ++i) {
      EXPECT_EQ(a.detections[i].range, b.detections[i].range);
      EXPECT_EQ(a.detections[i].bearing, b.detections[i].bearing);
    }
  }
}

TEST(SensorFactory, KindsAreReadByNameAndAnUnknownKindIsAConfigErrorNamingTheKey) {
  EXPECT_EQ(ParseConfig("", "x.yaml").sensor.kind, SensorKind::kNoisy);
  const Config c = ParseConfig("sensor:\n  kind: noisy\n  miss_probability: 0.25\n", "x.yaml");
  EXPECT_EQ(c.sensor.kind, SensorKind::kNoisy);
  EXPECT_DOUBLE_EQ(c.sensor.noisy.miss_probability, 0.25);
  try {
    ParseConfig("sensor:\n  kind: lidar\n", "configs/bad.yaml");
    ADD_FAILURE() << "no error";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.file(), "configs/bad.yaml");
    EXPECT_EQ(e.key(), "sensor.kind");
    EXPECT_EQ(e.value(), "lidar");
    EXPECT_NE(std::string(e.what()).find("noisy"), std::string::npos) << "the message lists the known kinds";
  }
  EXPECT_EQ(ParseSensorKind("noisy"), SensorKind::kNoisy);
  EXPECT_FALSE(ParseSensorKind("Noisy"));
  EXPECT_EQ(SensorKindNames(), std::vector<std::string>{"noisy"});
}

TEST(SensorFactory, BadOptionsAreRejectedWhenTheSensorIsMade) {
  const core::World w = sim::GenerateLabyrinth({}, 3);
  SensorConfig config;
  config.noisy.max_range = -1;
  EXPECT_THROW(CreateSensor(config, {&w, {}, std::nullopt, 1}), core::ConfigError);
}

}  // namespace
}  // namespace toponav::experiments

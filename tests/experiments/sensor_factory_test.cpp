#include "experiments/sensor_factory.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "core/error.h"
#include "experiments/trial.h"
#include "learning/mirror_average.h"
#include "learning/peaks.h"
#include "learning/vertex_model.h"
#include "sim/render.h"
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
  EXPECT_EQ(SensorKindNames(), (std::vector<std::string>{"noisy", "learned", "recorded"}));
}

TEST(SensorFactory, BadOptionsAreRejectedWhenTheSensorIsMade) {
  const core::World w = sim::GenerateLabyrinth({}, 3);
  SensorConfig config;
  config.noisy.max_range = -1;
  EXPECT_THROW(CreateSensor(config, {&w, {}, std::nullopt, 1}), core::ConfigError);
}

TEST(SensorFactory, TheLearnedKindRunsTheModelOnTheRenderedPanorama) {
  const std::string model =
      (std::filesystem::temp_directory_path() / ("toponav_sf_" + std::to_string(::getpid()) + ".pt")).string();
  learning::VertexNetOptions tiny;
  tiny.width = 0.125;
  learning::VertexModel(tiny, 5).Save(model);
  const Config c = ParseConfig("sensor:\n  kind: learned\n  model: " + model + "\n  threshold: 0.3\n", "x.yaml");
  EXPECT_EQ(c.sensor.kind, SensorKind::kLearned);
  EXPECT_DOUBLE_EQ(c.sensor.learned.threshold, 0.3);
  const core::World w = sim::GenerateLabyrinth({}, 3);
  auto sensor = CreateSensor(c.sensor, {&w, {}, std::nullopt, 1});
  const core::Observation z = sensor->Observe(w.start, 1);
  EXPECT_EQ(z.agent, 1);
  EXPECT_EQ(z.pose.x, w.start.x);
  // The untrained network's output, decoded: what the factory's sensor reports is what the model predicts.
  const learning::VertexModel m = learning::VertexModel::Load(model);
  const learning::GridOutput out = m.Predict(sim::Renderer(w, {}).Render(w.start));
  learning::DecodeOptions decode;
  decode.threshold = 0.3f;
  EXPECT_EQ(z.detections.size(), learning::DecodeDetections(out.vertex, out.labels, out.grid, decode).size());
  for (size_t i = 1; i < z.detections.size(); ++i) EXPECT_LE(z.detections[i - 1].bearing, z.detections[i].bearing);
  // A trial runs with it (a few steps).
  TrialOptions t;
  t.max_steps = 3;
  EXPECT_EQ(RunSearchTrial(w, c, t, 7).steps, 3);
  std::filesystem::remove(model);
}

TEST(SensorFactory, MirrorAveragingDecodesTheMeanOfThePlainAndTheMirroredBackOutputs) {
  const Config c = ParseConfig("sensor:\n  kind: learned\n  model: " TOPONAV_SOURCE_DIR
                               "/models/vertex_net_cpu.pt\n  mirror_average: true\n", "x.yaml");
  EXPECT_TRUE(c.sensor.learned.mirror_average);
  EXPECT_FALSE(ParseConfig("sensor:\n  kind: learned\n  model: m.pt\n", "x.yaml").sensor.learned.mirror_average)
      << "off by default";
  const core::World w = sim::GenerateLabyrinth({}, 3);
  const core::Observation z = CreateSensor(c.sensor, {&w, {}, std::nullopt, 1})->Observe(w.start, 0);
  const learning::VertexModel m = learning::VertexModel::Load(c.sensor.learned.model);
  const core::Panorama image = sim::Renderer(w, {}).Render(w.start);
  const learning::GridOutput plain = m.Predict(image);
  const learning::GridOutput mean =
      learning::Mean(plain, learning::MirroredBack(m.Predict(learning::MirroredPanorama(image))));
  learning::DecodeOptions decode;
  decode.sigma_range = c.sensor.learned.sigma_range;
  decode.sigma_bearing = c.sensor.learned.sigma_bearing;
  const auto want = learning::DecodeDetections(mean.vertex, mean.labels, mean.grid, decode);
  ASSERT_EQ(z.detections.size(), want.size());
  ASSERT_GT(want.size(), 3u);
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(z.detections[i].bearing, want[i].bearing);
    EXPECT_EQ(z.detections[i].range, want[i].range);
    EXPECT_FLOAT_EQ(z.detections[i].labels[1], want[i].labels[1]);
  }
  const auto alone = learning::DecodeDetections(plain.vertex, plain.labels, plain.grid, decode);
  bool differs = alone.size() != want.size();
  for (size_t i = 0; i < want.size() && !differs; ++i) differs = alone[i].labels[1] != want[i].labels[1];
  EXPECT_TRUE(differs) << "the mirrored pass changes what is reported";
}

TEST(SensorFactory, ASubgoalModelBesideTheVertexModelFillsTheCellsAndLeavesTheVerticesToIt) {
  const auto temp = [](const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("toponav_sf2_" + std::to_string(::getpid()) + name)).string();
  };
  const std::string vertex = temp("_v.pt"), subgoal = temp("_s.pt");
  learning::VertexNetOptions tiny;
  tiny.width = 0.125;
  learning::VertexModel(tiny, 5).Save(vertex);
  tiny.subgoal = true;
  learning::VertexModel(tiny, 6).Save(subgoal);
  const Config c = ParseConfig("sensor:\n  kind: learned\n  model: " + vertex + "\n  subgoal_model: " + subgoal +
                               "\n  threshold: 0.3\n", "x.yaml");
  EXPECT_EQ(c.sensor.learned.subgoal_model, subgoal);
  const core::World w = sim::GenerateLabyrinth({}, 3);
  SensorSetup setup{&w, {}, std::nullopt, 1};
  setup.goal_at_agent = true;
  const core::Observation z = CreateSensor(c.sensor, setup)->Observe(w.start, 0);
  EXPECT_FALSE(z.subgoal.empty()) << "the subgoal model's outputs";
  const learning::GridOutput out = learning::VertexModel::Load(vertex).Predict(sim::Renderer(w, {}).Render(w.start));
  learning::DecodeOptions decode;
  decode.threshold = 0.3f;
  EXPECT_EQ(z.detections.size(), learning::DecodeDetections(out.vertex, out.labels, out.grid, decode).size())
      << "the vertex model's detections";
  EXPECT_TRUE(CreateSensor(c.sensor, {&w, {}, std::nullopt, 1})->Observe(w.start, 0).subgoal.empty()) << "no goal";
  // A vertex network named as the subgoal model is an error naming its file.
  SensorConfig swapped = c.sensor;
  swapped.learned.subgoal_model = vertex;
  try {
    CreateSensor(swapped, setup);
    ADD_FAILURE() << "no error";
  } catch (const core::DataError& e) {
    EXPECT_NE(std::string(e.what()).find(vertex), std::string::npos) << e.what();
  }
  std::filesystem::remove(vertex);
  std::filesystem::remove(subgoal);
}

TEST(SensorFactory, TheLearnedKindNeedsAReadableModelAndOnlyItsOwnKeys) {
  auto key_of = [](const std::string& yaml) {
    try {
      ParseConfig(yaml, "x.yaml");
    } catch (const core::ConfigError& e) {
      return e.key();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(key_of("sensor:\n  kind: learned\n"), "sensor.model");
  EXPECT_EQ(key_of("sensor:\n  kind: learned\n  model: m.pt\n  miss_probability: 0.1\n"), "sensor.miss_probability")
      << "a noisy-sensor key with kind learned";
  EXPECT_EQ(key_of("sensor:\n  model: m.pt\n"), "sensor.model") << "a learned-sensor key with kind noisy";
  SensorConfig missing;
  missing.kind = SensorKind::kLearned;
  missing.learned.model = "/no/such/model.pt";
  const core::World w = sim::GenerateLabyrinth({}, 3);
  try {
    CreateSensor(missing, {&w, {}, std::nullopt, 1});
    ADD_FAILURE() << "no error";
  } catch (const core::DataError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/model.pt"), std::string::npos);
  }
}

}  // namespace
}  // namespace toponav::experiments

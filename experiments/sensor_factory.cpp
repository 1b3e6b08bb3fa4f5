#include "experiments/sensor_factory.h"

#include <fmt/core.h>

#include "core/error.h"
#include "experiments/recorded.h"
#include "learning/learned_detector.h"
#include "learning/learning.h"
#include "sim/rendering_sensor.h"

namespace toponav::experiments {

namespace {
constexpr SensorKind kKinds[] = {SensorKind::kNoisy, SensorKind::kLearned, SensorKind::kRecorded};
}  // namespace

const char* ToString(SensorKind kind) {
  switch (kind) {
    case SensorKind::kNoisy: return "noisy";
    case SensorKind::kLearned: return "learned";
    case SensorKind::kRecorded: return "recorded";
  }
  return "?";
}

std::optional<SensorKind> ParseSensorKind(const std::string& name) {
  for (SensorKind k : kKinds)
    if (name == ToString(k)) return k;
  return std::nullopt;
}

std::vector<std::string> SensorKindNames() {
  std::vector<std::string> out;
  for (SensorKind k : kKinds) out.push_back(ToString(k));
  return out;
}

const core::OptionFields<LearnedSensorOptions>& LearnedSensorOptions::Fields() {
  using O = LearnedSensorOptions;
  static const core::OptionFields<O> fields{
      {"threshold", &O::threshold, 0.01, 0.99},
      {"sigma_range", &O::sigma_range, 0.01, 100.0},
      {"sigma_bearing", &O::sigma_bearing, 1e-4, 3.0},
      {"threads", &O::threads, 0, 256},
      {"mirror_average", &O::mirror_average},
  };
  return fields;
}

std::string SensorsUsed(const SensorConfig& config) {
  return std::string(ToString(config.kind)) + (config.range_ring.enabled() ? "+range_ring" : "");
}

void SensorConfig::Validate() const {
  core::CheckRanges(range_ring, sim::RangeRingOptions::Fields(), "sensor.range_ring.");
  if (kind == SensorKind::kRecorded && range_ring.enabled())
    throw core::ConfigError("<options>", "sensor.range_ring.rays", std::to_string(range_ring.rays),
                            "a recording has no range ring's scans (set 0)");
  if (kind == SensorKind::kNoisy) noisy.Validate();
  if (kind == SensorKind::kNoisy) return;
  core::CheckRanges(learned, LearnedSensorOptions::Fields(), "sensor.");
  if (learned.model.empty())
    throw core::ConfigError("<options>", "sensor.model", "", fmt::format("kind {} needs a model file", ToString(kind)));
  if (kind == SensorKind::kRecorded && images.empty())
    throw core::ConfigError("<options>", "sensor.images", "", "kind recorded needs the recording's folder");
}

namespace {

std::unique_ptr<core::VertexDetectorInterface> LearnedDetector(const LearnedSensorOptions& o) {
  learning::DecodeOptions decode;
  decode.threshold = float(o.threshold);
  decode.sigma_range = o.sigma_range;
  decode.sigma_bearing = o.sigma_bearing;
  decode.sub_bin = o.sub_bin;
  learning::SelectBackend(false, o.threads);
  return learning::CreateLearnedDetector(o.model, decode, o.subgoal_model, o.mirror_average);
}

std::unique_ptr<core::VertexSensorInterface> VertexSensor(const SensorConfig& config, const SensorSetup& setup) {
  switch (config.kind) {
    case SensorKind::kNoisy: return sim::CreateNoisyGroundTruthSensor(*setup.world, config.noisy, setup.seed);
    case SensorKind::kLearned:
      return sim::CreateRenderingSensor(*setup.world, setup.render, LearnedDetector(config.learned), setup.goal,
                                        setup.goal_at_agent);
    case SensorKind::kRecorded:
      return CreateRecordedSensor(ReadRecording(config.images, config.poses), LearnedDetector(config.learned));
  }
  core::ThrowInternal(__FILE__, __LINE__, "unhandled sensor kind");
}

}  // namespace

std::unique_ptr<core::VertexSensorInterface> CreateSensor(const SensorConfig& config, const SensorSetup& setup) {
  config.Validate();
  TOPONAV_CHECK(setup.world != nullptr || config.kind == SensorKind::kRecorded,
                "a " << ToString(config.kind) << " sensor needs a world");
  std::unique_ptr<core::VertexSensorInterface> sensor = VertexSensor(config, setup);
  if (!config.range_ring.enabled()) return sensor;
  return sim::WithRangeRing(*setup.world, config.range_ring, std::move(sensor));
}

}  // namespace toponav::experiments

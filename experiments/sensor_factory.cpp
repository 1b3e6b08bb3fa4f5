#include "experiments/sensor_factory.h"

#include "core/error.h"
#include "learning/learned_detector.h"
#include "learning/learning.h"
#include "sim/rendering_sensor.h"

namespace toponav::experiments {

namespace {
constexpr SensorKind kKinds[] = {SensorKind::kNoisy, SensorKind::kLearned};
}  // namespace

const char* ToString(SensorKind kind) {
  switch (kind) {
    case SensorKind::kNoisy: return "noisy";
    case SensorKind::kLearned: return "learned";
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
  };
  return fields;
}

void SensorConfig::Validate() const {
  if (kind == SensorKind::kNoisy) noisy.Validate();
  if (kind != SensorKind::kLearned) return;
  core::CheckRanges(learned, LearnedSensorOptions::Fields(), "sensor.");
  if (learned.model.empty()) throw core::ConfigError("<options>", "sensor.model", "", "kind learned needs a model file");
}

std::unique_ptr<core::VertexSensorInterface> CreateSensor(const SensorConfig& config, const SensorSetup& setup) {
  TOPONAV_CHECK(setup.world != nullptr, "a sensor needs a world");
  config.Validate();
  switch (config.kind) {
    case SensorKind::kNoisy: return sim::CreateNoisyGroundTruthSensor(*setup.world, config.noisy, setup.seed);
    case SensorKind::kLearned: {
      learning::DecodeOptions decode;
      decode.threshold = float(config.learned.threshold);
      decode.sigma_range = config.learned.sigma_range;
      decode.sigma_bearing = config.learned.sigma_bearing;
      learning::SelectBackend(false, config.learned.threads);
      return sim::CreateRenderingSensor(*setup.world, setup.render, learning::CreateLearnedDetector(config.learned.model, decode),
                                        setup.goal);
    }
  }
  core::ThrowInternal(__FILE__, __LINE__, "unhandled sensor kind");
}

}  // namespace toponav::experiments

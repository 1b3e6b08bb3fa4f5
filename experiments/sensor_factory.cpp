#include "experiments/sensor_factory.h"

#include "core/error.h"

namespace toponav::experiments {

namespace {
constexpr SensorKind kKinds[] = {SensorKind::kNoisy};
}  // namespace

const char* ToString(SensorKind kind) {
  switch (kind) {
    case SensorKind::kNoisy: return "noisy";
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

void SensorConfig::Validate() const {
  if (kind == SensorKind::kNoisy) noisy.Validate();
}

std::unique_ptr<core::VertexSensorInterface> CreateSensor(const SensorConfig& config, const SensorSetup& setup) {
  TOPONAV_CHECK(setup.world != nullptr, "a sensor needs a world");
  config.Validate();
  switch (config.kind) {
    case SensorKind::kNoisy: return sim::CreateNoisyGroundTruthSensor(*setup.world, config.noisy, setup.seed);
  }
  core::ThrowInternal(__FILE__, __LINE__, "unhandled sensor kind");
}

}  // namespace toponav::experiments

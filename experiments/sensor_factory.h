#pragma once
// The sensor factory: the one place that builds the sensor a config asks for (`sensor: {kind: ..., ...}`),
// so the agent loop runs unchanged with any of them.  Kinds so far:
//   noisy: the simulated vertex sensor on the ray-cast ground truth (sim::NoisySensorOptions keys).
// Image-based kinds (a learned network, a folder of recorded panoramas) are detectors composed with the
// renderer (sim::CreateRenderingSensor) or with the recorded images; they are built here too, and this is
// the only file of the experiments layer that may include the learning layer.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/observation.h"
#include "core/world.h"
#include "sim/noisy_sensor.h"
#include "sim/render.h"

namespace toponav::experiments {

enum class SensorKind { kNoisy };
const char* ToString(SensorKind kind);                       // "noisy"
std::optional<SensorKind> ParseSensorKind(const std::string& name);
std::vector<std::string> SensorKindNames();

// YAML section `sensor:`.
struct SensorConfig {
  SensorKind kind = SensorKind::kNoisy;
  sim::NoisySensorOptions noisy;  // kind noisy: its keys sit beside `kind`
  void Validate() const;          // throws core::ConfigError ("sensor.max_range", ...)
};

// What the sensor is for: the world it observes (and renders), the render options of image-based kinds, the
// goal of goal-directed runs (passed to goal-conditioned detectors), and the seed of its randomness.
struct SensorSetup {
  const core::World* world = nullptr;
  sim::RenderOptions render;
  std::optional<core::Vec2> goal;
  uint64_t seed = 0;
};

std::unique_ptr<core::VertexSensorInterface> CreateSensor(const SensorConfig& config, const SensorSetup& setup);

}  // namespace toponav::experiments

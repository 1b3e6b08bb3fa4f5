#pragma once
// The sensor factory: the one place that builds the sensor a config asks for (`sensor: {kind: ..., ...}`),
// so the agent loop runs unchanged with any of them.  Kinds:
//   noisy:   the simulated vertex sensor on the ray-cast ground truth (sim::NoisySensorOptions keys);
//   learned: the vertex network of a model file (`model: PATH`) on the rendered panorama (LearnedSensorOptions);
//   recorded: the same network on the panoramas of a recording (`images: DIR`, experiments/recorded.h), which
//             answers only at the recorded poses and needs no world.
// Beside any kind but recorded, `range_ring: {rays, range}` adds a range ring's scans (sim/range_ring.h).
// Image-based kinds are detectors composed with the renderer (sim::CreateRenderingSensor); this is the only
// file of the experiments layer that includes the learning layer.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/observation.h"
#include "core/option_fields.h"
#include "core/world.h"
#include "sim/noisy_sensor.h"
#include "sim/range_ring.h"
#include "sim/render.h"

namespace toponav::experiments {

enum class SensorKind { kNoisy, kLearned, kRecorded };
const char* ToString(SensorKind kind);                       // "noisy", "learned", "recorded"
std::optional<SensorKind> ParseSensorKind(const std::string& name);
std::vector<std::string> SensorKindNames();

// The learned sensor's keys (beside `kind: learned`).
struct LearnedSensorOptions {
  std::string model;             // a model file written by `toponav train`
  std::string subgoal_model;     // optional: a subgoal network (train.subgoal) whose outputs fill the cells
                                 // where a goal is given, the vertices still coming from 'model'
  double threshold = 0.5;        // a vertex-map peak above this is a detection
  double sigma_range = 5.0;      // the covariance reported with each detection (world units, radians)
  double sigma_bearing = 0.125;
  int threads = 1;               // CPU threads for the network (a bench runs one trial per core); 0: LibTorch's default
  bool mirror_average = false;   // each network also runs on the panorama mirrored in bearing, outputs averaged
                                 // (learning/mirror_average.h): a second pass a step
  bool sub_bin = false;          // not a key: set from open_world.sub_bin by experiments::SensorFor
  static const core::OptionFields<LearnedSensorOptions>& Fields();  // the keys and their ranges
};

// YAML section `sensor:`.
struct SensorConfig {
  SensorKind kind = SensorKind::kNoisy;
  sim::NoisySensorOptions noisy;  // kind noisy: its keys sit beside `kind`
  LearnedSensorOptions learned;   // kinds learned and recorded: likewise
  std::string images;             // kind recorded: the recording's folder ...
  std::string poses;              // ... and its poses file (default: images/poses.csv)
  sim::RangeRingOptions range_ring;  // `range_ring: {rays, range}`: a short-range scan beside the vertex
                                     // sensor (none by default; not for recordings)
  void Validate() const;          // throws core::ConfigError ("sensor.max_range", "sensor.model", ...)
};

// The sensors a config declares, as trial records and reports name them: the kind, then "+range_ring" where
// one is declared (e.g. "learned+range_ring").
std::string SensorsUsed(const SensorConfig& config);

// What the sensor is for: the world it observes (and renders; none for a recording), the render options of image-based
// kinds, the goal of goal-directed runs (passed to goal-conditioned detectors), and the seed of its randomness.
struct SensorSetup {
  const core::World* world = nullptr;
  sim::RenderOptions render;
  std::optional<core::Vec2> goal;
  uint64_t seed = 0;
  bool goal_at_agent = false;  // without a goal: a goal-conditioned network is told the goal is at the agent
};

std::unique_ptr<core::VertexSensorInterface> CreateSensor(const SensorConfig& config, const SensorSetup& setup);

}  // namespace toponav::experiments

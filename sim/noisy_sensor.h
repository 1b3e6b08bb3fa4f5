#pragma once
// A simulated vertex sensor built on the ray-cast ground truth, with the imperfections of the learned one:
// quantization to its 32x128 range-bearing grid, range and bearing noise, missed vertices, false positives
// on walls and clutter, nearby vertices merging into one detection, and softened or confused labels.
// Unlike the reference's "noisy" sensor (vertexnav.md §3.2, essentially exact), the defaults are noisy
// enough that a map built without the posterior collects false vertices and walls.
#include <cstdint>
#include <memory>

#include "core/observation.h"
#include "core/option_fields.h"
#include "core/world.h"

namespace toponav::sim {

struct NoisySensorOptions {
  double max_range = 100.0;             // vertices at or beyond this are not seen
  int range_bins = 32;                  // quantize range to bin centres k*max_range/range_bins (0: off)
  int bearing_bins = 128;               // quantize bearing to -pi + 2*pi*k/bearing_bins (0: off)
  double range_sigma = 1.0;             // Gaussian range noise, world units ...
  double range_sigma_per_unit = 0.02;   // ... growing by this much per unit of range
  double bearing_sigma = 0.015;         // Gaussian bearing noise, radians
  double miss_probability = 0.15;       // a visible vertex goes undetected
  double false_positives_per_observation = 1.0;  // Poisson mean; placed where a random ray hits a wall or clutter
  int merge_bins = 1;                   // detections this close in both range and bearing bins merge into one
  double label_confusion = 0.1;         // the label is replaced by a different one
  double label_softness = 0.3;          // the one-hot label is mixed with a random distribution by this much
  // The standard deviations the sensor reports with each detection (range in world units, bearing in
  // radians): what the map's association gates and likelihoods assume.  The defaults sit above the sensor's
  // own error, with a margin for merged neighbours (README, "The map", says how they were chosen).
  double reported_sigma_range = 3.5;
  double reported_sigma_bearing = 0.06;
  static const core::OptionFields<NoisySensorOptions>& Fields();  // YAML keys (under sensor:) and ranges
  void Validate() const;                // throws core::ConfigError ("sensor.max_range", ...)
};

// 'seed' drives all of the sensor's randomness: the same seed and pose sequence give the same observations.
std::unique_ptr<core::VertexSensorInterface> CreateNoisyGroundTruthSensor(const core::World& world,
                                                                          const NoisySensorOptions& options,
                                                                          uint64_t seed);

}  // namespace toponav::sim

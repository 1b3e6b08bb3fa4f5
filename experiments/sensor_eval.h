#pragma once
// Sensor evaluation (`toponav eval-sensor`): any sensor the factory builds, at sample poses of chosen worlds,
// against the ray-cast ground truth on the range-bearing grid.  A detection matches a true vertex within one
// range bin and one bearing bin (one-to-one, nearest first).  The measured rates are also written as a
// `sensor:` block for the noisy sensor, so the simulated sensor can be calibrated to a learned one.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/detection.h"
#include "core/world.h"
#include "experiments/config.h"

namespace toponav::experiments {

struct SensorEvalOptions {
  core::WorldKind kind = core::WorldKind::kLabyrinth;
  std::vector<uint64_t> seeds;
  int samples_per_world = 10;
};

struct SensorEval {
  int observations = 0, true_vertices = 0, detections = 0, matches = 0;
  int label_correct = 0;
  double range_error_sum = 0, bearing_error_sum = 0, range_sq_sum = 0, bearing_sq_sum = 0;
  std::array<std::array<int, 4>, 4> confusion{};  // [true label][detected label] over matches
  // Recall by the true vertex's range (bands split at kRangeEdges) and by its true label.
  static constexpr std::array<double, 3> kRangeEdges{10.0, 25.0, 50.0};
  std::array<int, 4> true_by_range{}, matched_by_range{}, true_by_label{};
  // Recall by the sight-line angle (SightAngle; bands split at kSightEdges, radians: 5, 15, 30 degrees): a
  // vertex at the end of a wall seen end-on shows the camera no face.
  static constexpr std::array<double, 3> kSightEdges{0.0873, 0.2618, 0.5236};
  std::array<int, 4> true_by_sight{}, matched_by_sight{};
  // Signed errors (detected - true) of matches by true label; bearing toward the gap side for the gap labels
  // (positive: the vertex is seen out in the open, off the wall's end), counter-clockwise for the others.
  std::array<double, 4> range_bias_sum{}, bearing_bias_sum{};
  double seconds = 0;
  double precision() const { return detections > 0 ? double(matches) / detections : 0.0; }
  double recall() const { return true_vertices > 0 ? double(matches) / true_vertices : 0.0; }
  double f1() const { const double p = precision(), r = recall(); return p + r > 0 ? 2 * p * r / (p + r) : 0.0; }
  double label_accuracy() const { return matches > 0 ? double(label_correct) / matches : 0.0; }
  double mean_range_error() const { return matches > 0 ? range_error_sum / matches : 0.0; }
  double mean_bearing_error() const { return matches > 0 ? bearing_error_sum / matches : 0.0; }
  double recall_at_sight(size_t b) const {
    return true_by_sight[b] > 0 ? double(matched_by_sight[b]) / true_by_sight[b] : 0.0;
  }
  double recall_in_band(size_t b) const {
    return true_by_range[b] > 0 ? double(matched_by_range[b]) / true_by_range[b] : 0.0;
  }
  int matches_of_label(size_t l) const {
    int found = 0;
    for (int n : confusion[l]) found += n;
    return found;
  }
  double range_bias_of_label(size_t l) const {
    return matches_of_label(l) > 0 ? range_bias_sum[l] / matches_of_label(l) : 0.0;
  }
  double bearing_bias_of_label(size_t l) const {
    return matches_of_label(l) > 0 ? bearing_bias_sum[l] / matches_of_label(l) : 0.0;
  }
  double recall_of_label(size_t l) const {
    return true_by_label[l] > 0 ? double(matches_of_label(l)) / true_by_label[l] : 0.0;
  }
};

SensorEval EvaluateSensor(const Config& config, const SensorEvalOptions& options);
// The smaller angle (radians, [0, pi/2]) between the line of sight from 'eye' to vertex 'ref' of 'world' and
// the vertex's two walls: 0 where one of them is seen end-on.
double SightAngle(const core::World& world, const core::VertexRef& ref, const core::Vec2& eye);
// A detection's signed bearing error (radians, detected - true, wrapped) as the bias sums count it: toward
// the gap side for the gap labels (positive: out in the open, off the wall's end), else counter-clockwise.
double SignedBearingError(core::VertexLabel true_label, double detected_bearing, double true_bearing);
// The measured rates as a `sensor:` YAML block for the noisy sensor (kind noisy), with a comment saying
// what was measured.
std::string NoisySensorYaml(const SensorEval& e, const std::string& measured_on);

}  // namespace toponav::experiments

#include "experiments/sensor_eval.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/range_bearing_grid.h"
#include "experiments/sensor_factory.h"
#include "sim/raycast.h"
#include "sim/training_data.h"

namespace toponav::experiments {

namespace {

int ArgMax(const core::LabelProbs& p) { return int(std::max_element(p.begin(), p.end()) - p.begin()); }

size_t RangeBand(double range) {
  const auto& edges = SensorEval::kRangeEdges;
  return size_t(std::upper_bound(edges.begin(), edges.end(), range) - edges.begin());
}

// Matches the detections of one observation with the true vertices (within one range and one bearing bin,
// nearest cell distance first, one-to-one) and adds the counts to 'e'.
void Score(const core::Observation& z, const std::vector<sim::VisibleVertex>& truth, const core::RangeBearingGrid& g,
           SensorEval* e) {
  struct Pair {
    int cells;
    size_t d, t;
  };
  std::vector<Pair> pairs;
  for (size_t d = 0; d < z.detections.size(); ++d)
    for (size_t t = 0; t < truth.size(); ++t) {
      const int dr = std::abs(g.RangeRow(z.detections[d].range) - g.RangeRow(truth[t].range));
      const int dc0 = std::abs(g.BearingCol(z.detections[d].bearing) - g.BearingCol(truth[t].bearing));
      const int dc = std::min(dc0, g.cols - dc0);
      if (dr <= 1 && dc <= 1) pairs.push_back({dr + dc, d, t});
    }
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.cells < b.cells; });
  std::vector<char> used_d(z.detections.size(), 0), used_t(truth.size(), 0);
  for (const auto& p : pairs) {
    if (used_d[p.d] || used_t[p.t]) continue;
    used_d[p.d] = used_t[p.t] = 1;
    const auto& d = z.detections[p.d];
    const auto& t = truth[p.t];
    ++e->matches;
    ++e->matched_by_range[RangeBand(t.range)];
    const int detected = ArgMax(d.labels), real = int(t.label);
    e->label_correct += detected == real;
    ++e->confusion[size_t(real)][size_t(detected)];
    const double dr = std::abs(d.range - t.range), db = std::abs(core::WrapAngle(d.bearing - t.bearing));
    e->range_error_sum += dr;
    e->bearing_error_sum += db;
    e->range_bias_sum[size_t(real)] += d.range - t.range;
    e->bearing_bias_sum[size_t(real)] += SignedBearingError(t.label, d.bearing, t.bearing);
    e->range_sq_sum += dr * dr;
    e->bearing_sq_sum += db * db;
  }
  for (const auto& t : truth) {
    ++e->true_by_range[RangeBand(t.range)];
    ++e->true_by_label[size_t(t.label)];
  }
  ++e->observations;
  e->detections += int(z.detections.size());
  e->true_vertices += int(truth.size());
}

}  // namespace

double SignedBearingError(core::VertexLabel true_label, double detected_bearing, double true_bearing) {
  // A right gap's wall runs on its counter-clockwise side, so its gap is clockwise.
  const double toward_gap = true_label == core::VertexLabel::kRightGap ? -1.0 : 1.0;
  return toward_gap * core::WrapAngle(detected_bearing - true_bearing);
}

SensorEval EvaluateSensor(const Config& config, const SensorEvalOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const core::RangeBearingGrid grid;
  SensorEval e;
  for (uint64_t seed : o.seeds) {
    const core::World w = sim::GenerateWorld(o.kind, config.worlds, seed);
    const sim::RayCaster caster(w);
    auto sensor = CreateSensor(config.sensor, {&w, config.render, std::nullopt, core::DeriveSeed(seed, 1)});
    for (int i = 0; i < o.samples_per_world; ++i) {
      const core::Pose2 pose = sim::SamplePose(w, {sim::Split::kVal, o.kind, seed, i}, config.datagen);
      Score(sensor->Observe(pose, 0), caster.VisibleVertices(pose, grid.max_range), grid, &e);
    }
  }
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

std::string NoisySensorYaml(const SensorEval& e, const std::string& measured_on) {
  std::ostringstream os;
  os.precision(4);
  const double per_obs = e.observations > 0 ? double(e.detections - e.matches) / e.observations : 0.0;
  os << "# Measured by toponav eval-sensor on " << measured_on << ": precision " << e.precision() << ", recall "
     << e.recall() << ", F1 " << e.f1() << ", label accuracy " << e.label_accuracy() << ".\n"
     << "sensor:\n  kind: noisy\n"
     << "  miss_probability: " << std::min(0.99, 1.0 - e.recall()) << "\n"
     << "  false_positives_per_observation: " << std::min(50.0, per_obs) << "\n"
     << "  label_confusion: " << 1.0 - e.label_accuracy() << "\n"
     << "  range_sigma: " << (e.matches > 0 ? std::sqrt(e.range_sq_sum / e.matches) : 0.0) << "\n"
     << "  range_sigma_per_unit: 0.0\n"
     << "  bearing_sigma: " << (e.matches > 0 ? std::sqrt(e.bearing_sq_sum / e.matches) : 0.0) << "\n";
  return os.str();
}

}  // namespace toponav::experiments

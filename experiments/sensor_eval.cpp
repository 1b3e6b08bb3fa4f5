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

template <size_t N>
size_t Band(const std::array<double, N>& edges, double value) {
  return size_t(std::upper_bound(edges.begin(), edges.end(), value) - edges.begin());
}
size_t RangeBand(double range) { return Band(SensorEval::kRangeEdges, range); }

// Matches the detections of one observation with the true vertices (within one range and one bearing bin,
// nearest cell distance first, one-to-one) and adds the counts to 'e'.
// 'sight[t]': the band of truth[t]'s sight-line angle.
void Score(const core::Observation& z, const std::vector<sim::VisibleVertex>& truth, const std::vector<size_t>& sight,
           const core::RangeBearingGrid& g, SensorEval* e) {
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
    ++e->matched_by_sight[sight[p.t]];
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
  for (size_t t = 0; t < truth.size(); ++t) ++e->true_by_sight[sight[t]];
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

double SightAngle(const core::World& world, const core::VertexRef& ref, const core::Vec2& eye) {
  const core::Ring& ring = *core::MapRings(world).at(size_t(ref.ring));
  const size_t n = ring.size(), i = size_t(ref.index);
  const core::Vec2 v = ring[i], sight = v - eye;
  double angle = core::kPi / 2;
  for (const core::Vec2& w : {ring[(i + n - 1) % n], ring[(i + 1) % n]}) {
    const core::Vec2 wall = w - v;
    const double a = std::abs(std::atan2(core::Cross(sight, wall), core::Dot(sight, wall)));  // [0, pi]
    angle = std::min(angle, std::min(a, core::kPi - a));
  }
  return angle;
}

SensorEval EvaluateSensor(const Config& config, const SensorEvalOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const core::RangeBearingGrid grid;
  SensorEval e;
  for (uint64_t seed : o.seeds) {
    const core::World w = sim::GenerateWorld(o.kind, config.worlds, seed);
    const sim::RayCaster caster(w);
    auto sensor = CreateSensor(SensorFor(config, w), {&w, config.render, std::nullopt, core::DeriveSeed(seed, 1)});
    for (int i = 0; i < o.samples_per_world; ++i) {
      const core::Pose2 pose = sim::SamplePose(w, {sim::Split::kVal, o.kind, seed, i}, config.datagen);
      const std::vector<sim::VisibleVertex> truth = caster.VisibleVertices(pose, grid.max_range);
      std::vector<size_t> sight;
      for (const auto& t : truth) sight.push_back(Band(SensorEval::kSightEdges, SightAngle(w, t.ref, pose.position())));
      Score(sensor->Observe(pose, 0), truth, sight, grid, &e);
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

#include "sim/noisy_sensor.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/rng.h"
#include "sim/raycast.h"

namespace toponav::sim {

using core::Detection;
using core::LabelProbs;

const core::OptionFields<NoisySensorOptions>& NoisySensorOptions::Fields() {
  using O = NoisySensorOptions;
  static const core::OptionFields<O> fields{
      {"max_range", &O::max_range, 1.0, 1e4},
      {"range_bins", &O::range_bins, 0, 1024},
      {"bearing_bins", &O::bearing_bins, 0, 4096},
      {"range_sigma", &O::range_sigma, 0.0, 100.0},
      {"range_sigma_per_unit", &O::range_sigma_per_unit, 0.0, 1.0},
      {"bearing_sigma", &O::bearing_sigma, 0.0, 1.0},
      {"miss_probability", &O::miss_probability, 0.0, 0.99},
      {"false_positives_per_observation", &O::false_positives_per_observation, 0.0, 50.0},
      {"merge_bins", &O::merge_bins, 0, 10},
      {"label_confusion", &O::label_confusion, 0.0, 1.0},
      {"label_softness", &O::label_softness, 0.0, 1.0},
      {"reported_sigma_range", &O::reported_sigma_range, 1e-3, 100.0},
      {"reported_sigma_bearing", &O::reported_sigma_bearing, 1e-4, 3.0},
  };
  return fields;
}

void NoisySensorOptions::Validate() const { core::CheckRanges(*this, Fields(), "sensor."); }

namespace {

class NoisyGroundTruthSensor : public core::VertexSensorInterface {
 public:
  NoisyGroundTruthSensor(const core::World& world, const NoisySensorOptions& o, uint64_t seed)
      : options_(o), caster_(world), rng_(seed) {
    o.Validate();
  }

  core::Observation Observe(const core::Pose2& pose, int agent) override {
    const NoisySensorOptions& o = options_;
    struct Raw {
      double range, bearing;
      LabelProbs labels;
      double weight;
    };
    std::vector<Raw> raw;
    for (const auto& v : caster_.VisibleVertices(pose, o.max_range)) {
      if (rng_.Bernoulli(o.miss_probability)) continue;
      raw.push_back({v.range, v.bearing, NoisyLabel(v.label), 1.0});
    }
    const int num_fp = rng_.Poisson(o.false_positives_per_observation);
    for (int i = 0; i < num_fp; ++i) {
      const double bearing = rng_.Uniform(-core::kPi, core::kPi);
      const double range = caster_.CastRay(pose.position(), pose.yaw + bearing, o.max_range, true);
      if (range >= o.max_range) continue;
      const auto label = static_cast<core::VertexLabel>(rng_.UniformInt(0, 3));
      raw.push_back({range, bearing, Soften(core::OneHot(label)), 1.0});
    }
    // Noise, then quantization to the sensor grid.
    const double dr = o.range_bins > 0 ? o.max_range / o.range_bins : 0.0;
    const double db = o.bearing_bins > 0 ? 2 * core::kPi / o.bearing_bins : 0.0;
    struct Cell {
      int rb, bb;
    };
    std::vector<Cell> cells;
    for (auto& r : raw) {
      r.range = std::max(0.0, r.range + rng_.Normal(0.0, o.range_sigma + o.range_sigma_per_unit * r.range));
      r.bearing = core::WrapAngle(r.bearing + rng_.Normal(0.0, o.bearing_sigma));
      Cell c{0, 0};
      if (dr > 0) {
        c.rb = std::clamp(int(std::lround(r.range / dr)), 1, o.range_bins);
        r.range = c.rb * dr;
      }
      if (db > 0) {
        c.bb = int(std::lround((r.bearing + core::kPi) / db)) % o.bearing_bins;
        r.bearing = core::WrapAngle(-core::kPi + c.bb * db);
      }
      cells.push_back(c);
    }
    // Nearby vertices merge into one detection (one peak per blob), nearest first.
    std::vector<size_t> order(raw.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return raw[a].range < raw[b].range; });
    std::vector<size_t> kept;
    for (size_t i : order) {
      bool merged = false;
      if (dr > 0 && db > 0)
        for (size_t k : kept) {
          int dbins = std::abs(cells[i].bb - cells[k].bb);
          dbins = std::min(dbins, o.bearing_bins - dbins);
          if (std::abs(cells[i].rb - cells[k].rb) <= o.merge_bins && dbins <= o.merge_bins) {
            for (int j = 0; j < 4; ++j)
              raw[k].labels[size_t(j)] =
                  (raw[k].labels[size_t(j)] * raw[k].weight + raw[i].labels[size_t(j)]) / (raw[k].weight + 1);
            raw[k].weight += 1;
            merged = true;
            break;
          }
        }
      if (!merged) kept.push_back(i);
    }
    core::Observation obs;
    obs.pose = pose;
    obs.agent = agent;
    for (size_t k : kept) {
      Detection d;
      d.range = raw[k].range;
      d.bearing = raw[k].bearing;
      d.polar = {o.reported_sigma_range * o.reported_sigma_range, 0.0,
                 o.reported_sigma_bearing * o.reported_sigma_bearing};
      d.labels = raw[k].labels;
      obs.detections.push_back(d);
    }
    std::sort(obs.detections.begin(), obs.detections.end(),
              [](const Detection& a, const Detection& b) { return a.bearing < b.bearing; });
    return obs;
  }

 private:
  LabelProbs Soften(const LabelProbs& onehot) {
    LabelProbs noise{rng_.Uniform(), rng_.Uniform(), rng_.Uniform(), rng_.Uniform()};
    const double sum = noise[0] + noise[1] + noise[2] + noise[3];
    LabelProbs out;
    for (size_t j = 0; j < 4; ++j)
      out[j] = (1 - options_.label_softness) * onehot[j] + options_.label_softness * noise[j] / sum;
    return out;
  }

  LabelProbs NoisyLabel(core::VertexLabel truth) {
    if (rng_.Bernoulli(options_.label_confusion)) {
      int other = rng_.UniformInt(0, 2);
      if (other >= static_cast<int>(truth)) ++other;
      truth = static_cast<core::VertexLabel>(other);
    }
    return Soften(core::OneHot(truth));
  }

  NoisySensorOptions options_;
  RayCaster caster_;
  core::Rng rng_;
};

}  // namespace

std::unique_ptr<core::VertexSensorInterface> CreateNoisyGroundTruthSensor(const core::World& world,
                                                                          const NoisySensorOptions& options,
                                                                          uint64_t seed) {
  return std::make_unique<NoisyGroundTruthSensor>(world, options, seed);
}

}  // namespace toponav::sim

#include "sim/noisy_sensor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "sim/worlds.h"

namespace toponav::sim {
namespace {

// Detections of true vertices (no false positives) from free poses of a labyrinth, matched to the nearest
// true vertex (within 10 units): root-mean-square range and bearing errors.
struct Errors {
  double rms_range = 0, rms_bearing = 0;
  int matched = 0;
  double rms_range_far = 0;  // detections beyond 70 units, where range noise is largest
  int matched_far = 0;
};

Errors MeasureErrors(const NoisySensorOptions& o, uint64_t seed) {
  const core::World world = GenerateWorld(core::WorldKind::kLabyrinth, WorldOptions{}, seed);
  auto sensor = CreateNoisyGroundTruthSensor(world, o, seed);
  const std::vector<core::Vec2> truth = core::MapVertices(world);
  core::Rng rng(seed + 1);
  Errors e;
  double sr = 0, sb = 0, sf = 0;
  for (int poses = 0; poses < 40;) {
    const core::Vec2 p{rng.Uniform(world.bounds.min.x, world.bounds.max.x),
                       rng.Uniform(world.bounds.min.y, world.bounds.max.y)};
    if (core::SignedDistance(world, p) < 2.0) continue;
    ++poses;
    const core::Pose2 pose{p.x, p.y, rng.Uniform(-core::kPi, core::kPi)};
    for (const auto& d : sensor->Observe(pose, 0).detections) {
      const double a = pose.yaw + d.bearing;
      const core::Vec2 seen = p + core::Vec2{std::cos(a), std::sin(a)} * d.range;
      const core::Vec2* best = nullptr;
      for (const auto& v : truth)
        if (!best || core::Distance(v, seen) < core::Distance(*best, seen)) best = &v;
      if (!best || core::Distance(*best, seen) > 10.0) continue;
      const double dr = d.range - core::Distance(p, *best);
      const double db = core::WrapAngle(a - std::atan2(best->y - p.y, best->x - p.x));
      sr += dr * dr;
      sb += db * db;
      ++e.matched;
      if (d.range > 70) {
        sf += dr * dr;
        ++e.matched_far;
      }
    }
  }
  e.rms_range = std::sqrt(sr / std::max(1, e.matched));
  e.rms_bearing = std::sqrt(sb / std::max(1, e.matched));
  e.rms_range_far = std::sqrt(sf / std::max(1, e.matched_far));
  return e;
}

TEST(NoisySensor, ReportedCovarianceCoversItsOwnError) {
  NoisySensorOptions o;
  o.false_positives_per_observation = 0.0;  // errors of true vertices only
  const Errors e = MeasureErrors(o, 3);
  ASSERT_GT(e.matched, 200);
  EXPECT_LT(e.rms_range, o.reported_sigma_range) << "range error larger than the sensor says";
  EXPECT_LT(e.rms_bearing, o.reported_sigma_bearing) << "bearing error larger than the sensor says";
  ASSERT_GT(e.matched_far, 30);
  EXPECT_LT(e.rms_range_far, o.reported_sigma_range) << "far detections: range error larger than the sensor says";
  EXPECT_GT(e.rms_range, 0.5) << "the sensor is meant to be noisy";
}

TEST(NoisySensor, MoreRangeNoiseShowsInTheMeasuredError) {
  NoisySensorOptions o;
  o.false_positives_per_observation = 0.0;
  const Errors base = MeasureErrors(o, 4);
  o.range_sigma = 4.0;
  EXPECT_GT(MeasureErrors(o, 4).rms_range, base.rms_range + 1.0);
}

}  // namespace
}  // namespace toponav::sim

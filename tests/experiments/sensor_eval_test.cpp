#include "experiments/sensor_eval.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/world.h"
#include "tests/testing/worlds.h"

namespace toponav::experiments {
namespace {

SensorEvalOptions Labyrinths() {
  SensorEvalOptions o;
  o.kind = core::WorldKind::kLabyrinth;
  o.seeds = {100, 101, 102, 103};
  o.samples_per_world = 10;
  return o;
}

TEST(SensorEval, AnExactSensorScoresOne) {
  Config c;
  auto& n = c.sensor.noisy;
  n.range_sigma = n.range_sigma_per_unit = n.bearing_sigma = n.miss_probability = 0.0;
  n.false_positives_per_observation = n.label_confusion = n.label_softness = 0.0;
  n.merge_bins = 0;
  const SensorEval e = EvaluateSensor(c, Labyrinths());
  EXPECT_GT(e.true_vertices, 100);
  EXPECT_NEAR(e.recall(), 1.0, 0.02) << "every vertex found within a bin (two in one cell are one detection)";
  EXPECT_NEAR(e.precision(), 1.0, 1e-9);
  EXPECT_NEAR(e.label_accuracy(), 1.0, 1e-9);
  EXPECT_LT(e.mean_range_error(), 1.6) << "range quantized to 3.125-unit bins";
  for (size_t l = 0; l < 3; ++l) {  // quantization alone biases neither range nor bearing
    EXPECT_GT(e.matches_of_label(l), 50) << "label " << l;
    EXPECT_LT(std::abs(e.range_bias_of_label(l)), 0.25) << "label " << l;
    EXPECT_LT(std::abs(e.bearing_bias_of_label(l)), 0.004) << "label " << l;
  }
}

// Bearing bias is counted toward the gap for gap labels: a right gap's gap is clockwise (its wall runs
// counter-clockwise), a left gap's counter-clockwise; other labels count counter-clockwise.
TEST(SensorEval, SignedBearingErrorPointsTowardTheGap) {
  EXPECT_NEAR(SignedBearingError(core::VertexLabel::kRightGap, 0.99, 1.0), 0.01, 1e-12);
  EXPECT_NEAR(SignedBearingError(core::VertexLabel::kLeftGap, 1.01, 1.0), 0.01, 1e-12);
  EXPECT_NEAR(SignedBearingError(core::VertexLabel::kCorner, 0.99, 1.0), -0.01, 1e-12);
  EXPECT_NEAR(SignedBearingError(core::VertexLabel::kLeftGap, -3.14, 3.14), 2 * core::kPi - 6.28, 1e-12) << "wraps";
}

// The square obstacle (1, 1)-(2, 2) of testing::SquareWorld: its corner (1, 1) seen along its south wall's
// line is seen end-on (0); from straight down the diagonal both walls are at 45 degrees.
TEST(SensorEval, TheSightAngleIsZeroAlongAWallAndFortyFiveDegreesDownTheDiagonal) {
  const core::World w = testing::SquareWorld();
  const auto rings = core::MapRings(w);
  core::VertexRef corner{-1, -1};
  for (size_t r = 0; r < rings.size(); ++r)
    for (size_t i = 0; i < rings[r]->size(); ++i)
      if (core::Distance((*rings[r])[i], {1, 1}) < 1e-9) corner = {int(r), int(i)};
  ASSERT_GE(corner.ring, 0);
  EXPECT_NEAR(SightAngle(w, corner, {-5, 1}), 0.0, 1e-9);
  EXPECT_NEAR(SightAngle(w, corner, {5, 1}), 0.0, 1e-9) << "along the wall, from its far side";
  EXPECT_NEAR(SightAngle(w, corner, {0, 0}), core::kPi / 4, 1e-9);
  EXPECT_NEAR(SightAngle(w, corner, {0, 1 - std::tan(0.2)}), 0.2, 1e-9);
}

TEST(SensorEval, TheNoisySensorsConfiguredRatesAreMeasuredBack) {
  Config c;
  c.sensor.noisy.miss_probability = 0.3;
  c.sensor.noisy.false_positives_per_observation = 2.0;
  c.sensor.noisy.label_confusion = 0.2;
  c.sensor.noisy.merge_bins = 0;
  const SensorEval e = EvaluateSensor(c, Labyrinths());
  EXPECT_NEAR(e.recall(), 0.7, 0.06);
  EXPECT_NEAR(double(e.detections - e.matches) / e.observations, 2.0, 0.5);
  EXPECT_NEAR(e.label_accuracy(), 0.8, 0.08);
  int banded = 0;
  for (size_t b = 0; b < e.true_by_range.size(); ++b) {
    banded += e.true_by_range[b];
    if (e.true_by_range[b] >= 50) {
      EXPECT_NEAR(e.recall_in_band(b), 0.7, 0.12) << "misses fall alike at every range";
    }
  }
  EXPECT_EQ(banded, e.true_vertices);
  for (size_t l = 0; l < e.true_by_label.size(); ++l)
    if (e.true_by_label[l] >= 50) {
      EXPECT_NEAR(e.recall_of_label(l), 0.7, 0.12) << "label " << l;
    }
  const std::string yaml = NoisySensorYaml(e, "test");
  EXPECT_NE(yaml.find("miss_probability: 0.3"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("kind: noisy"), std::string::npos);
}

}  // namespace
}  // namespace toponav::experiments

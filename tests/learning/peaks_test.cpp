#include "learning/peaks.h"

#include <gtest/gtest.h>

namespace toponav::learning {
namespace {

TEST(Peaks, OnePeakPerBlobAtItsHighestCell) {
  const core::RangeBearingGrid g;
  std::vector<float> p(g.size(), 0.0f);
  p[g.Index(5, 40)] = 0.9f;
  p[g.Index(5, 41)] = 0.7f;  // same blob
  p[g.Index(6, 41)] = 0.45f; // above threshold - 0.1: still the same blob
  p[g.Index(20, 90)] = 0.55f;
  p[g.Index(25, 10)] = 0.45f;  // a blob below the threshold: no peak
  const auto peaks = DetectPeaks(p, g, 0.5f);
  ASSERT_EQ(peaks.size(), 2u);
  EXPECT_EQ(peaks[0].row, 5);
  EXPECT_EQ(peaks[0].col, 40);
  EXPECT_EQ(peaks[1].row, 20);
  EXPECT_EQ(peaks[1].col, 90);
}

TEST(Peaks, ABlobAcrossTheBearingWrapIsOnePeak) {
  const core::RangeBearingGrid g;
  std::vector<float> p(g.size(), 0.0f);
  p[g.Index(10, 127)] = 0.8f;
  p[g.Index(10, 0)] = 0.95f;
  p[g.Index(11, 1)] = 0.6f;
  const auto peaks = DetectPeaks(p, g, 0.5f);
  ASSERT_EQ(peaks.size(), 1u) << "columns 127 and 0 are neighbours";
  EXPECT_EQ(peaks[0].col, 0);
  EXPECT_FLOAT_EQ(peaks[0].value, 0.95f);
}

TEST(Peaks, DecodedDetectionsCarryTheCellsRangeBearingLabelsAndTheReportedCovariance) {
  const core::RangeBearingGrid g;
  std::vector<float> p(g.size(), 0.0f), labels(4 * g.size(), 0.25f);
  p[g.Index(3, 96)] = 0.9f;  // range 12.5, bearing pi/2
  p[g.Index(7, 32)] = 0.8f;  // range 25, bearing -pi/2
  for (int k = 0; k < 4; ++k) labels[4 * g.Index(3, 96) + size_t(k)] = k == 1 ? 0.7f : 0.1f;
  const auto d = DecodeDetections(p, labels, g, DecodeOptions{});
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(d[0].bearing, -core::kPi / 2, 1e-9) << "sorted by bearing";
  EXPECT_NEAR(d[0].range, 25.0, 1e-9);
  EXPECT_NEAR(d[1].range, 12.5, 1e-9);
  EXPECT_NEAR(d[1].bearing, core::kPi / 2, 1e-9);
  EXPECT_NEAR(d[1].labels[1], 0.7, 1e-6);
  EXPECT_NEAR(d[1].polar.xx, 25.0, 1e-9);
  EXPECT_NEAR(d[1].polar.yy, 0.125 * 0.125, 1e-12);
}

}  // namespace
}  // namespace toponav::learning

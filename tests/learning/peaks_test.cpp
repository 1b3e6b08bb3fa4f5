#include "learning/peaks.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(Peaks, SubBinDecodingPlacesAVertexSpreadOverTwoCellsBetweenThem) {
  const core::RangeBearingGrid g;
  std::vector<float> p(g.size(), 0.0f), labels(4 * g.size(), 0.25f);
  p[g.Index(3, 96)] = 0.9f;  // range 12.5, bearing pi/2
  p[g.Index(4, 96)] = 0.6f;  // the next range bin: the centroid lies 0.6 / 1.5 of a bin beyond row 3
  p[g.Index(10, 0)] = 0.8f;  // bearing -pi, with its neighbour across the wrap (column 127)
  p[g.Index(10, 127)] = 0.4f;
  DecodeOptions sub_bin;
  sub_bin.sub_bin = true;
  const auto d = DecodeDetections(p, labels, g, sub_bin);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(DecodeDetections(p, labels, g, DecodeOptions{})[1].range, 12.5, 1e-9)
      << "without: the cell's centre (bearing -pi sorts first)";
  const double bin = 2 * core::kPi / g.cols;
  EXPECT_NEAR(d[0].range, 12.5 + 0.4 * g.RangeStep(), 1e-6);
  EXPECT_NEAR(d[0].bearing, core::kPi / 2, 1e-9) << "no bearing neighbours: the column's own bearing";
  EXPECT_NEAR(d[1].range, 34.375, 1e-6) << "a lone row: no range offset";
  EXPECT_NEAR(d[1].bearing, core::kPi - bin / 3, 1e-6) << "a third of a bin toward column 127, across the wrap";
}

}  // namespace
}  // namespace toponav::learning

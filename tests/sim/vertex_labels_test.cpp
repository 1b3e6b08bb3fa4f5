#include "sim/vertex_labels.h"

#include <gtest/gtest.h>

#include "tests/testing/worlds.h"

namespace toponav::sim {
namespace {

VisibleVertex At(double range, double bearing, core::VertexLabel label) {
  VisibleVertex v;
  v.range = range;
  v.bearing = bearing;
  v.label = label;
  return v;
}

TEST(VertexLabels, AVertexMarksTheCellNearestItsRangeAndBearing) {
  const core::RangeBearingGrid g;  // 32 x 128 over 100 units: range bins 3.125, 6.25, ...; bearing -pi + 2 pi j / 128
  const auto labels = RasterizeVertexLabels({At(10.0, 0.0, core::VertexLabel::kCorner)}, g);
  ASSERT_EQ(labels.num_vertices(), 1);
  // 10 / 3.125 = 3.2: nearest bin centre 9.375 is row 2; bearing 0 is column 64.
  EXPECT_EQ(labels.cells[g.Index(2, 64)], 1 + int(core::VertexLabel::kCorner));
  EXPECT_NEAR(g.RowRange(2), 9.375, 1e-12);
  EXPECT_NEAR(g.ColBearing(64), 0.0, 1e-12);
}

TEST(VertexLabels, BearingWrapsAndRangeIsClampedToTheGrid) {
  const core::RangeBearingGrid g;
  const double just_below_pi = core::kPi - 0.001;  // nearer to column 128 = column 0 than to 127
  const auto labels = RasterizeVertexLabels({At(1.0, just_below_pi, core::VertexLabel::kLeftGap),
                                             At(99.0, -core::kPi, core::VertexLabel::kPoint),
                                             At(100.0, 0.5, core::VertexLabel::kPoint)},  // at max range: not seen
                                            g);
  EXPECT_EQ(labels.num_vertices(), 2);
  EXPECT_EQ(labels.cells[g.Index(0, 0)], 1 + int(core::VertexLabel::kLeftGap)) << "range 1 -> first row";
  EXPECT_EQ(labels.cells[g.Index(31, 0)], 1 + int(core::VertexLabel::kPoint)) << "range 99 -> last row";
}

TEST(VertexLabels, TheNearerOfTwoVerticesInOneCellWins) {
  const core::RangeBearingGrid g;
  const auto labels = RasterizeVertexLabels(
      {At(20.3, 0.01, core::VertexLabel::kCorner), At(19.9, 0.0, core::VertexLabel::kRightGap)}, g);
  EXPECT_EQ(labels.num_vertices(), 1);
  EXPECT_EQ(labels.cells[g.Index(g.RangeRow(20.0), 64)], 1 + int(core::VertexLabel::kRightGap));
}

TEST(VertexLabels, ARoomsCornersFromTheRayCasterAreLabelledCorners) {
  const core::World w = testing::RoomWorld(40, 30);  // start at the centre: four corners at range 25
  const RayCaster caster(w);
  const auto labels = RasterizeVertexLabels(caster.VisibleVertices(w.start, 100.0), core::RangeBearingGrid{});
  EXPECT_EQ(labels.num_vertices(), 4);
  for (uint8_t c : labels.cells) {
    if (c != kNoVertex) {
      EXPECT_EQ(c, 1 + int(core::VertexLabel::kCorner));
    }
  }
}

}  // namespace
}  // namespace toponav::sim

#include "core/error.h"

#include <gtest/gtest.h>

#include "core/detection.h"
#include "core/geometry.h"

namespace toponav::core {
namespace {

TEST(Error, ConfigErrorNamesFileKeyAndValue) {
  const ConfigError e("configs/x.yaml", "worlds.labyrinth.num_rooms", "99", "must be in [2, 12]");
  const std::string msg = e.what();
  EXPECT_NE(msg.find("configs/x.yaml"), std::string::npos);
  EXPECT_NE(msg.find("worlds.labyrinth.num_rooms"), std::string::npos);
  EXPECT_NE(msg.find("99"), std::string::npos);
  EXPECT_EQ(e.key(), "worlds.labyrinth.num_rooms");
}

TEST(Error, CheckThrowsInternalErrorWithLocation) {
  try {
    TOPONAV_CHECK(1 + 1 == 3, "arithmetic " << 42);
    FAIL() << "no throw";
  } catch (const InternalError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("error_test.cpp"), std::string::npos);
    EXPECT_NE(msg.find("arithmetic 42"), std::string::npos);
  }
}

TEST(BearingConvention, ColumnZeroLooksBackwardAndCentreLooksAhead) {
  EXPECT_NEAR(ColumnToBearing(0, 512), -kPi, 1e-12);
  EXPECT_NEAR(ColumnToBearing(256, 512), 0.0, 1e-12);
  EXPECT_EQ(BearingToColumn(0.0, 512), 256);
  EXPECT_EQ(BearingToColumn(kPi - 1e-9, 512), 0);  // wraps
  for (int j = 0; j < 128; ++j) EXPECT_EQ(BearingToColumn(ColumnToBearing(j, 128), 128), j);
}

TEST(VertexLabel, WallsOnEachSideGiveTheFourLabels) {
  EXPECT_EQ(LabelFromWalls(true, true), VertexLabel::kCorner);
  EXPECT_EQ(LabelFromWalls(true, false), VertexLabel::kRightGap);
  EXPECT_EQ(LabelFromWalls(false, true), VertexLabel::kLeftGap);
  EXPECT_EQ(LabelFromWalls(false, false), VertexLabel::kPoint);
  EXPECT_EQ(ToChar(VertexLabel::kCorner), 'c');
}

}  // namespace
}  // namespace toponav::core

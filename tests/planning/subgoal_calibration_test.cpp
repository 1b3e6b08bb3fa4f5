#include "planning/subgoal_calibration.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"

namespace toponav::planning {
namespace {

TEST(PiecewiseLinear, WithoutKnotsGivesTheValueItselfAndWithKnotsInterpolatesFlatPastTheEnds) {
  EXPECT_EQ(PiecewiseLinear{}(0.37), 0.37);
  const PiecewiseLinear f{{{0.1, 0.0}, {0.5, 0.2}, {0.9, 1.0}}};
  EXPECT_NEAR(f(0.3), 0.1, 1e-12);
  EXPECT_NEAR(f(0.7), 0.6, 1e-12);
  EXPECT_NEAR(f(0.5), 0.2, 1e-12);
  EXPECT_EQ(f(0.0), 0.0);
  EXPECT_EQ(f(5.0), 1.0);
}

TEST(SubgoalCalibration, MapsPsThroughItsKnotsAndLeavesTheCosts) {
  SubgoalCalibration c;
  EXPECT_TRUE(c.empty());
  c.ps.knots = {{0.0, 0.0}, {1.0, 0.5}};
  EXPECT_FALSE(c.empty());
  const SubgoalProperties p = c.Apply({0.8, 7.0, 90.0});
  EXPECT_NEAR(p.ps, 0.4, 1e-12);
  EXPECT_EQ(p.delta_success, 7.0);
  EXPECT_EQ(p.exploration, 90.0);
}

TEST(SubgoalCalibration, KnotsOutOfOrderOrAProbabilityAboveOneAreErrorsNamingTheKey) {
  SubgoalCalibration c;
  c.ps.knots = {{0.3, 0.1}, {0.3, 0.2}};
  try {
    c.Validate("cal.yaml");
    FAIL() << "no error";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("ps[1]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cal.yaml"), std::string::npos) << e.what();
  }
  c.ps.knots = {{0.2, 0.1}, {0.6, 1.2}};
  EXPECT_THROW(c.Validate("cal.yaml"), core::ConfigError);
  c.ps.knots = {{0.2, 0.1}, {0.6, 0.9}};
  EXPECT_NO_THROW(c.Validate("cal.yaml"));
}

}  // namespace
}  // namespace toponav::planning

#include "experiments/subgoal_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "experiments/results_io.h"

namespace toponav::experiments {
namespace {

// 100 pieces at each Ps estimate 0.01, 0.03, ..., 0.99, of which round(100 * truth(estimate)) lead to the goal.
std::vector<PieceSample> Samples(double (*truth)(double)) {
  std::vector<PieceSample> out;
  for (int b = 0; b < 50; ++b) {
    const double x = 0.01 + 0.02 * b;
    const int positives = int(std::lround(100 * truth(x)));
    for (int i = 0; i < 100; ++i) out.push_back({{x, 10.0 + i, 50.0}, {i < positives ? 1.0 : 0.0, 40.0, 20.0}});
  }
  return out;
}

TEST(SubgoalCalibrationFit, MapsPsToTheShareOfItsBinWhoseGoalWasReachable) {
  const CalibrationFit fit = FitSubgoalCalibration(Samples([](double x) { return x * x; }));
  const auto& c = fit.calibration;
  ASSERT_GE(c.ps.knots.size(), 10u);
  for (double x : {0.15, 0.45, 0.75, 0.9}) EXPECT_NEAR(c.ps(x), x * x, 0.02) << "Ps estimate " << x;
  EXPECT_LT(fit.cross_entropy[1], fit.cross_entropy[0]);
  size_t successes = 0;
  for (int b = 0; b < 50; ++b) successes += size_t(std::lround(100 * std::pow(0.01 + 0.02 * b, 2)));
  EXPECT_EQ(fit.successes, successes);
  EXPECT_EQ(fit.samples, 5000u);
  const planning::SubgoalProperties p = c.Apply({0.5, 12.0, 34.0});
  EXPECT_EQ(p.delta_success, 12.0) << "the costs as the network gives them";
  EXPECT_EQ(p.exploration, 34.0);
}

TEST(SubgoalCalibrationFit, PsNeverFallsAsTheEstimateRises) {
  // Truth falls between 0.4 and 0.6: those bins are pooled into one knot.
  const CalibrationFit fit = FitSubgoalCalibration(Samples([](double x) { return x > 0.4 && x < 0.6 ? 0.2 : x; }));
  const auto& k = fit.calibration.ps.knots;
  for (size_t i = 1; i < k.size(); ++i) {
    EXPECT_GT(k[i].first, k[i - 1].first);
    EXPECT_GE(k[i].second, k[i - 1].second) << "knot " << i;
  }
}

TEST(SubgoalCalibrationFile, WritesAndReadsBackTheKnotsAndNamesWhatIsWrong) {
  const auto dir = std::filesystem::temp_directory_path() / "toponav_calibration_test";
  std::filesystem::create_directories(dir);
  planning::SubgoalCalibration c;
  c.ps.knots = {{0.05, 0.001}, {0.5, 0.25}, {0.97, 0.95}};
  const std::string path = (dir / "cal.yaml").string();
  WriteTextFile(path, SubgoalCalibrationYaml(c, {"a comment"}));
  EXPECT_EQ(LoadSubgoalCalibration(path).ps.knots, c.ps.knots);
  WriteTextFile(path, "ps: [[0.1, 0.0], [0.5, 1.5]]\n");
  try {
    LoadSubgoalCalibration(path);
    FAIL() << "no error";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("ps[1]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  WriteTextFile(path, "ps: []\nexploration: []\n");
  EXPECT_THROW(LoadSubgoalCalibration(path), core::ConfigError) << "an unknown key";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace toponav::experiments

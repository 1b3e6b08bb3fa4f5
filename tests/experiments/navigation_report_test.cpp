#include "experiments/navigation_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include "core/error.h"

namespace toponav::experiments {
namespace {

TrialRecord Record(const std::string& planner, uint64_t seed, double cost, bool reached = true, bool ok = true) {
  TrialRecord r;
  r.id = {core::WorldKind::kGuidedMaze, 1, seed, planner};
  r.ok = ok;
  r.success = reached;
  r.distance = cost;
  r.steps = int(cost);
  return r;
}

TEST(NavigationReport, ReductionIsTheRatioOfTotalsOverTheSeedsBothPlannersFinished) {
  const std::vector<TrialRecord> records{
      Record("optimistic", 1, 100), Record("optimistic", 2, 200), Record("optimistic", 3, 300, false),
      Record("lsp", 1, 50), Record("lsp", 2, 150), Record("lsp", 3, 0, false, false),  // crashed: left out
      Record("", 1, 10)};  // a search trial: not a navigation row
  const auto rows = SummarizeNavigation(records);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].planner, "optimistic") << "the baseline comes first";
  EXPECT_EQ(rows[0].reached, 2);
  EXPECT_EQ(rows[0].trials, 3);
  EXPECT_DOUBLE_EQ(rows[0].total_cost, 600.0) << "a trial short of the goal keeps its cost in the totals";
  EXPECT_TRUE(std::isnan(rows[0].reduction));
  EXPECT_TRUE(std::isnan(rows[0].median_ratio));
  EXPECT_EQ(rows[1].planner, "lsp");
  EXPECT_EQ(rows[1].failed, 1);
  EXPECT_EQ(rows[1].paired, 2);
  EXPECT_NEAR(rows[1].reduction, (300.0 - 200.0) / 300.0, 1e-12);
  EXPECT_DOUBLE_EQ(rows[1].mean_cost, 100.0);
  EXPECT_NEAR(rows[1].median_ratio, 0.625, 1e-12) << "per trial: 50/100 and 150/200";
  const std::string md = NavigationMarkdown(rows, records);
  EXPECT_NE(md.find("| guided_maze | lsp | 2/3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("33.3 % (2 seeds) | 0.625 | - |"), std::string::npos) << "no shortest ways recorded\n" << md;
  EXPECT_NE(md.find("Short of the goal (2):"), std::string::npos) << md;
  EXPECT_NE(md.find("- guided_maze/optimistic/s3: "), std::string::npos) << md;
  EXPECT_NE(md.find("- guided_maze/lsp/s3: failed"), std::string::npos) << md;
  const std::string png =
      (std::filesystem::temp_directory_path() / ("toponav_costs_" + std::to_string(::getpid()) + ".png")).string();
  WriteCostScatter(records, png);
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
  std::filesystem::remove(png);
}

TEST(NavigationReport, DetourIsTotalCostOverTotalShortestWayOfTheTrialsThatReachedTheGoal) {
  std::vector<TrialRecord> records{Record("optimistic", 1, 120), Record("optimistic", 2, 300),
                                   Record("optimistic", 3, 500, false), Record("optimistic", 4, 90)};
  records[0].shortest = 100;
  records[1].shortest = 200;
  records[2].shortest = 50;  // short of the goal: its cost is no way's length
  const auto rows = SummarizeNavigation(records);  // seed 4 has none recorded (an older record): left out
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0].over_shortest, 420.0 / 300.0, 1e-12);
  EXPECT_NE(NavigationMarkdown(rows).find("| - | 1.400 |"), std::string::npos) << NavigationMarkdown(rows);
}

TEST(NavigationReport, TrialKeysNameThePlannerInsteadOfTheAgentCount) {
  EXPECT_EQ((TrialId{core::WorldKind::kGuidedMaze, 1, 10000, "optimistic"}.Key()), "guided_maze/optimistic/s10000");
  EXPECT_EQ((TrialId{core::WorldKind::kLabyrinth, 3, 10000, ""}.Key()), "labyrinth/a3/s10000");
  const Config c =
      ParseConfig("bench:\n  rows:\n    - {kind: guided_maze, planner: optimistic}\n  num_seeds: 2\n", "m.yaml");
  const auto trials = ListTrials(c.bench);
  ASSERT_EQ(trials.size(), 2u);
  EXPECT_EQ(trials[1].Key(), "guided_maze/optimistic/s10001");
  try {
    ParseConfig("bench:\n  rows:\n    - {kind: guided_maze, planner: greedy}\n", "m.yaml");
    FAIL() << "an unknown planner is an error";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "bench.rows[0].planner");
  }
  EXPECT_THROW(ParseConfig("bench:\n  rows:\n    - {kind: guided_maze, planner: optimistic, agents: 2}\n", "m.yaml"),
               core::ConfigError);
}

}  // namespace
}  // namespace toponav::experiments

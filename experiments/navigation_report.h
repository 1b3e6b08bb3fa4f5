#pragma once
// `toponav report` for goal-directed navigation trials (the maze benchmark, paper Sec. V): per world kind and
// planner the trials that reached the goal, the mean and total cost (distance travelled) and the reduction
// against the optimistic planner, (total optimistic - total planner) / total optimistic over the seeds both
// ran (lsp.md §4.4: failed trials stay in the totals); and the paper's scatter plot.
#include <string>
#include <vector>

#include "experiments/batch.h"

namespace toponav::experiments {

struct NavigationReportRow {
  core::WorldKind kind = core::WorldKind::kGuidedMaze;
  std::string planner;
  int trials = 0, reached = 0, failed = 0;  // failed: the run threw or crashed (left out of the means)
  double mean_cost = 0.0, total_cost = 0.0;
  // Against the optimistic planner on the seeds both finished (NaN for the optimistic row, or without one).
  double reduction = 0.0;
  int paired = 0;                           // seeds the reduction is over
  double median_ratio = 0.0;                // median over those seeds of planner cost / optimistic cost (NaN as above)
  double mean_steps = 0.0, mean_iou = 0.0, mean_wall_s = 0.0;
  // Over the trials that reached the goal: total cost / total true shortest way (1: no detour; NaN where the
  // records have no shortest way).
  double over_shortest = 0.0;
  // What the planner had to go on: the sensors its trials name, and "+ true world" where it was given the true
  // world ("?" for records that do not say).
  std::string inputs;
};

// Rows for the records that name a planner, by kind then planner (optimistic first).
std::vector<NavigationReportRow> SummarizeNavigation(const std::vector<TrialRecord>& records);
// The table, then the trials that did not reach the goal (key, end reason, steps), one line each.
std::string NavigationMarkdown(const std::vector<NavigationReportRow>& rows,
                               const std::vector<TrialRecord>& records = {});
std::string NavigationCsv(const std::vector<NavigationReportRow>& rows);
// One panel per (kind, planner other than optimistic): each seed a point at (optimistic cost, planner cost),
// with the y = x line; below the line the planner travelled less.  PNG.
void WriteCostScatter(const std::vector<TrialRecord>& records, const std::string& png_path);

}  // namespace toponav::experiments

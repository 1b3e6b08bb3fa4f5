#pragma once
// How well a subgoal network's frontier estimates match the truth: runs through worlds made as the training
// data is (experiments/subgoal_data.h: optimistic runs through guided mazes, one-agent searches with the goal
// at the agent elsewhere), and at every sample the network's per-cell Ps, success and exploration costs
// (through the learned sensor, as the planners get them) against the true properties of the frontier cells
// the pose sees.  Held-out quality: benchmark seeds (10000 up) the network never trained on.
#include <cstdint>
#include <functional>
#include <vector>

#include "core/world.h"
#include "experiments/config.h"
#include "experiments/sensor_factory.h"

namespace toponav::experiments {

struct SubgoalEvalOptions {
  core::WorldKind kind = core::WorldKind::kGuidedMaze;
  std::vector<uint64_t> seeds;  // worlds of that kind
  int every = 6;                // a sample every this many steps of each run
};

struct SubgoalEval {
  int worlds = 0, examples = 0;
  size_t cells = 0, positives = 0;  // frontier cells scored, of which the goal is reachable through (Ps = 1)
  double auc = 0.5;                 // of the predicted Ps over the cells (0.5: no better than chance)
  double cross_entropy = 0.0;       // mean over the cells
  double mean_ps_positive = 0.0, mean_ps_negative = 0.0;
  double success_mae = 0.0;      // mean |error| of the success cost over positive cells
  double exploration_mae = 0.0;  // ... of the exploration cost over negative cells
  // The mean true and estimated exploration costs over negative cells.
  double exploration_truth = 0.0, exploration_estimate = 0.0;
  // The order of a sample's frontiers by exploration cost (each frontier's estimate: the mean over its
  // cells), as a search's tour uses it: of the pairs whose true costs differ by kOrderRatio or more, the
  // share the estimates put in the same order (ties half); 0.5 without such pairs.
  static constexpr double kOrderRatio = 1.5;
  size_t frontier_pairs = 0;
  double exploration_order = 0.5;
  // The Ps AUC of the cells nearer than 20, from 20 to 40, and farther than 40 (world units) from the pose,
  // with their counts: how quality falls with range.
  static constexpr double kBandEdges[2] = {20.0, 40.0};
  double band_auc[3] = {0.5, 0.5, 0.5};
  size_t band_cells[3] = {0, 0, 0};
  double seconds = 0.0;
  double positive_rate() const { return cells > 0 ? double(positives) / double(cells) : 0.0; }
};

// The area under the ROC curve of 'scores' for the 'positive' flags (ties count half); 0.5 when either
// class is empty.
double RocAuc(const std::vector<float>& scores, const std::vector<bool>& positive);

// One sample's frontiers, each with its true exploration cost and the mean estimate over its cells.
struct FrontierCost {
  double truth = 0.0, estimate = 0.0;
};

// Adds to *agree (ties half) and *pairs the pairs of 'frontiers' whose true costs differ by
// SubgoalEval::kOrderRatio or more, agreeing when the estimates order them as the truths do.
void CountOrderedPairs(const std::vector<FrontierCost>& frontiers, double* agree, size_t* pairs);

// Runs config's planner and sensor settings (the data runs' sensor: config.sensor) through the worlds; the
// network is 'model' (a subgoal model file, through the learned sensor).  'progress' after each world.
SubgoalEval EvaluateSubgoalEstimates(const Config& config, const LearnedSensorOptions& model,
                                     const SubgoalEvalOptions& options,
                                     const std::function<void(int, int)>& progress = nullptr);

}  // namespace toponav::experiments

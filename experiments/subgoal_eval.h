#pragma once
// How well a subgoal network's frontier estimates match the truth: optimistic runs through guided mazes (as
// the training data is made, experiments/subgoal_data.h), and at every sample the network's per-cell Ps,
// success and exploration costs (through the learned sensor, as the LSP planner gets them) against the true
// properties of the frontier cells the pose sees.  Held-out quality: benchmark seeds (10000 up) the network
// never trained on.
#include <cstdint>
#include <functional>
#include <vector>

#include "experiments/config.h"
#include "experiments/sensor_factory.h"

namespace toponav::experiments {

struct SubgoalEvalOptions {
  std::vector<uint64_t> seeds;  // guided mazes
  int every = 6;                // a sample every this many steps of each run
};

struct SubgoalEval {
  int mazes = 0, examples = 0;
  size_t cells = 0, positives = 0;   // frontier cells scored, of which the goal is reachable through (Ps = 1)
  double auc = 0.5;                  // of the predicted Ps over the cells (0.5: no better than chance)
  double cross_entropy = 0.0;        // mean over the cells
  double mean_ps_positive = 0.0, mean_ps_negative = 0.0;
  double success_mae = 0.0;          // mean |error| of the success cost over positive cells
  double exploration_mae = 0.0;      // ... of the exploration cost over negative cells
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

// Runs config's planner and sensor settings (the data runs' sensor: config.sensor) through the mazes; the
// network is 'model' (a subgoal model file, through the learned sensor).  'progress' after each maze.
SubgoalEval EvaluateSubgoalEstimates(const Config& config, const LearnedSensorOptions& model,
                                     const SubgoalEvalOptions& options,
                                     const std::function<void(int, int)>& progress = nullptr);

}  // namespace toponav::experiments

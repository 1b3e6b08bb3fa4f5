#pragma once
// Calibrating a subgoal network's Ps for Learned Subgoal Planning (planning/subgoal_calibration.h): LSP runs
// through guided mazes with the network's outputs taken as they are, each frontier piece's estimate (its cells
// averaged over the views that saw them, as the planner gets it) beside its true properties, and Ps mapped to
// the share of the pieces in its bin through which the goal could be reached.  (The two costs mapped the same
// way made LSP dearer on tuning mazes: results/maze_learned/README.md.)  Also the file lsp.calibration names.
// `toponav eval-sensor --subgoal --calibrate FILE` measures and writes it; measure on tuning mazes only.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "experiments/config.h"
#include "planning/subgoal_calibration.h"

namespace toponav::experiments {

struct PieceSample {
  planning::SubgoalProperties estimate, truth;  // truth.ps is 0 or 1
};

struct CalibrationFit {
  // Pieces binned by their Ps estimate between these edges; a bin of fewer than kMinBinSamples pieces gives no
  // knot; the knots are then made non-decreasing (adjacent bins pooled, weighted by their counts): a higher
  // estimate never means a lower chance.
  static constexpr std::array<double, 14> kPsEdges{0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4,
                                                   0.5,  0.6,  0.7, 0.8,  0.9, 0.95, 0.98};
  static constexpr int kMinBinSamples = 50;
  planning::SubgoalCalibration calibration;
  size_t samples = 0, successes = 0;      // pieces, of which Ps 1
  std::array<double, 2> cross_entropy{};  // of Ps over the pieces, before and after the mapping
};

CalibrationFit FitSubgoalCalibration(const std::vector<PieceSample>& samples);

// Planner "lsp" through the guided mazes 'seeds' (config's sensor, mapping, navigation and lsp settings;
// lsp.calibration set aside): every piece the network's outputs covered, at every estimate.  'progress'
// after each maze.
std::vector<PieceSample> MeasurePieceEstimates(const Config& config, const std::vector<uint64_t>& seeds,
                                               const std::function<void(int, int)>& progress = nullptr);

// Reads a calibration file: key ps, a list of [estimate, truth] pairs (none: Ps as the network gives it).
// Throws core::ConfigError naming the file and the key.
planning::SubgoalCalibration LoadSubgoalCalibration(const std::string& path);
// The file's text, after 'comment' (each line gets "# ").
std::string SubgoalCalibrationYaml(const planning::SubgoalCalibration& calibration,
                                   const std::vector<std::string>& comment);

}  // namespace toponav::experiments

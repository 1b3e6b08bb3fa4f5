#pragma once
// The learned estimator of Learned Subgoal Planning (paper Sec. V): a network's per-cell subgoal outputs on
// its range-bearing grid (core::Observation::subgoal), averaged
// for each frontier over the cells it covers and over every observation that saw them -- the paper
// averages; the reference estimated once, from the first image (lsp.md §3.4).  The sums are kept per place
// (world cell), so an estimate settles as observations accumulate, whatever ids the map gives its frontiers
// as they grow: an estimate over a sliding window changed with every step and the agent dithered between
// frontiers.  A cell counts for an observation when it lies within the grid's range and no map wall stands
// between it and the pose.  A frontier no observation has seen keeps the optimistic default (Ps 1, costs 0);
// the others' Ps goes through the network's calibration (planning/subgoal_calibration.h), if any.
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/observation.h"
#include "planning/lsp_planner.h"
#include "planning/subgoal_calibration.h"

namespace toponav::planning {

class CellAveragingEstimator : public SubgoalEstimator {
 public:
  // 'pending': at most this many observations wait for the next estimate (the latest ones).
  explicit CellAveragingEstimator(int pending = 10, SubgoalCalibration calibration = {})
      : max_pending_(pending), calibration_(std::move(calibration)) {}
  // Queues the observation if it carries subgoal cells.  Throws core::DataError for cells whose count does not
  // match their grid.
  void Observe(const core::Observation& z);
  // Adds the queued observations' outputs at the frontiers' cells to the running sums, then averages them.
  std::vector<SubgoalProperties> Estimate(const SubgoalGrid& grid, const OrderingProblem& distances) override;
  size_t observations() const { return observed_; }  // accepted so far
  // Per frontier of the last Estimate: 1 where some observation saw its cells (it has an estimate of its own).
  const std::vector<char>& seen() const { return seen_; }

 private:
  struct Seen {
    core::Pose2 pose;
    core::SubgoalCells cells;
  };
  struct Sum {
    double ps = 0, delta_success = 0, exploration = 0;
    int count = 0;
  };
  void Accumulate(const Seen& s, const SubgoalGrid& grid);
  int max_pending_;
  SubgoalCalibration calibration_;
  std::vector<char> seen_;
  std::deque<Seen> pending_;
  std::unordered_map<uint64_t, Sum> sums_;  // by world cell
  size_t observed_ = 0;
};

}  // namespace toponav::planning

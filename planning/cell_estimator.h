#pragma once
// The learned estimator of Learned Subgoal Planning (paper Sec. V): a network's per-cell subgoal outputs on
// its range-bearing grid (core::Observation::cells, channels "ps", "delta_success", "exploration"), averaged
// for each frontier over the cells it covers and over every observation that saw them -- the paper
// averages; the reference estimated once, from the first image (lsp.md §3.4).  The sums are kept per place
// (world cell), so an estimate settles as observations accumulate, whatever ids the map gives its frontiers
// as they grow: an estimate over a sliding window changed with every step and the agent dithered between
// frontiers.  A cell counts for an observation when it lies within the grid's range and no map wall stands
// between it and the pose.  A frontier no observation has seen keeps the optimistic default (Ps 1, costs 0).
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include "core/observation.h"
#include "planning/lsp_planner.h"

namespace toponav::planning {

class CellAveragingEstimator : public SubgoalEstimator {
 public:
  // 'pending': at most this many observations wait for the next estimate (the latest ones).
  explicit CellAveragingEstimator(int pending = 10) : max_pending_(pending) {}
  // Queues the observation if it carries the three channels.  Throws core::DataError for a grid whose
  // channels lack one of them or whose size does not match.
  void Observe(const core::Observation& z);
  // Adds the queued observations' outputs at the frontiers' cells to the running sums, then averages them.
  std::vector<SubgoalProperties> Estimate(const SubgoalGrid& grid, const OrderingProblem& distances) override;
  size_t observations() const { return observed_; }  // accepted so far

 private:
  struct Seen {
    core::Pose2 pose;
    core::CellGrid cells;
    int ps = 0, delta_success = 0, exploration = 0;  // channel indices
  };
  struct Sum {
    double ps = 0, delta_success = 0, exploration = 0;
    int count = 0;
  };
  void Accumulate(const Seen& s, const SubgoalGrid& grid);
  int max_pending_;
  std::deque<Seen> pending_;
  std::unordered_map<uint64_t, Sum> sums_;  // by world cell
  size_t observed_ = 0;
};

}  // namespace toponav::planning

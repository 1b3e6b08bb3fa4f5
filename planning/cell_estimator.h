#pragma once
// The learned estimator of Learned Subgoal Planning (paper Sec. V): a network's per-cell subgoal outputs on
// its range-bearing grid (core::Observation::cells, channels "ps", "delta_success", "exploration"), averaged
// for each frontier over the cells it covers in every recent observation that sees them -- the paper
// averages; the reference estimated once, from the first image (lsp.md §3.4).  A cell counts for an
// observation when it lies within the grid's range and no map wall stands between it and the pose.  A
// frontier no observation sees keeps the optimistic default (Ps 1, costs 0).
#include <deque>
#include <vector>

#include "core/observation.h"
#include "planning/lsp_planner.h"

namespace toponav::planning {

class CellAveragingEstimator : public SubgoalEstimator {
 public:
  explicit CellAveragingEstimator(int history = 10) : history_(history) {}
  // Keeps the observation if it carries the three channels (the last 'history' such ones).  Throws
  // core::DataError for a grid whose channels lack one of them or whose size does not match.
  void Observe(const core::Observation& z);
  std::vector<SubgoalProperties> Estimate(const SubgoalGrid& grid, const OrderingProblem& distances) override;
  size_t observations() const { return seen_.size(); }

 private:
  struct Seen {
    core::Pose2 pose;
    core::CellGrid cells;
    int ps = 0, delta_success = 0, exploration = 0;  // channel indices
  };
  int history_;
  std::deque<Seen> seen_;
};

}  // namespace toponav::planning

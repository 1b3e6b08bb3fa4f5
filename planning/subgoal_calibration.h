#pragma once
// What a subgoal network's Ps means.  Measured on tuning mazes (experiments/subgoal_calibration.h: Learned
// Subgoal Planning runs, each frontier piece's estimate beside its true Ps), an estimate maps to the share of
// the pieces estimated near it through which the goal could be reached: where the committed network says 0.5,
// a quarter of them.  The expected cost of an order (planning/subgoal_ordering.h) takes Ps at its word.
#include <string>
#include <utility>
#include <vector>

#include "planning/subgoal_ordering.h"

namespace toponav::planning {

// y(x) through the knots (x ascending), linear between them and flat past the first and the last; no knots:
// x itself.
struct PiecewiseLinear {
  std::vector<std::pair<double, double>> knots;
  double operator()(double x) const;
  // Throws core::ConfigError naming 'source' and 'key' unless the x are finite and strictly ascending and the
  // y finite and within [lo, hi].
  void Validate(const std::string& source, const std::string& key, double lo, double hi) const;
};

struct SubgoalCalibration {
  PiecewiseLinear ps;  // estimated Ps -> the true share, knots within [0, 1]; none: Ps as the network gives it
  bool empty() const { return ps.knots.empty(); }
  SubgoalProperties Apply(const SubgoalProperties& estimate) const;  // the costs as they are
  void Validate(const std::string& source) const;                    // the knots (key ps)
};

}  // namespace toponav::planning

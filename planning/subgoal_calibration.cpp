#include "planning/subgoal_calibration.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace toponav::planning {

double PiecewiseLinear::operator()(double x) const {
  if (knots.empty()) return x;
  if (x <= knots.front().first) return knots.front().second;
  if (x >= knots.back().first) return knots.back().second;
  const auto hi = std::upper_bound(knots.begin(), knots.end(), x,
                                   [](double v, const std::pair<double, double>& k) { return v < k.first; });
  const auto lo = hi - 1;
  const double t = (x - lo->first) / (hi->first - lo->first);
  return lo->second + t * (hi->second - lo->second);
}

void PiecewiseLinear::Validate(const std::string& source, const std::string& key, double lo, double hi) const {
  for (size_t i = 0; i < knots.size(); ++i) {
    const auto [x, y] = knots[i];
    const std::string at = key + "[" + std::to_string(i) + "]";
    if (!std::isfinite(x) || (i > 0 && !(x > knots[i - 1].first)))
      throw core::ConfigError(source, at, std::to_string(x), "estimates must be finite and strictly ascending");
    if (!std::isfinite(y) || y < lo || y > hi)
      throw core::ConfigError(source, at, std::to_string(y),
                              "the truth must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
}

SubgoalProperties SubgoalCalibration::Apply(const SubgoalProperties& e) const {
  return {ps(e.ps), e.delta_success, e.exploration};
}

void SubgoalCalibration::Validate(const std::string& source) const { ps.Validate(source, "ps", 0.0, 1.0); }

}  // namespace toponav::planning

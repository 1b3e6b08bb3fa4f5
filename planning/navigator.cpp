#include "planning/navigator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace toponav::planning {

double PathBudget(const NavigatorInput& input, int reserve_steps) {
  TOPONAV_CHECK(input.step_length > 0, "step length " << input.step_length);
  if (input.max_steps <= 0) return std::numeric_limits<double>::infinity();
  return std::max(0, input.max_steps - input.step - reserve_steps) * input.step_length;
}

core::Vec2 RandomNudge(double distance, core::Rng& rng) {
  const double angle = rng.Uniform(-core::kPi, core::kPi);
  return core::Vec2{std::cos(angle), std::sin(angle)} * distance;
}

}  // namespace toponav::planning

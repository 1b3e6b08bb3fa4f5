#pragma once
// A navigator's input for one agent standing at 'at' on a hand-made map view (its trail: that one position; an
// empty observation this step), for planning tests with no simulator.
#include <vector>

#include "core/observation.h"
#include "mapping/mapping.h"
#include "planning/navigator.h"

namespace toponav::planning::testing {

struct OneAgentStep {
  OneAgentStep(const mapping::MapView& view, const core::Vec2& at, double step_length = 1.8) : trails{{at}} {
    input.step_length = step_length;
    input.view = &view;
    input.poses = {{at.x, at.y, 0.0}};
    input.observations = &observations;
    input.trails = &trails;
  }
  OneAgentStep(const OneAgentStep&) = delete;  // 'input' points into this object
  OneAgentStep& operator=(const OneAgentStep&) = delete;

  std::vector<std::vector<core::Vec2>> trails;
  std::vector<core::Observation> observations = std::vector<core::Observation>(1);
  NavigatorInput input;
};

}  // namespace toponav::planning::testing

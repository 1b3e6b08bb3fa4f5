#pragma once
// A pose-in sensor made of the renderer and an image detector: each Observe renders the agent's panorama at
// its pose and hands it to the detector, with the goal (if any) in the agent's frame.  This is how a learned
// (or any image-based) detector runs in the simulator's agent loop.
#include <memory>
#include <optional>

#include "core/observation.h"
#include "core/world.h"
#include "sim/render.h"

namespace toponav::sim {

// 'goal': in world coordinates, passed to the detector relative to each pose (goal-conditioned networks);
// none: the detector sees no goal, unless 'goal_at_agent' tells it the goal is where the agent stands (a
// search's exploration estimates).  Throws core::ConfigError for bad render options.
std::unique_ptr<core::VertexSensorInterface> CreateRenderingSensor(
    const core::World& world, const RenderOptions& render, std::unique_ptr<core::VertexDetectorInterface> detector,
    std::optional<core::Vec2> goal = std::nullopt, bool goal_at_agent = false);

}  // namespace toponav::sim

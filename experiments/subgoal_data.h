#pragma once
// Training samples for the subgoal network (paper Sec. V; lsp.md §2.3): an agent driven by the optimistic
// planner through a training maze on the shared agent loop; every 'every' steps the pose, the goal, and the
// true properties of the frontiers on offer (planning::TrueSubgoalProperties on the agent's own map)
// rasterized on the range-bearing grid where the agent sees them.  The panorama and the vertex labels of a
// sample are a pure function of the world and the pose (rendered when needed).
#include <cstdint>
#include <vector>

#include "core/world.h"
#include "experiments/config.h"
#include "planning/subgoal_grid.h"

namespace toponav::experiments {

struct SubgoalSample {
  uint64_t world_seed = 0;
  int step = 0;
  core::Pose2 pose;
  core::Vec2 goal;
  int frontiers = 0;                   // frontiers labelled (on offer and seen)
  planning::SubgoalLabelGrid labels;
};

// The samples of one optimistic run through 'maze' (seed: the run's randomness); steps without a frontier
// cell in view give none.  Uses config.lsp (raster cell, clearance) and config.bench.max_steps.
std::vector<SubgoalSample> CollectSubgoalSamples(const core::World& maze, const Config& config, uint64_t seed,
                                                 int every, const core::RangeBearingGrid& grid = {});

}  // namespace toponav::experiments

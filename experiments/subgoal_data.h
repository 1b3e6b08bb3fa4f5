#pragma once
// Training samples for the subgoal network (paper Sec. V; lsp.md §2.3): an agent driven by the optimistic
// planner through a training maze on the shared agent loop; every 'every' steps the pose, the goal, and the
// true properties of the frontiers on offer (planning::TrueSubgoalProperties on the agent's own map)
// rasterized on the range-bearing grid where the agent sees them.  In other worlds the agent searches (the
// config's search options, one agent) and the goal is where it stands, so every frontier is labelled with
// its exploration cost (planning::ProblemWithoutDistances).  The panorama and the vertex labels of a sample are
// a pure function of the world and the pose (rendered when needed).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/config.h"
#include "planning/subgoal_grid.h"
#include "sim/training_data.h"
#include "sim/vertex_labels.h"

namespace toponav::experiments {

struct SubgoalSample {
  uint64_t world_seed = 0;
  int step = 0;
  core::Pose2 pose;
  core::Vec2 goal;
  int frontiers = 0;                   // frontiers labelled (on offer and seen)
  planning::SubgoalLabelGrid labels;
};

// The samples of one run through 'world' (seed: the run's randomness): optimistic in a guided maze, a search
// elsewhere; steps without a frontier cell in view give none.  Uses config.lsp (raster cell, clearance) and
// config.bench (max_steps, mcmc_every).
std::vector<SubgoalSample> CollectSubgoalSamples(const core::World& world, const Config& config, uint64_t seed,
                                                 int every, const core::RangeBearingGrid& grid = {});

// A training example of the subgoal network: the panorama at a sample's pose, its vertex labels (32x128), the
// goal in the agent's frame and the subgoal labels (64x256).
struct SubgoalExample {
  uint64_t world_seed = 0;
  int step = 0;
  core::Pose2 pose;
  core::Panorama image;
  sim::VertexLabelGrid labels;
  core::Vec2 goal;
  core::SubgoalLabelGrid subgoal;
};

// How the examples' runs go, in words: "optimistic runs" in guided mazes, "one-agent searches (the goal at the
// agent)" elsewhere.
std::string SubgoalRunsText(const SubgoalDataOptions& o);

// The examples of a split's worlds (config.subgoal_data, of its kind): one run through each (its seed the
// world's), a sample every config.subgoal_data.every steps.  'progress' is told after each maze (mazes done, of
// how many, examples so far).
std::vector<SubgoalExample> MakeSubgoalExamples(const Config& config, sim::Split split,
                                                const std::function<void(int, int, size_t)>& progress = nullptr);

}  // namespace toponav::experiments

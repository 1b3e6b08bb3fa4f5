#pragma once
// The agent loop shared by every run in the simulator (a search trial, `toponav map`'s scripted drive, a
// goal-directed navigation trial): agents start at the world's start; every step each observes (the sensor
// the config asks for), the observations join one map (one that repeats another agent's this step, pose and
// detections alike, joins it once), MCMC runs on its cadence, the navigator (planning/navigator.h) says where
// each agent goes (or that the run ends), and the agents move one step (Box2D), each nudged where the
// navigator asks.  After the last step a final MCMC call and an
// exact view give the map that metrics score.  A run is a pure function of its inputs and seed.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/rng.h"
#include "core/world.h"
#include "experiments/config.h"
#include "mapping/mapping.h"
#include "planning/navigator.h"

namespace toponav::experiments {

struct LoopOptions {
  int num_agents = 1;
  int max_steps = 400;
  // MCMC on steps 0, every, 2*every, ... with 'mcmc_samples' proposals a call (negative: mapping.mcmc_samples);
  // 0: never, and then the map keeps every vertex with enough detections (mapping.defer_to_mcmc off).
  int mcmc_every = 5;
  int mcmc_samples = -1;
  // Goal-directed runs: the goal, which the sensor passes to goal-conditioned detectors; none for a search.
  std::optional<core::Vec2> goal;
  // After every step with the map the navigator used and the agents' paths so far, and once more with the final
  // map the metrics score (videos).
  std::function<void(const mapping::MapView&, const std::vector<std::vector<core::Vec2>>&)> on_step;
};

struct LoopResult {
  int steps = 0;                                // steps the navigator planned (the last one may have ended the run)
  bool ended_by_navigator = false;              // false: the step cap
  std::vector<std::vector<core::Vec2>> paths;   // per agent, from the start
  std::vector<double> distance;                 // travelled per agent
  mapping::MapView final_view;                  // after the final MCMC call, known space exact
  std::unique_ptr<mapping::Mapper> mapper;      // the map, for further questions (its posterior)
  // Where the time went (seconds): observations and map updates, MCMC, views (known space, frontiers),
  // planning and motion; and how many MCMC calls were made during the steps.
  double observe_s = 0.0, mcmc_s = 0.0, view_s = 0.0, plan_s = 0.0;
  int mcmc_calls = 0;
};

// Runs 'navigator' in 'world'.  The sensor draws from DeriveSeed(seed, 1), MCMC and the navigator's nudges from
// DeriveSeed(seed, 2).
LoopResult RunAgentLoop(const core::World& world, const Config& config, const LoopOptions& options,
                        planning::Navigator& navigator, uint64_t seed);

}  // namespace toponav::experiments

#pragma once
// One search trial (paper Sec. IV): the search navigator (planning/search_navigator.h) on the agent loop
// (experiments/agent_loop.h), scored by the final map.  A trial is a pure function of its spec.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/agent_loop.h"
#include "experiments/config.h"
#include "planning/navigation.h"

namespace toponav::experiments {

// One trial's run; how agents search and plan comes from the config (config.search, config.planning).
struct TrialOptions {
  int num_agents = 1;
  int max_steps = 400;          // step cap (the reference's 400 iterations)
  int mcmc_every = 5;           // MCMC cadence in steps (0: never), with mapping.mcmc_samples proposals a call
  // The cadence in open worlds (config: open_world.mcmc_every), at the same proposals per step: a call there
  // proposes mapping.mcmc_samples * open_world_mcmc_every / mcmc_every (at least 1).  The last call of a
  // trial always proposes mapping.mcmc_samples.
  int open_world_mcmc_every = 2;
  // Called after every step with the map the planners used and the agents' paths so far, and once more
  // with the final map the metrics score (videos).
  std::function<void(const mapping::MapView&, const std::vector<std::vector<core::Vec2>>&)> on_step;
  // SearchNavigator::on_plan: every step before agents move (traces, training data).
  std::function<void(const planning::NavigatorInput&, const std::vector<planning::FrontierTarget>&,
                     const std::vector<planning::FrontierChoice>&)>
      on_plan;
};

struct TrialResult {
  uint64_t seed = 0;
  int num_agents = 0;
  std::string sensors;            // what the agents sensed with (SensorsUsed: "noisy", "learned", ...)
  bool explored = false;          // no reachable frontier left (none at all, or none reachable for a while)
  bool success = false;
  int steps = 0;
  double iou = 0.0;               // indoor: known space vs true free space; office park: building placement
  std::vector<double> distance;   // travelled per agent
  int nudges = 0;                 // stuck-agent perturbations
  int give_ups = 0;               // frontiers given up (agents stood next to them, or were stuck on the way)
  int inspections = 0;            // map vertices agents were sent to look at before the end: walls run straight
                                  // through them (search.inspect_bend) or the map lacks their walls
                                  // (search.inspect_unwalled)
  int sealed_steps = 0;           // agent-steps spent looking for a wall that seals part of a closed world off
                                  // (search.sealed_reach)
  std::vector<core::Segment2> blocks;  // motion blocks added (search.block_when_stuck)
  std::string end_reason;         // "explored", "unreachable" (frontiers left, none reachable), "step_cap"
  double wall_time_s = 0.0;
  // Where the time went: observations and map updates, MCMC, known space and frontiers, planning and motion.
  double time_map_s = 0.0, time_mcmc_s = 0.0, time_known_s = 0.0, time_plan_s = 0.0;
  std::vector<std::vector<core::Vec2>> paths;  // per agent
};

TrialResult RunSearchTrial(const core::World& world, const Config& config, const TrialOptions& options,
                           uint64_t seed, mapping::MapView* final_view = nullptr);

// Office park metric (paper footnote: buildings detected in the right places, no spurious ones), as the reference
// computes it: IoU of the true buildings and the holes of the known space, i.e. the places the map has enclosed
// without marking them free.  A building not walked all the way around is not enclosed and counts as missed;
// open ground the search never needed to see (far from every building) does not count.
double BuildingPlacementIoU(const core::World& world, const mapping::MapView& map);

// A search trial's map score: KnownSpaceIoU in closed worlds, BuildingPlacementIoU in open ones.
double SearchIoU(const core::World& world, const mapping::MapView& map);

// Where that IoU is lost: per true building, the IoU of it and the holes that overlap it (0 for a building
// no hole overlaps), and the area of holes that overlap no building.
struct BuildingPlacementBreakdown {
  std::vector<double> building_iou;  // per world obstacle
  double spurious_area = 0.0;        // world units^2
};
BuildingPlacementBreakdown BreakDownBuildingPlacement(const core::World& world, const mapping::MapView& map);

}  // namespace toponav::experiments

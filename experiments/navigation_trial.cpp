#include "experiments/navigation_trial.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "experiments/agent_loop.h"
#include "experiments/map_drive.h"
#include "planning/subgoal_grid.h"
#include "sim/paths.h"

namespace toponav::experiments {

using core::Vec2;

namespace {

// The goal navigator's setup from the config: the true world only for the planners defined by knowing it.
planning::GoalNavigatorSetup GoalSetup(const core::World& world, const Config& config, planning::GoalPlanner planner) {
  planning::GoalNavigatorSetup s;
  s.planner = planner;
  s.goal = world.goal;
  s.region = world.bounds;
  s.step_length = MotionFor(config, world).step_length;
  s.navigation = config.navigation;
  s.planning = config.planning;
  s.lsp = config.lsp;
  if (planning::NeedsTrueWorld(planner)) s.truth = &world;
  return s;
}

// Hands each learned estimate's seen pieces to 'hook' beside their true properties (what the oracle would get).
planning::EstimateHook TruthRecorder(const core::World& world, const Config& config, const SubgoalTruthHook& hook) {
  std::shared_ptr<planning::SubgoalEstimator> truth =
      planning::CreateOracleEstimator(world, config.lsp.cell, config.lsp.clearance);
  return [truth, hook](const planning::SubgoalGrid& grid, const planning::OrderingProblem& distances,
                       const std::vector<planning::SubgoalProperties>& estimates, const std::vector<char>& seen) {
    const std::vector<planning::SubgoalProperties> true_properties = truth->Estimate(grid, distances);
    std::vector<planning::SubgoalProperties> seen_estimates, seen_truth;
    for (size_t f = 0; f < estimates.size(); ++f)
      if (seen[f]) seen_estimates.push_back(estimates[f]), seen_truth.push_back(true_properties[f]);
    hook(seen_estimates, seen_truth);
  };
}

}  // namespace

NavigationResult RunNavigationTrial(const core::World& world, const Config& config, const NavigationTrialOptions& o,
                                    uint64_t seed, mapping::MapView* final_view) {
  const auto t0 = std::chrono::steady_clock::now();
  planning::GoalNavigator navigator(GoalSetup(world, config, o.planner));
  navigator.on_decision = o.on_decision;
  navigator.on_plan = o.on_plan;
  if (o.on_subgoal_truth) navigator.set_on_estimate(TruthRecorder(world, config, o.on_subgoal_truth));
  LoopOptions lo;
  lo.max_steps = o.max_steps;
  lo.mcmc_every = o.mcmc_every;
  lo.goal = world.goal;
  lo.on_step = o.on_step;
  const LoopResult loop = RunAgentLoop(world, config, lo, navigator, seed);
  NavigationResult r;
  r.seed = seed;
  r.planner = ToString(o.planner);
  r.sensors = SensorsUsed(config.sensor);
  r.privileged = planning::NeedsTrueWorld(o.planner);
  r.end_reason = navigator.end_reason();
  r.reached = r.end_reason == "goal";
  r.steps = loop.steps;
  r.distance = loop.distance.at(0);
  r.shortest = core::PolylineLength(
      sim::FreePath(world, world.start.position(), world.goal, config.lsp.clearance, config.lsp.cell));
  r.nudges = navigator.counts().nudges;
  r.recovery_steps = navigator.counts().recovery_steps;
  r.repeated_steps = navigator.counts().repeated_steps;
  r.scan_steps = navigator.counts().scan_steps;
  r.scan_walls = navigator.scan_walls();
  r.longest_hold = planning::LongestHold(loop.paths.at(0), config.navigation.stuck_span);
  r.blocks = navigator.added_blocks();
  r.path = loop.paths.at(0);
  r.frontier_ps = navigator.estimates();
  r.iou = KnownSpaceIoU(world, loop.final_view);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (final_view) *final_view = loop.final_view;
  return r;
}

}  // namespace toponav::experiments

#pragma once
// One goal-directed navigation trial (paper Sec. V): the goal navigator (planning/goal_navigator.h) takes one
// agent from the world's start to its goal on the shared agent loop.  The trial ends when the navigator says so
// (goal, stuck, cut off) or at the step cap; its cost is the distance travelled.  The oracle and "known"
// planners get the true world as their declared privileged input, and the record says so.  A trial is a pure
// function of (world, config, planner, seed).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/agent_loop.h"
#include "experiments/config.h"
#include "planning/goal_navigator.h"
#include "planning/lsp_planner.h"
#include "planning/planner.h"

namespace toponav::experiments {

using planning::GoalPlanner;
using planning::NavigationDecision;
using planning::ParseGoalPlanner;

// Each learned estimate's frontier pieces that some observation covered: the estimates beside their true
// properties.
using SubgoalTruthHook = std::function<void(const std::vector<planning::SubgoalProperties>& estimates,
                                            const std::vector<planning::SubgoalProperties>& truth)>;

struct NavigationTrialOptions {
  GoalPlanner planner = GoalPlanner::kOptimistic;
  int max_steps = 600;   // step cap (the reference's maze runs: 600 iterations)
  int mcmc_every = 5;    // MCMC cadence in steps (0: never)
  // Called after every step with the map built so far (the one the planner used, but for "known") and the path
  // so far, and once more with the final map (videos).
  std::function<void(const mapping::MapView&, const std::vector<std::vector<core::Vec2>>&)> on_step;
  // Called every step before the planner with the loop's state and the frontier targets on offer (training
  // data: the frontiers to label).
  std::function<void(const planning::NavigatorInput&, const std::vector<planning::FrontierTarget>&)> on_plan;
  // Called every step that does not end the trial, before the agent moves, with what the planner decided.
  std::function<void(const NavigationDecision&)> on_decision;
  // Planner "lsp": called at every estimate with each frontier piece the network's outputs covered, its
  // estimate (calibrated as lsp.calibration says) beside its true properties (what the oracle would get: the
  // harness's scoring, not the navigator's).
  SubgoalTruthHook on_subgoal_truth;
};

struct NavigationResult {
  uint64_t seed = 0;
  std::string planner;
  std::string sensors;            // what the agent sensed with (SensorsUsed: "learned", "learned+range_ring", ...)
  bool privileged = false;        // the planner was given the true world (oracle, known)
  bool reached = false;           // within navigation.goal_radius of the goal
  int steps = 0;
  double distance = 0.0;          // travelled: the trial's cost
  // The true world's shortest way from start to goal (lsp.clearance from walls, on the lsp.cell raster): about
  // what a planner that knew the maze travels (planner "known" measures it).  0 where the true world has none.
  double shortest = 0.0;
  std::string end_reason;         // "goal", "stuck", "cut_off" (no way to the goal, nothing to explore), "step_cap"
  int nudges = 0;
  // The most consecutive positions within navigation.stuck_span of each other (planning::LongestHold): the
  // trial ends "stuck" where it reaches navigation.stuck_window, so a trial that reached its goal with a long
  // hold came near that end.
  int longest_hold = 0;
  int recovery_steps = 0;  // steps on which the planner found no way to the goal (so the recovery ran)
  int repeated_steps = 0;  // steps of a third or later lap of the same loop, with a path (planning::RepeatedStep)
  int scan_steps = 0;      // steps planned with the range ring's scans, after a hold (navigation.scan_when_held)
  std::vector<core::Segment2> scan_walls;  // the walls those scans showed, merged (planning::ScanWallSet)
  std::vector<core::Segment2> blocks;  // every motion block added (navigation.block_when_stuck), taken back or not
  double iou = 0.0;               // known space of the final map vs the true free space
  double wall_time_s = 0.0;
  std::vector<core::Vec2> path;
  std::vector<planning::FrontierEstimate> frontier_ps;  // the last step's (NavigationDecision::estimates)
};

NavigationResult RunNavigationTrial(const core::World& world, const Config& config,
                                    const NavigationTrialOptions& options, uint64_t seed,
                                    mapping::MapView* final_view = nullptr);

}  // namespace toponav::experiments

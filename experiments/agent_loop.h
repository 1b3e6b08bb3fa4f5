#pragma once
// The agent loop shared by every run in the simulator (a search trial, `toponav map`'s scripted drive, a
// goal-directed navigation trial): agents start at the world's start; every step each observes (the sensor
// the config asks for), the observations join one map (one that repeats another agent's this step, pose and
// detections alike, joins it once), MCMC runs on its cadence, the policy says where each agent goes (or
// that the run ends), and the agents move one step (Box2D).  After the last step a final MCMC call and an
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
#include "sim/motion.h"

namespace toponav::experiments {

// What a policy sees at a step.  The pointers are valid during the call.
struct LoopState {
  int step = 0;
  int max_steps = 0;                                        // the run's step cap (0: none)
  const core::World* world = nullptr;
  const mapping::MapView* view = nullptr;                   // after this step's observations
  std::vector<core::Pose2> poses;                           // before the agents move
  const std::vector<core::Observation>* observations = nullptr;  // this step's, one per agent
  const std::vector<std::vector<core::Vec2>>* trails = nullptr;  // each agent's positions so far
  double step_length = 0.0;                                 // how far an agent steps in this world
};

// How far (world units of path) an agent can still walk before the step cap while keeping 'reserve_steps'
// steps in hand: (max_steps - step - reserve_steps) * step_length, at least 0; infinity without a cap.
double PathBudget(const LoopState& state, int reserve_steps);

// Who decides where agents go and when a run ends.
class AgentPolicy {
 public:
  virtual ~AgentPolicy() = default;
  // The waypoints each agent follows this step (after its position; empty: it stays), or false to end the
  // run now, before the agents move.
  virtual bool Plan(const LoopState& state, std::vector<std::vector<core::Vec2>>* paths) = 0;
  // After agent 'agent' stepped (before the next agent does): the policy may correct the motion, e.g. nudge
  // a stuck agent through 'motion' with randomness from 'rng'; returns the step as it ended.
  virtual sim::StepResult AfterStep(const LoopState& state, int agent, const sim::StepResult& step,
                                    sim::MotionSim& motion, core::Rng& rng) {
    return step;
  }
};

// A stuck agent's way out (the paper's failures were agents stuck in place feeding identical images): a step
// of 'distance' in a direction drawn from 'rng'; the step as it ended.
sim::StepResult NudgeRandomly(sim::MotionSim& motion, int agent, double distance, core::Rng& rng);

struct LoopOptions {
  int num_agents = 1;
  int max_steps = 400;
  // MCMC on steps 0, every, 2*every, ... with 'mcmc_samples' proposals a call (negative: mapping.mcmc_samples);
  // 0: never, and then the map keeps every vertex with enough detections (mapping.defer_to_mcmc off).
  int mcmc_every = 5;
  int mcmc_samples = -1;
  // Goal-directed runs: the goal, which the sensor passes to goal-conditioned detectors; none for a search.
  std::optional<core::Vec2> goal;
  bool goal_at_agent = false;  // searches whose network estimates what lies past frontiers (SensorSetup)
  // After every step with the map the policy used and the agents' paths so far, and once more with the final
  // map the metrics score (videos).
  std::function<void(const mapping::MapView&, const std::vector<std::vector<core::Vec2>>&)> on_step;
};

struct LoopResult {
  int steps = 0;                                // steps the policy planned (the last one may have ended the run)
  bool ended_by_policy = false;                 // false: the step cap
  std::vector<std::vector<core::Vec2>> paths;   // per agent, from the start
  std::vector<double> distance;                 // travelled per agent
  mapping::MapView final_view;                  // after the final MCMC call, known space exact
  std::unique_ptr<mapping::Mapper> mapper;      // the map, for further questions (its posterior)
  // Where the time went (seconds): observations and map updates, MCMC, views (known space, frontiers),
  // planning and motion; and how many MCMC calls were made during the steps.
  double observe_s = 0.0, mcmc_s = 0.0, view_s = 0.0, plan_s = 0.0;
  int mcmc_calls = 0;
};

// Runs 'policy' in 'world'.  The sensor draws from DeriveSeed(seed, 1), MCMC and the policy from
// DeriveSeed(seed, 2).
LoopResult RunAgentLoop(const core::World& world, const Config& config, const LoopOptions& options,
                        AgentPolicy& policy, uint64_t seed);

}  // namespace toponav::experiments

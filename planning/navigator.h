#pragma once
// A navigator decides, for an agent team's task, where each agent goes every step: SearchNavigator explores the
// world (paper Sec. IV), GoalNavigator takes one agent to a goal (Sec. V).  It sees the world only through what the
// harness (experiments/agent_loop.h) hands it each step -- the map built from the sensors, the agents' poses and
// trails, this step's observations (detections, a subgoal network's estimates, a declared range ring's scans) and
// each step's motion outcome -- and returns each agent's way, or that the task ended and why.  A planner that is
// given the true world (GoalPlanner oracle and known) gets it as a declared input at construction.
#include <optional>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "core/observation.h"
#include "core/rng.h"
#include "mapping/mapping.h"

namespace toponav::planning {

// What an agent's motion reported for one step (odometry and contact).
struct MotionOutcome {
  core::Pose2 pose;       // where the step left the agent
  double distance = 0.0;  // how far it went (world units)
  bool blocked = false;   // it went less than half of what was asked: something it could not pass stopped it
};

// What a navigator sees at a step.  The pointers are valid during the call.
struct NavigatorInput {
  int step = 0;
  int max_steps = 0;                                             // the run's step cap (0: none)
  double step_length = 0.0;                                      // how far an agent steps (world units)
  const mapping::MapView* view = nullptr;                        // the map after this step's observations
  std::vector<core::Pose2> poses;                                // the agents', before they move
  const std::vector<core::Observation>* observations = nullptr;  // this step's, one per agent
  const std::vector<std::vector<core::Vec2>>* trails = nullptr;  // each agent's positions so far
};

// What a navigator makes of an agent's step: a displacement the harness nudges the agent by, and contact
// evidence the harness gives the map (mapping::Mapper::AddContact).
struct StepResponse {
  std::optional<core::Vec2> nudge;
  std::optional<core::Contact> contact;
};

// How far (world units of path) an agent can still walk before the step cap while keeping 'reserve_steps'
// steps in hand: (max_steps - step - reserve_steps) * step_length, at least 0; infinity without a cap.
double PathBudget(const NavigatorInput& input, int reserve_steps);

// A step of 'distance' in a direction drawn from 'rng': the way out for an agent stuck in place (the paper's
// failures were agents stuck feeding identical images).
core::Vec2 RandomNudge(double distance, core::Rng& rng);

class Navigator {
 public:
  virtual ~Navigator() = default;
  // The waypoints each agent follows this step (after its position; empty: it stays), or false: the task ended
  // now, before the agents move (end_reason() says why).
  virtual bool Plan(const NavigatorInput& input, std::vector<std::vector<core::Vec2>>* ways) = 0;
  // After agent 'agent' stepped (before the next agent does): a nudge (drawn from 'rng') and contact evidence,
  // or neither.
  virtual StepResponse AfterStep(const NavigatorInput& input, int agent, const MotionOutcome& step, core::Rng& rng) {
    return {};
  }
  // Why the task ended ("step_cap" while it has not: the harness's cap ends it then).
  virtual std::string end_reason() const { return "step_cap"; }
};

}  // namespace toponav::planning

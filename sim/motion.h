#pragma once
// Agent motion (Box2D): disc-shaped agents that follow waypoint paths one fixed-length step at a time and
// collide with walls, clutter and the region bounds, never passing through them.  Agents do not collide
// with each other (a team starts at one spot).
#include <memory>
#include <vector>

#include "core/option_fields.h"
#include "core/world.h"

namespace toponav::sim {

struct MotionOptions {
  // World units travelled per agent step along the path (when unobstructed).  The experiments layer derives
  // the open-world value (experiments::MotionFor); a caller of MotionSim passes the step it wants.
  double step_length = 1.8;
  double agent_radius = 1.0;   // world units
  int substeps = 12;           // physics sub-steps per agent step
  // Local obstacle avoidance (the robot's own range sensing, which sees clutter the map leaves out): when the
  // straight step would pass closer than agent_radius + avoid_margin to a wall or clutter, the agent plans
  // on a local grid (avoid_window around it, avoid_cell cells) to the point of its path that best trades
  // detour for progress, and steps along that.  avoid_margin 0 turns it off.
  double avoid_margin = 0.3;
  double avoid_window = 12.0;  // half-width of the local grid, world units
  double avoid_cell = 0.5;     // world units
  static const core::OptionFields<MotionOptions>& Fields();  // YAML keys and their ranges
  void Validate() const;       // throws core::ConfigError
};

struct StepResult {
  core::Pose2 pose;             // after the step; yaw faces the direction of travel
  double distance = 0.0;        // actually travelled
  bool blocked = false;         // travelled less than half of what was asked
  bool reached_end = false;     // the last waypoint is reached
  bool avoided = false;         // turned aside from the path to keep clear of an obstacle
};

class MotionSim {
 public:
  MotionSim(const core::World& world, const MotionOptions& options);
  ~MotionSim();
  MotionSim(const MotionSim&) = delete;
  MotionSim& operator=(const MotionSim&) = delete;

  // Adds an agent at 'pose' and returns its id (0, 1, ...).  Throws core::DataError if the disc does not
  // fit there (overlaps a wall or clutter).
  int AddAgent(const core::Pose2& pose);
  int num_agents() const;
  core::Pose2 Pose(int agent) const;

  // Moves 'agent' up to step_length along the polyline 'waypoints' (starting from its position toward
  // waypoints[0], then on), turning aside from what is in the way (avoid_margin) and sliding along whatever
  // it still touches.  An empty path leaves it in place.
  StepResult Step(int agent, const std::vector<core::Vec2>& waypoints);

  // Moves 'agent' by 'offset' (as far as collisions allow): used to perturb a stuck agent.
  StepResult Nudge(int agent, const core::Vec2& offset);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::sim

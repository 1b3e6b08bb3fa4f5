#pragma once
// The navigators' rules on the agents' progress, each a small unit: commitment to a chosen frontier
// (hysteresis), counting the steps agents dwell next to a frontier that does not go away (push-through, then
// give-up), and detecting agents that make no headway (nudges).  planning::SearchNavigator and
// planning::GoalNavigator compose them with a planner.
#include <map>
#include <optional>
#include <vector>

#include "core/geometry.h"
#include "planning/navigation.h"

namespace toponav::planning {

// An agent keeps heading for its previous frontier while that is still a target, reachable, not chosen by a
// team mate, and costs at most switch_ratio * (the new choice's cost) + switch_margin: switching back and
// forth between two frontiers wastes a whole search.
class FrontierCommitment {
 public:
  FrontierCommitment(int num_agents, double switch_ratio, double switch_margin);
  // Overrides 'choices' (one per agent, in agent order) where an agent's commitment holds, then commits each
  // agent to its (possibly overridden) choice; an agent without a found path commits to nothing.
  void Apply(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
             const std::vector<core::Vec2>& agents, std::vector<FrontierChoice>* choices);
  int committed(int agent) const { return committed_[size_t(agent)]; }  // -1: none

 private:
  std::vector<int> committed_;
  double ratio_, margin_;
};

// Steps agents have spent next to each frontier (or stuck on the way to it) without it going away, counted
// per frontier so that the count holds however a team shuffles.  Past half of give_up_steps a frontier's
// target is pushed through into the unknown space behind it (an agent walks in and looks from there); past
// give_up_steps the frontier is given up.
class FrontierDwell {
 public:
  FrontierDwell(int give_up_steps, double give_up_distance);
  // An agent counts as standing when its last step moved it less than half a step (or it has not moved).
  static bool Standing(const std::vector<core::Vec2>& trail, double step_length);
  // Counts one step for every target that a standing agent is within give_up_distance of (of the target's
  // point or of its point before the push 'original[i]'); returns the indices of the targets now due to be
  // given up, ascending.
  std::vector<size_t> CountStanding(const std::vector<FrontierTarget>& targets,
                                    const std::vector<FrontierTarget>& original,
                                    const std::vector<core::Vec2>& agents, const std::vector<char>& standing);
  // Counts one step for frontier 'id' (an agent heading for it is stuck); true when it is due to be given up.
  bool Count(int id);
  void Reset(int id) { steps_[id] = 0; }
  int steps(int id) const;
  // Moves the target of every frontier dwelt at past half of give_up_steps to 'distance' beyond the frontier
  // (its depth plus 'distance' along its outward normal), unless that leaves 'region' (when given).
  void PushThrough(std::vector<FrontierTarget>* targets, double distance,
                   const std::optional<core::Aabb2>& region) const;

 private:
  int give_up_steps_;
  double give_up_distance_;
  std::map<int, int> steps_;
};

// Agents that make no headway: a path but (almost) no motion, no path while there is somewhere to go, or
// pacing (no farther than one step from where it was 2 * stuck_steps steps ago).  After stuck_steps such
// steps (not necessarily in a row: a step with headway restarts the count) the agent is due for a nudge.
class StuckMonitor {
 public:
  StuckMonitor(int num_agents, int stuck_steps, double step_length);
  // 'trail': the agent's positions before this step; 'now' and 'moved': where the step left it and how far
  // it went; 'no_way': it had no path although there were targets.
  bool NoHeadway(const std::vector<core::Vec2>& trail, bool has_path, bool no_way, const core::Vec2& now,
                 double moved) const;
  // Records agent's step; true when it is due for a nudge (its count restarts).
  bool Record(int agent, bool no_headway);
  // The pacing window of NoHeadway, in steps: 2 * stuck_steps.
  int pacing_steps() const { return 2 * stuck_steps_; }

 private:
  std::vector<int> still_;
  int stuck_steps_;
  double step_length_;
};

// True if the agent's last two steps, each at least half of 'step_length' long, took it forth and back: 'now'
// lies within half a step of where the first began ('trail': positions before this step).  An agent heading
// for a graph node inside a wall the map lacks paces so, and its forward steps make headway along the path,
// so StuckMonitor::NoHeadway and MotionBlocks do not count them.
bool PacedForthAndBack(const std::vector<core::Vec2>& trail, const core::Vec2& now, double step_length);

// True if the last 'steps' entries of 'trail' and 'now' (which may repeat trail.back()) all lie within 'span' of
// each other, a distance equal to 'span' included (false while the trail is shorter).  An agent whose plan
// flips between two ways each time the map is sampled again walks a loop a step or two across, forth, back and
// pressing, with steps that make headway in between, so neither StuckMonitor::NoHeadway nor PacedForthAndBack
// counts enough of them in a row.
bool HeldInPlace(const std::vector<core::Vec2>& trail, const core::Vec2& now, int steps, double span);

// True if the step from trail.back() to 'now' repeats the steps 'period', 2 * period, ... 'laps' * period steps
// before it, for some period up to 'max_period': each began within 'tolerance' of trail.back() and ended within
// 'tolerance' of 'now' (a step no longer than 'tolerance' repeats nothing).  Motion is deterministic, so an
// agent whose map and plan stay the same from one lap to the next walks a loop of steps over and over; the loop
// may be wider than HeldInPlace's span and make headway at every step.  Walking back once the way it came
// reverses its steps and does not repeat them.
bool RepeatedStep(const std::vector<core::Vec2>& trail, const core::Vec2& now, int max_period, int laps,
                  double tolerance);


}  // namespace toponav::planning

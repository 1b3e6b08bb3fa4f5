#pragma once
// Where an agent's steps make no headway along its planned path, the map lacks something the agent runs into
// (a building side whose corners the posterior rejects, so the path cuts through the building; a maze wall
// seen only edge-on, inside known space): local
// avoidance slides it along the real wall half a unit a step, or not at all, for as long as the plan says
// "straight on".  MotionBlocks notes such places from the agent's own motion (no sensing) and gives the
// planners a short wall across the way the agent was heading there, so the next plan goes round.
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"

namespace toponav::planning {

class MotionBlocks {
 public:
  // 'steps': steps in a row without headway before a block; 'step_length': the agent's step (world units);
  // a block is 2 * half_width long and stands 'ahead' in front of where the agent stood.
  MotionBlocks(int num_agents, int steps, double step_length, double half_width, double ahead);
  // Records agent's step from 'before' to 'after' while it followed 'path' (path[0] = before).  Headway: the
  // step's progress toward path[1] is at least half of min(step, distance to path[1]).  Returns true when this
  // step added a block.
  bool Record(int agent, const std::vector<core::Vec2>& path, const core::Vec2& before, const core::Vec2& after);
  // Adds a block across the way from 'at' toward 'toward', placed as Record places one; nothing (false) when
  // the two points coincide.
  bool Block(const core::Vec2& at, const core::Vec2& toward);
  const std::vector<core::Segment2>& blocks() const { return blocks_; }
  // Every block ever added, those Clear() took back too (pictures, trial records).
  const std::vector<core::Segment2>& added() const { return added_; }
  // Every block taken back, and the counts of steps without headway restarted (a goal-directed agent whose map
  // is sealed retries); added() keeps them.
  void Clear();
  // 'view' with every block as a free-standing wall (AddFreeStandingWall), so plans go round its ends.
  mapping::MapView With(const mapping::MapView& view) const;

 private:
  void Add(const core::Vec2& at, const core::Vec2& dir);  // 'dir': unit heading

  std::vector<int> count_;
  std::vector<core::Segment2> blocks_, added_;
  int steps_;
  double step_length_, half_width_, ahead_;
};

}  // namespace toponav::planning

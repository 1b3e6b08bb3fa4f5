#pragma once
// The goal navigator's recovery where its planner finds no way to the goal (a goal-directed trial's goal is
// reachable, so some wall of the map is false): in turn, the cheapest way through a doorway hypothesis
// (planning/internal/doorways.h); else, if some frontiers were blocked or motion blocks added, all of them taken back;
// else a frontier or a suspected false wall to look at from close by (planning::SuspectInspector).  Where the
// agent already stands where the inspector leads it, the map walls within NavigationOptions::inspect_reach become
// openings (planning::OpeningsNear) that this and later doorway searches try too, each until the agent makes
// no headway through it.
#include <optional>
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"
#include "planning/internal/doorways.h"
#include "planning/internal/given_up_frontiers.h"
#include "planning/internal/map_suspects.h"
#include "planning/internal/motion_blocks.h"
#include "planning/navigation.h"
#include "planning/navigator_options.h"

namespace toponav::planning::internal {

class DoorwayRecovery {
 public:
  DoorwayRecovery(const NavigationOptions& options, const PlannerOptions& planning, const core::Vec2& goal);
  // 'map': the map's view; 'view': it with the walls the navigator adds after the map's own, the last
  // 'scan_walls' of them a range ring's (true walls: no doorway in them); 'graph' built on 'view'.  May clear
  // 'blocked' and 'blocks' (null: none kept).
  FrontierChoice Recover(const mapping::MapView& map, const mapping::MapView& view, size_t scan_walls,
                         const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                         const core::Vec2& at, double step_length, GivenUpFrontiers& blocked, MotionBlocks* blocks);
  // Called before each step's plan: the agent heads through no doorway yet.
  void Reset() { doorway_.reset(); }
  // The agent made no headway through the doorway it headed for: none near it is tried again.
  void Failed() {
    if (doorway_) failed_.push_back(*doorway_);
  }

 private:
  FrontierChoice ThroughDoorway(const mapping::MapView& view, size_t map_walls, size_t scan_walls,
                                const core::Vec2& at);
  bool AddOpenings(const mapping::MapView& map, const core::Vec2& at);

  NavigationOptions options_;
  PlannerOptions planning_;
  core::Vec2 goal_;
  SuspectInspector inspector_;
  std::optional<core::Vec2> doorway_;   // the middle of the doorway the agent heads through now
  std::vector<core::Vec2> failed_;      // middles of those it made no headway through
  std::vector<Doorway> openings_;       // walls beside a place recovery led to, opened (OpeningsNear)
};

}  // namespace toponav::planning::internal

#pragma once
// The search navigator (paper Sec. IV): every step the frontier targets the search
// has not given up (in open worlds only those inside the search region), pushed through where agents dwelt,
// go to the planner (for one agent the nearest frontier, or with search.tour the first of its shortest tour
// through all of them; distinct frontiers for a team); agents keep their frontier while it stays competitive
// (commitment); frontiers agents stand next to without them going away, or cannot get to, are given up;
// stuck agents are nudged.  The search ends when no frontier is left ("explored") or none has been reachable
// for SearchOptions::unreachable_steps steps ("unreachable").  With search.block_when_stuck, where an agent's
// steps make no headway along its path the planners get a short wall across its way (MotionBlocks); with
// search.close_buildings, in open worlds a building's last side (ClosesWallChain) is no target; with
// search.dropped_wall_steps, neither is a frontier along a wall the map held and has left out since
// (DroppedWalls); with search.inspect_bend and search.inspect_unwalled, once no frontier is left
// agents look from close by at the map vertices that walls run straight through and (open worlds) those the
// map lacks walls for (VertexInspector) before the search ends, those they can reach and look from
// within the steps left.  With search.sealed_reach, in closed worlds a search whose known space stops short of a
// side of the world's bounds goes on: agents look at the map walls that may seal the rest off
// (UnreachedSide, SuspectInspector) until none is left to look at.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/world.h"
#include "planning/internal/dropped_walls.h"
#include "planning/internal/given_up_frontiers.h"
#include "planning/internal/map_suspects.h"
#include "planning/internal/motion_blocks.h"
#include "planning/navigator.h"
#include "planning/navigator_options.h"
#include "planning/planner.h"
#include "planning/internal/progress.h"
#include "planning/internal/vertex_inspector.h"

namespace toponav::planning {

struct SearchNavigatorSetup {
  int num_agents = 1;
  core::Aabb2 bounds;        // the world's bounds, known to the agents
  bool closed = true;        // a closed world (walled round); an open world is searched inside its bounds
  double step_length = 1.8;  // the agents' step (world units)
  SearchOptions search;
  PlannerOptions planning;
};

class SearchNavigator : public Navigator {
 public:
  explicit SearchNavigator(const SearchNavigatorSetup& setup);

  bool Plan(const NavigatorInput& input, std::vector<std::vector<core::Vec2>>* ways) override;
  StepResponse AfterStep(const NavigatorInput& input, int agent, const MotionOutcome& step, core::Rng& rng) override;
  std::string end_reason() const override { return end_reason_; }  // "explored", "unreachable", "step_cap"

  // Called every step before agents move with the loop's state, the frontier targets on offer and each agent's
  // choice (traces, training data).
  std::function<void(const NavigatorInput&, const std::vector<FrontierTarget>&, const std::vector<FrontierChoice>&)>
      on_plan;

  bool explored() const { return explored_; }
  int nudges() const { return nudges_; }
  int give_ups() const { return given_up_.given_up(); }
  int inspections() const { return inspector_ ? inspector_->targeted() : 0; }
  // Agent-steps spent heading for a wall that may seal the world off (search.sealed_reach).
  int sealed_steps() const { return sealed_choices_; }
  // Where agents made no headway (search.block_when_stuck): the walls given to the planners.
  std::vector<core::Segment2> blocks() const { return blocks_ ? blocks_->blocks() : std::vector<core::Segment2>{}; }

 private:
  static constexpr int kSealedSuspect = -2;  // the frontier id of a choice headed for a suspect wall
  std::vector<FrontierTarget> Targets(const mapping::MapView& view);
  bool Ended(const std::vector<FrontierTarget>& targets, const mapping::MapView& view);
  void CountDwelling(const NavigatorInput& input, const std::vector<core::Vec2>& agents);
  // search.sealed_reach: each agent's way to a suspect wall while known space misses a side of the bounds;
  // false (choices_ untouched) when it reaches them all or no suspect is left.
  bool ChooseSealedSuspects(const mapping::MapView& view, const VisibilityGraph& graph,
                            const std::vector<core::Vec2>& agents);

  SearchOptions search_;
  PlannerOptions planning_;
  std::optional<core::Aabb2> region_;  // open worlds: the search region (the world's bounds)
  std::unique_ptr<Planner> planner_;
  GivenUpFrontiers given_up_;
  DroppedWalls dropped_walls_;  // search.dropped_wall_steps
  FrontierDwell dwell_;
  FrontierCommitment commitment_;
  StuckMonitor stuck_;
  std::optional<MotionBlocks> blocks_;  // search.block_when_stuck only
  std::optional<VertexInspector> inspector_;  // search.inspect_bend or inspect_unwalled only
  std::optional<SuspectInspector> sealed_;     // search.sealed_reach, closed worlds only
  int sealed_choices_ = 0;                               // agent-steps headed for a suspect wall
  core::Aabb2 bounds_;  // the world's
  // This step's targets (pushed through where agents dwelt, and as they were before) and choices.
  std::vector<FrontierTarget> targets_, original_;
  std::vector<FrontierChoice> choices_;
  int unreachable_ = 0;
  bool explored_ = false;
  std::string end_reason_ = "step_cap";
  int nudges_ = 0;
};

}  // namespace toponav::planning

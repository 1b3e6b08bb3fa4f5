#pragma once
// The frontier-search policy (paper Sec. IV) on the agent loop: every step the frontier targets the search
// has not given up (in open worlds only those inside the search region), pushed through where agents dwelt,
// go to the planner (for one agent the nearest frontier, or with search.tour the first of its shortest tour
// through all of them; distinct frontiers for a team); agents keep their frontier while it stays competitive
// (commitment); frontiers agents stand next to without them going away, or cannot get to, are given up;
// stuck agents are nudged.  The search ends when no frontier is left ("explored") or none has been reachable
// for search.unreachable_steps steps ("unreachable").  With search.block_when_stuck, where an agent's steps make
// no headway along its path the planners get a short wall across its way (planning::MotionBlocks); with
// search.close_buildings, in open worlds a building's last side (planning::ClosesWallChain) is no target; with
// search.dropped_wall_steps, neither is a frontier along a wall the map held and has left out since
// (planning::DroppedWalls); with search.inspect_bend and search.inspect_unwalled, once no frontier is left
// agents look from close by at the map vertices that walls run straight through and (open worlds) those the
// map lacks walls for (planning::VertexInspector) before the search ends, those they can reach and look from
// within the steps left.  With search.sealed_reach, in closed worlds a search whose known space stops short of a
// side of the world's bounds goes on: agents look at the map walls that may seal the rest off
// (planning::UnreachedSide, planning::SuspectInspector) until none is left to look at.
// With search.exploration_estimate, one agent's tour knows what lies past each frontier
// (planning/frontier_exploration.h).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "experiments/agent_loop.h"
#include "planning/cell_estimator.h"
#include "planning/dropped_walls.h"
#include "planning/given_up_frontiers.h"
#include "planning/lsp_planner.h"
#include "planning/map_suspects.h"
#include "planning/motion_blocks.h"
#include "planning/planner.h"
#include "planning/search_policy.h"
#include "planning/vertex_inspector.h"

namespace toponav::experiments {

class SearchPolicy : public AgentPolicy {
 public:
  SearchPolicy(const core::World& world, const Config& config, int num_agents);

  bool Plan(const LoopState& state, std::vector<std::vector<core::Vec2>>* paths) override;
  sim::StepResult AfterStep(const LoopState& state, int agent, const sim::StepResult& step, sim::MotionSim& motion,
                            core::Rng& rng) override;

  // Called every step before agents move with the loop's state, the frontier targets on offer and each agent's
  // choice (traces, training data).
  std::function<void(const LoopState&, const std::vector<planning::FrontierTarget>&,
                     const std::vector<planning::FrontierChoice>&)>
      on_plan;
  // Whether the sensor must tell a goal-conditioned network the goal is at the agent (the learned estimate).
  bool wants_goal_at_agent() const { return cells_ != nullptr; }

  bool explored() const { return explored_; }
  const std::string& end_reason() const { return end_reason_; }  // "explored", "unreachable", "step_cap"
  int nudges() const { return nudges_; }
  int give_ups() const { return given_up_.given_up(); }
  int inspections() const { return inspector_ ? inspector_->targeted() : 0; }
  // Agent-steps spent heading for a wall that may seal the world off (search.sealed_reach).
  int sealed_steps() const { return sealed_choices_; }
  // Where agents made no headway (search.block_when_stuck): the walls given to the planners.
  std::vector<core::Segment2> blocks() const { return blocks_ ? blocks_->blocks() : std::vector<core::Segment2>{}; }

 private:
  static constexpr int kSealedSuspect = -2;  // the frontier id of a choice headed for a suspect wall
  std::vector<planning::FrontierTarget> Targets(const mapping::MapView& view);
  bool Ended(const std::vector<planning::FrontierTarget>& targets, const mapping::MapView& view);
  void CountDwelling(const LoopState& state, const std::vector<core::Vec2>& agents);
  void ObserveCells(const LoopState& state);  // "learned": this step's network outputs to the estimator
  // search.sealed_reach: each agent's way to a suspect wall while known space misses a side of the bounds;
  // false (choices_ untouched) when it reaches them all or no suspect is left.
  bool ChooseSealedSuspects(const mapping::MapView& view, const planning::VisibilityGraph& graph,
                            const std::vector<core::Vec2>& agents);

  SearchOptions search_;
  planning::PlannerOptions planning_;
  std::optional<core::Aabb2> region_;  // open worlds: the search region (the world's bounds)
  std::unique_ptr<planning::Planner> planner_;
  planning::GivenUpFrontiers given_up_;
  planning::DroppedWalls dropped_walls_;  // search.dropped_wall_steps
  planning::FrontierDwell dwell_;
  planning::FrontierCommitment commitment_;
  planning::StuckMonitor stuck_;
  std::optional<planning::MotionBlocks> blocks_;  // search.block_when_stuck only
  std::optional<planning::VertexInspector> inspector_;  // search.inspect_bend or inspect_unwalled only
  std::optional<planning::SuspectInspector> sealed_;     // search.sealed_reach, closed worlds only
  int sealed_choices_ = 0;                               // agent-steps headed for a suspect wall
  std::unique_ptr<planning::SubgoalEstimator> exploration_;  // search.exploration_estimate, one agent only
  planning::CellAveragingEstimator* cells_ = nullptr;        // "learned": exploration_, fed the observations
  std::string model_;                                         // its sensor's model file (errors)
  double cell_ = 1.0;                                         // its raster's cell (lsp.cell)
  core::Aabb2 bounds_;                                        // the world's
  // This step's targets (pushed through where agents dwelt, and as they were before) and choices.
  std::vector<planning::FrontierTarget> targets_, original_;
  std::vector<planning::FrontierChoice> choices_;
  int unreachable_ = 0;
  bool explored_ = false;
  std::string end_reason_ = "step_cap";
  int nudges_ = 0;
};

}  // namespace toponav::experiments

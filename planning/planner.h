#pragma once
// The planner interface: what each agent of a team does next, given the map view, the frontier targets on
// offer, where the agents are and, for goal-directed navigation, the goal.  Frontier search plans with the
// nearest-frontier planner (one agent) or the team assignment (agents to distinct frontiers); goal-directed
// planners (optimistic, learned subgoals) implement the same interface.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"
#include "planning/navigation.h"

namespace toponav::planning {

// Everything a planner may read for one decision.  The pointers stay valid for the call only.
struct PlanningProblem {
  const mapping::MapView* view = nullptr;
  const VisibilityGraph* graph = nullptr;           // built on 'view' (optimistic: unknown space is free)
  const std::vector<FrontierTarget>* targets = nullptr;
  std::vector<core::Vec2> agents;                   // positions, one per agent
  std::optional<core::Vec2> goal;                   // goal-directed navigation only
};

class Planner {
 public:
  virtual ~Planner() = default;
  // One choice per agent (PlanStatus::kNothingToExplore when there are no targets).
  virtual std::vector<FrontierChoice> Plan(const PlanningProblem& problem) = 0;
  virtual std::string name() const = 0;
};

enum class PlannerKind { kNearestFrontier, kTourFrontier, kTeamFrontiers, kOptimistic };
// "nearest_frontier", "frontier_tour", "team_frontiers", "optimistic"
const char* ToString(PlannerKind kind);

// kNearestFrontier: each agent its own cheapest reachable frontier (ChooseNearestFrontier); kTourFrontier: each
// agent the first frontier of its shortest tour through all of them (ChooseTourFrontier); kTeamFrontiers:
// agents to distinct frontiers at the least total cost (AssignFrontiers); kOptimistic (goal-directed
// navigation's baseline, lsp.md §4.2): each agent the shortest path to the goal on the problem's graph, on
// which unknown space counts as free (frontier_id -1; kNoPath when the map's walls cut the goal off).
std::unique_ptr<Planner> CreatePlanner(PlannerKind kind);
// The frontier planner a search with 'num_agents' agents uses: for one, the nearest frontier or ('tour') the
// first of the shortest tour; the team assignment for more.
std::unique_ptr<Planner> CreateSearchPlanner(int num_agents, bool tour = false);

}  // namespace toponav::planning

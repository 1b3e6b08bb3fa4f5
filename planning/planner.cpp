#include "planning/planner.h"

#include "core/error.h"
#include "planning/frontier_tour.h"

namespace toponav::planning {

const char* ToString(PlannerKind kind) {
  switch (kind) {
    case PlannerKind::kNearestFrontier: return "nearest_frontier";
    case PlannerKind::kTourFrontier: return "frontier_tour";
    case PlannerKind::kTeamFrontiers: return "team_frontiers";
    case PlannerKind::kOptimistic: return "optimistic";
  }
  return "?";
}

namespace {

void CheckProblem(const PlanningProblem& p) {
  TOPONAV_CHECK(p.view && p.graph && p.targets, "planning problem without a view, graph or targets");
}

// Each agent on its own: 'choose' picks its frontier (nearest, or first of its tour).
class PerAgentPlanner : public Planner {
 public:
  using Choose = FrontierChoice (*)(const VisibilityGraph&, const std::vector<FrontierTarget>&, const core::Vec2&);
  PerAgentPlanner(PlannerKind kind, Choose choose) : kind_(kind), choose_(choose) {}
  std::vector<FrontierChoice> Plan(const PlanningProblem& p) override {
    CheckProblem(p);
    std::vector<FrontierChoice> out;
    for (const auto& agent : p.agents) out.push_back(choose_(*p.graph, *p.targets, agent));
    return out;
  }
  std::string name() const override { return ToString(kind_); }

 private:
  PlannerKind kind_;
  Choose choose_;
};

class TeamFrontierPlanner : public Planner {
 public:
  std::vector<FrontierChoice> Plan(const PlanningProblem& p) override {
    CheckProblem(p);
    return AssignFrontiers(*p.graph, *p.targets, p.agents);
  }
  std::string name() const override { return ToString(PlannerKind::kTeamFrontiers); }
};

class OptimisticPlanner : public Planner {
 public:
  std::vector<FrontierChoice> Plan(const PlanningProblem& p) override {
    CheckProblem(p);
    TOPONAV_CHECK(p.goal, "the optimistic planner needs a goal");
    std::vector<FrontierChoice> out;
    for (const auto& agent : p.agents) {
      FrontierChoice c;
      c.path = p.graph->Plan(agent, *p.goal);
      c.status = c.path.status;
      out.push_back(std::move(c));
    }
    return out;
  }
  std::string name() const override { return ToString(PlannerKind::kOptimistic); }
};

}  // namespace

std::unique_ptr<Planner> CreatePlanner(PlannerKind kind) {
  switch (kind) {
    case PlannerKind::kNearestFrontier: return std::make_unique<PerAgentPlanner>(kind, &ChooseNearestFrontier);
    case PlannerKind::kTourFrontier: return std::make_unique<PerAgentPlanner>(kind, &ChooseTourFrontier);
    case PlannerKind::kTeamFrontiers: return std::make_unique<TeamFrontierPlanner>();
    case PlannerKind::kOptimistic: return std::make_unique<OptimisticPlanner>();
  }
  return nullptr;
}

std::unique_ptr<Planner> CreateSearchPlanner(int num_agents, bool tour) {
  if (num_agents > 1) return CreatePlanner(PlannerKind::kTeamFrontiers);
  return CreatePlanner(tour ? PlannerKind::kTourFrontier : PlannerKind::kNearestFrontier);
}

}  // namespace toponav::planning

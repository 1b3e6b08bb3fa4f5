#include "planning/planner.h"

#include "core/error.h"

namespace toponav::planning {

const char* ToString(PlannerKind kind) {
  return kind == PlannerKind::kNearestFrontier ? "nearest_frontier" : "team_frontiers";
}

namespace {

void CheckProblem(const PlanningProblem& p) {
  TOPONAV_CHECK(p.view && p.graph && p.targets, "planning problem without a view, graph or targets");
}

class NearestFrontierPlanner : public Planner {
 public:
  std::vector<FrontierChoice> Plan(const PlanningProblem& p) override {
    CheckProblem(p);
    std::vector<FrontierChoice> out;
    for (const auto& agent : p.agents) out.push_back(ChooseNearestFrontier(*p.graph, *p.targets, agent));
    return out;
  }
  std::string name() const override { return ToString(PlannerKind::kNearestFrontier); }
};

class TeamFrontierPlanner : public Planner {
 public:
  std::vector<FrontierChoice> Plan(const PlanningProblem& p) override {
    CheckProblem(p);
    return AssignFrontiers(*p.graph, *p.targets, p.agents);
  }
  std::string name() const override { return ToString(PlannerKind::kTeamFrontiers); }
};

}  // namespace

std::unique_ptr<Planner> CreatePlanner(PlannerKind kind) {
  if (kind == PlannerKind::kNearestFrontier) return std::make_unique<NearestFrontierPlanner>();
  return std::make_unique<TeamFrontierPlanner>();
}

std::unique_ptr<Planner> CreateSearchPlanner(int num_agents) {
  return CreatePlanner(num_agents > 1 ? PlannerKind::kTeamFrontiers : PlannerKind::kNearestFrontier);
}

}  // namespace toponav::planning

#include "planning/frontier_exploration.h"

#include "core/error.h"
#include "planning/subgoal_grid.h"

namespace toponav::planning {

OrderingProblem ProblemWithoutDistances(size_t frontiers) {
  OrderingProblem none;
  none.properties.resize(frontiers);
  none.robot_cost.assign(frontiers, 0.0);
  none.goal_cost.assign(frontiers, 0.0);
  none.between.assign(frontiers, std::vector<double>(frontiers, 0.0));
  return none;
}

void EstimateExploration(const mapping::MapView& view, const core::Vec2& agent, double cell, const core::Aabb2& region,
                         SubgoalEstimator& estimator, std::vector<FrontierTarget>* targets) {
  for (auto& t : *targets) t.exploration = 0.0;
  const std::vector<const mapping::Frontier*> frontiers = TargetFrontiers(view, *targets);
  if (frontiers.empty() || frontiers.size() != targets->size()) return;
  const SubgoalGrid grid(view, frontiers, agent, agent, cell, region);  // the goal at the agent: in known space
  const std::vector<SubgoalProperties> estimates = estimator.Estimate(grid, ProblemWithoutDistances(frontiers.size()));
  TOPONAV_CHECK(estimates.size() == targets->size(),
                estimates.size() << " estimates for " << targets->size() << " targets");
  for (size_t i = 0; i < targets->size(); ++i) (*targets)[i].exploration = Clamped(estimates[i]).exploration;
}

}  // namespace toponav::planning

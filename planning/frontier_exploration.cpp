#include "planning/frontier_exploration.h"

#include "core/error.h"
#include "planning/subgoal_grid.h"

namespace toponav::planning {

void EstimateExploration(const mapping::MapView& view, const core::Vec2& agent, double cell, const core::Aabb2& region,
                         SubgoalEstimator& estimator, std::vector<FrontierTarget>* targets) {
  for (auto& t : *targets) t.exploration = 0.0;
  const std::vector<const mapping::Frontier*> frontiers = TargetFrontiers(view, *targets);
  if (frontiers.empty() || frontiers.size() != targets->size()) return;
  const SubgoalGrid grid(view, frontiers, agent, agent, cell, region);  // the goal at the agent: in known space
  // No frontier leads to the goal, so the distance tables (a Dijkstra per frontier, most of the raster's cost)
  // go unread: the estimators read how many frontiers there are, and costs toward a goal only where one does.
  OrderingProblem none;
  none.properties.resize(frontiers.size());
  none.robot_cost.assign(frontiers.size(), 0.0);
  none.goal_cost.assign(frontiers.size(), 0.0);
  none.between.assign(frontiers.size(), std::vector<double>(frontiers.size(), 0.0));
  const std::vector<SubgoalProperties> estimates = estimator.Estimate(grid, none);
  TOPONAV_CHECK(estimates.size() == targets->size(),
                estimates.size() << " estimates for " << targets->size() << " targets");
  for (size_t i = 0; i < targets->size(); ++i) (*targets)[i].exploration = Clamped(estimates[i]).exploration;
}

}  // namespace toponav::planning

#include "planning/frontier_tour.h"

#include <algorithm>
#include <limits>

#include "planning/subgoal_ordering.h"

namespace toponav::planning {

namespace {

// The reachable targets' indices, cheapest first (ties: lower index), at most kMaxTourFrontiers.
std::vector<size_t> TourMembers(const std::vector<Path>& from_agent) {
  std::vector<size_t> members;
  for (size_t k = 0; k < from_agent.size(); ++k)
    if (from_agent[k]) members.push_back(k);
  std::stable_sort(members.begin(), members.end(),
                   [&](size_t a, size_t b) { return from_agent[a].cost < from_agent[b].cost; });
  if (members.size() > size_t(kMaxTourFrontiers)) members.resize(size_t(kMaxTourFrontiers));
  std::sort(members.begin(), members.end());
  return members;
}

// The ordering problem whose expected cost is the tour's length: every frontier fails (Ps 0) at no cost of
// its own, so only the legs between frontiers count.
OrderingProblem TourProblem(const VisibilityGraph& graph, const std::vector<core::Vec2>& points,
                            const std::vector<double>& from_agent) {
  OrderingProblem p;
  const size_t n = points.size();
  p.properties.assign(n, SubgoalProperties{0.0, 0.0, 0.0});
  p.robot_cost = from_agent;
  p.goal_cost.assign(n, 0.0);
  p.between.assign(n, std::vector<double>(n, 0.0));
  for (size_t i = 0; i + 1 < n; ++i) {
    const std::vector<core::Vec2> rest(points.begin() + long(i) + 1, points.end());
    const std::vector<Path> legs = graph.PlanToMany(points[i], rest);
    for (size_t j = i + 1; j < n; ++j) {
      const Path& leg = legs[j - i - 1];
      const double cost = leg ? leg.cost : std::numeric_limits<double>::infinity();
      p.between[i][j] = cost;
      p.between[j][i] = cost;
    }
  }
  return p;
}

}  // namespace

FrontierChoice ChooseTourFrontier(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                                  const core::Vec2& agent) {
  FrontierChoice choice;
  if (targets.empty()) return choice;
  std::vector<core::Vec2> goals;
  for (const auto& t : targets) goals.push_back(t.point);
  const std::vector<Path> paths = graph.PlanToMany(agent, goals);
  choice.status = PlanStatus::kNoPath;
  const std::vector<size_t> members = TourMembers(paths);
  if (members.empty()) return choice;
  std::vector<core::Vec2> points;
  std::vector<double> from_agent;
  for (size_t k : members) {
    points.push_back(goals[k]);
    from_agent.push_back(paths[k].cost);
  }
  const Ordering tour = BestOrdering(TourProblem(graph, points, from_agent));
  // Legs between reachable targets always exist (through the agent); without an order, go to the nearest.
  size_t first = members[0];
  for (size_t k : members) first = paths[k].cost < paths[first].cost ? k : first;
  if (!tour.order.empty()) first = members[size_t(tour.order.front())];
  choice.status = PlanStatus::kFound;
  choice.frontier_id = targets[first].frontier_id;
  choice.path = paths[first];
  return choice;
}

}  // namespace toponav::planning

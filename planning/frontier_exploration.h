#pragma once
// What lies past each frontier of a search, as Learned Subgoal Planning estimates it (lsp.md §1): a search is
// LSP with the goal where the agent stands, in known space, so no frontier leads to it, every frontier
// "fails", and its estimate is its exploration cost -- the round trip from where the unseen region behind it
// is entered to its deepest point.  The tour (planning/frontier_tour.h) leaves the frontier with the most
// behind it for last.
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"
#include "planning/lsp_planner.h"
#include "planning/navigation.h"

namespace toponav::planning {

// The ordering problem of 'frontiers' frontiers with no distance tables (all zero): enough when the goal is
// at the agent, since no frontier leads to it -- the estimators and the true properties read how many
// frontiers there are, and costs toward a goal only where one does.  It spares a Dijkstra per frontier.
OrderingProblem ProblemWithoutDistances(size_t frontiers);

// Sets each target's 'exploration' from 'estimator' (path units, clamped to >= 0), on a raster of 'view' with
// cells of 'cell' units over 'region'.  Targets whose frontier 'view' lacks (inspection lookouts) leave every
// estimate at 0.
void EstimateExploration(const mapping::MapView& view, const core::Vec2& agent, double cell, const core::Aabb2& region,
                         SubgoalEstimator& estimator, std::vector<FrontierTarget>* targets);

}  // namespace toponav::planning

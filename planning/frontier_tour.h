#pragma once
// One agent's frontier choice by tour: head for the first frontier of the shortest open tour that starts at the
// agent and visits every reachable frontier target once (path costs on the visibility graph).  Nearest-frontier
// search (the paper's) leaves a frontier behind whenever another is a little closer and walks back for it at
// the end; the tour weighs where each choice leaves the agent for the rest.  The order is solved exactly by the
// subgoal-ordering dynamic programme (every frontier "fails", so its expected cost is the tour length).
#include <vector>

#include "core/geometry.h"
#include "planning/navigation.h"

namespace toponav::planning {

// At most this many targets enter the tour: the nearest ones (by path cost) when there are more.
constexpr int kMaxTourFrontiers = 12;

// The choice for an agent at 'agent' (PlanStatus::kNothingToExplore without targets, kNoPath when none is
// reachable).  Ties go to the lower target index, so the choice is deterministic.
FrontierChoice ChooseTourFrontier(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                                  const core::Vec2& agent);

}  // namespace toponav::planning

#pragma once
// Recovering from a sealed map.  When the map leaves an agent no way to its goal, a wall somewhere is false
// (a goal-directed trial's goal is reachable): most often one drawn across an opening that was only seen
// from afar or edge-on, whose jambs the posterior left out (rejected vertices: detected often enough, not in
// the map) or that were never detected at all.  The inspector sends the agent to look from close by at a
// suspect -- a rejected vertex, or a point along a map wall -- that separates the places it can reach from
// those it cannot, the one that would make the shortest way to the goal first; new detections there let the
// posterior open the map up.
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"
#include "planning/navigation.h"

namespace toponav::planning {

class SuspectInspector {
 public:
  // 'reach': a suspect counts as inspected once the agent came this close.  It is looked at from one of
  // eight lookouts 'standoff' away from it that the agent can reach while the point opposite (across the
  // suspect) cannot be reached: a suspect between two reachable places could open no new way.  Walls are
  // sampled every 'spacing' (at least their middle).
  SuspectInspector(double reach, double standoff, double spacing);
  // The suspects of 'view' (its rejected vertices and points along its walls) not yet inspected.
  std::vector<core::Vec2> Suspects(const mapping::MapView& view) const;
  // Where the map cuts 'goal' off: among the frontier 'targets' (their target points) and the suspects'
  // lookouts, the one with the least path cost plus straight-line distance on to the goal (frontier_id -1
  // for a suspect), or status kNothingToExplore when there is neither.  Marks inspected the suspects within
  // reach of 'agent' and those without a lookout.
  FrontierChoice Choose(const mapping::MapView& view, const VisibilityGraph& graph, const core::Vec2& agent,
                        const core::Vec2& goal, const std::vector<FrontierTarget>& targets);
  int inspected() const { return int(inspected_.size()); }

 private:
  bool Inspected(const core::Vec2& p) const;
  void AddSamples(const core::Vec2& a, const core::Vec2& b, std::vector<core::Vec2>* out) const;
  double reach_, standoff_, spacing_;
  std::vector<core::Vec2> inspected_;  // places inspected: suspects within 'reach' of one are done
};

}  // namespace toponav::planning

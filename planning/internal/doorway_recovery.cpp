#include "planning/internal/doorway_recovery.h"

#include <algorithm>

namespace toponav::planning::internal {

using core::Vec2;

DoorwayRecovery::DoorwayRecovery(const NavigationOptions& options, const PlannerOptions& planning, const Vec2& goal)
    : options_(options),
      planning_(planning),
      goal_(goal),
      inspector_(options.inspect_reach, planning.inflation_radius + planning.clearance, options.inspect_reach) {}

FrontierChoice DoorwayRecovery::Recover(const mapping::MapView& map, const mapping::MapView& view, size_t scan_walls,
                                        const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                                        const Vec2& at, double step_length, GivenUpFrontiers& blocked,
                                        MotionBlocks* blocks) {
  FrontierChoice c = ThroughDoorway(view, map.walls.size(), scan_walls, at);
  if (c.status == PlanStatus::kFound) return c;
  if (blocked.given_up() > 0 || (blocks && !blocks->blocks().empty())) {
    blocked.Clear();
    if (blocks) blocks->Clear();
    return c;
  }
  c = inspector_.Choose(map, graph, at, goal_, targets);
  if (c.status != PlanStatus::kFound || c.path.cost >= 0.5 * step_length) return c;
  if (!AddOpenings(map, at)) return c;
  const FrontierChoice through = ThroughDoorway(view, map.walls.size(), scan_walls, at);
  return through.status == PlanStatus::kFound ? through : c;
}

// The map walls within inspect_reach of 'at' as openings, those overlapping one tried or failed before left
// out; true if some are new.
bool DoorwayRecovery::AddOpenings(const mapping::MapView& map, const Vec2& at) {
  const double apart = options_.doorway_min_width;
  bool added = false;
  for (const auto& o : OpeningsNear(map, map.walls.size(), at, options_.inspect_reach, apart)) {
    bool known = false;
    for (const auto& k : openings_) known = known || core::Distance(k.middle(), o.middle()) < apart;
    for (const auto& f : failed_) known = known || core::Distance(f, o.middle()) < apart;
    if (!known) openings_.push_back(o), added = true;
  }
  return added;
}

// The way to the goal through the doorway hypothesis or the opening (on one of the view's first 'map_walls'
// walls; not yet failed) that makes it cheapest.
FrontierChoice DoorwayRecovery::ThroughDoorway(const mapping::MapView& view, size_t map_walls, size_t scan_walls,
                                               const Vec2& at) {
  constexpr double kOnWall = 2.0, kSame = 4.0;
  FrontierChoice best;
  std::vector<Doorway> doorways =
      DoorwayHypotheses(view, kOnWall, options_.doorway_min_width, options_.doorway_max_width);
  // The walls the range ring's scans showed come last in the view: they are true walls, with no doorway in them.
  const size_t scanned_from = view.walls.size() - scan_walls;
  doorways.erase(std::remove_if(doorways.begin(), doorways.end(),
                                [&](const Doorway& d) { return size_t(d.wall) >= scanned_from; }),
                 doorways.end());
  for (const auto& o : openings_)
    if (const auto d = Anchored(view, map_walls, o, kOnWall / 2)) doorways.push_back(*d);
  for (const auto& d : doorways) {
    bool failed = false;
    for (const auto& f : failed_) failed = failed || core::Distance(f, d.middle()) < kSame;
    if (failed) continue;
    const Path p = VisibilityGraph(WithDoorway(view, d), planning_, false).Plan(at, goal_);
    if (!p || (best.status == PlanStatus::kFound && p.cost >= best.path.cost)) continue;
    best = {PlanStatus::kFound, -1, p};
    doorway_ = d.middle();
  }
  return best;
}

}  // namespace toponav::planning::internal

#include "experiments/trial.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "experiments/agent_loop.h"
#include "experiments/map_drive.h"
#include "planning/search_navigator.h"
#include "mapping/polygon_set.h"

namespace toponav::experiments {

using core::Vec2;

double SearchIoU(const core::World& world, const mapping::MapView& map) {
  return world.has_boundary() ? KnownSpaceIoU(world, map) : BuildingPlacementIoU(world, map);
}

double BuildingPlacementIoU(const core::World& world, const mapping::MapView& map) {
  const mapping::PolygonSet found = KnownSet(map).Holes();
  std::vector<mapping::PolygonSet> buildings;
  for (const auto& o : world.obstacles) buildings.push_back(mapping::PolygonSet::FromRing(o));
  return mapping::IoU(found, mapping::PolygonSet::JoinAll(buildings));
}

BuildingPlacementBreakdown BreakDownBuildingPlacement(const core::World& world, const mapping::MapView& map) {
  BuildingPlacementBreakdown out;
  const std::vector<mapping::PolygonSet> holes = KnownSet(map).Holes().Components();
  std::vector<char> overlaps(holes.size(), 0);
  for (const auto& o : world.obstacles) {
    const mapping::PolygonSet building = mapping::PolygonSet::FromRing(o);
    std::vector<const mapping::PolygonSet*> found;
    for (size_t h = 0; h < holes.size(); ++h) {
      mapping::PolygonSet common = holes[h];
      common.Intersect(building);
      if (common.Area() <= 0.0) continue;
      overlaps[h] = 1;
      found.push_back(&holes[h]);
    }
    out.building_iou.push_back(found.empty() ? 0.0 : mapping::IoU(mapping::PolygonSet::JoinAll(found), building));
  }
  for (size_t h = 0; h < holes.size(); ++h)
    if (!overlaps[h]) out.spurious_area += holes[h].Area();
  return out;
}

namespace {

// The search navigator's setup from the config (no privileged input: a search plans from the sensors only).
planning::SearchNavigatorSetup SearchSetup(const core::World& world, const Config& config, int num_agents) {
  planning::SearchNavigatorSetup s;
  s.num_agents = num_agents;
  s.bounds = world.bounds;
  s.closed = world.has_boundary();
  s.step_length = MotionFor(config, world).step_length;
  s.search = config.search;
  s.planning = config.planning;
  return s;
}

}  // namespace

TrialResult RunSearchTrial(const core::World& world, const Config& config, const TrialOptions& o, uint64_t seed,
                           mapping::MapView* final_view) {
  const auto t0 = std::chrono::steady_clock::now();
  TOPONAV_CHECK(o.num_agents >= 1, "num_agents " << o.num_agents);
  const bool open_world = !world.has_boundary();
  planning::SearchNavigator navigator(SearchSetup(world, config, o.num_agents));
  navigator.on_plan = o.on_plan;
  LoopOptions lo;
  lo.num_agents = o.num_agents;
  lo.max_steps = o.max_steps;
  lo.on_step = o.on_step;
  // MCMC cadence; open worlds spread the same proposals per step over more frequent calls.
  lo.mcmc_every = o.mcmc_every > 0 && open_world ? o.open_world_mcmc_every : o.mcmc_every;
  if (o.mcmc_every > 0)
    lo.mcmc_samples = std::max(1, int(std::lround(double(config.mapping.mcmc_samples) * lo.mcmc_every / o.mcmc_every)));
  const LoopResult loop = RunAgentLoop(world, config, lo, navigator, seed);
  TrialResult r;
  r.seed = seed;
  r.num_agents = o.num_agents;
  r.steps = loop.steps;
  r.distance = loop.distance;
  r.paths = loop.paths;
  r.sensors = SensorsUsed(config.sensor);
  r.explored = navigator.explored();
  r.end_reason = navigator.end_reason();
  r.nudges = navigator.nudges();
  r.give_ups = navigator.give_ups();
  r.inspections = navigator.inspections();
  r.sealed_steps = navigator.sealed_steps();
  r.blocks = navigator.blocks();
  r.iou = SearchIoU(world, loop.final_view);
  r.success = r.explored && r.iou > config.search.success_iou;
  r.time_map_s = loop.observe_s;
  r.time_mcmc_s = loop.mcmc_s;
  r.time_known_s = loop.view_s;
  r.time_plan_s = loop.plan_s;
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (final_view) *final_view = loop.final_view;
  return r;
}

}  // namespace toponav::experiments

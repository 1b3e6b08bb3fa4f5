#include "experiments/map_drive.h"

#include <chrono>
#include <limits>

#include "core/error.h"
#include "core/rng.h"
#include "sim/motion.h"
#include "sim/noisy_sensor.h"
#include "sim/paths.h"

namespace toponav::experiments {

mapping::PolygonSet KnownSet(const mapping::MapView& map) {
  if (map.known_set) return *map.known_set;
  std::vector<mapping::PolygonSet> parts;
  for (const auto& p : map.known_space) parts.push_back(mapping::PolygonSet::FromPolygon(p, /*check_simple=*/false));
  return mapping::PolygonSet::JoinAll(parts);
}

double KnownSpaceIoU(const core::World& world, const mapping::MapView& map) {
  return mapping::IoU(KnownSet(map), mapping::PolygonSet::FromPolygon(core::FreeSpacePolygon(world)));
}

MapDriveResult RunMapDrive(const core::World& world, const Config& config, const MapDriveOptions& o) {
  using Clock = std::chrono::steady_clock;
  std::vector<core::Vec2> path;
  const double clearance = config.motion.agent_radius + 1.0;  // room to pass clutter
  if (o.path == "guide") path = world.guide_path;
  else if (o.path == "goal") path = sim::FreePath(world, world.start.position(), world.goal, clearance);
  else if (o.path == "tour") path = sim::CoverageTour(world, world.start.position(), o.tour_spacing, clearance);
  else throw core::ConfigError("<command line>", "--path", o.path, "expected tour, guide or goal");
  if (path.size() < 2) throw core::DataError("<world>", "no drivable path of kind '" + o.path + "'");

  mapping::MapperOptions mo = config.mapping;
  mo.world_bounds = world.bounds;
  if (!world.has_boundary()) mo.open_region = world.bounds;  // open world: its bounds are the search region
  if (o.mcmc_every <= 0) mo.defer_to_mcmc = false;  // without MCMC every vertex with enough detections is kept
  mapping::Mapper mapper(mo);
  auto sensor = sim::CreateNoisyGroundTruthSensor(world, config.sensor, core::DeriveSeed(o.seed, 1));
  core::Rng rng(core::DeriveSeed(o.seed, 2));
  sim::MotionSim motion(world, config.motion);
  const int agent = motion.AddAgent(world.start);

  MapDriveResult r;
  double update_ms = 0, mcmc_ms = 0;
  int mcmc_calls = 0;
  size_t waypoint = 1;
  r.agent_path.push_back(world.start.position());
  for (int step = 0; step < o.max_steps && waypoint < path.size(); ++step) {
    const core::Pose2 pose = motion.Pose(agent);
    auto t0 = Clock::now();
    mapper.AddObservation(sensor->Observe(pose, agent));
    mapper.View();  // what a planner would ask for each step
    update_ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (o.mcmc_every > 0 && (step + 1) % o.mcmc_every == 0) {
      t0 = Clock::now();
      mapper.SampleMostLikelyMap(rng);
      mcmc_ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
      ++mcmc_calls;
    }
    // Follow the path; waypoints already reached are dropped.
    std::vector<core::Vec2> rest(path.begin() + long(waypoint), path.end());
    const sim::StepResult s = motion.Step(agent, rest);
    r.agent_path.push_back(s.pose.position());
    while (waypoint < path.size() && core::Distance(s.pose.position(), path[waypoint]) < 0.5 * sim::StepLength(config.motion, world))
      ++waypoint;
    if (s.blocked) ++waypoint;  // skip a waypoint we cannot reach (clutter in the way)
    r.steps = step + 1;
  }
  if (o.mcmc_every > 0) mapper.SampleMostLikelyMap(rng);
  r.view = mapper.ExactView();  // (the per-step views let vertices drift a little before known space follows)
  r.log_posterior = mapper.LogPosterior();
  r.known_space_iou = KnownSpaceIoU(world, r.view);
  const auto truth = core::MapVertices(world);
  r.map_vertices = int(r.view.vertices.size());
  int matched = 0;
  for (const auto& v : r.view.vertices) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : truth) best = std::min(best, core::Distance(v.position, t));
    r.false_vertices += best > kVertexMatchRadius;
    if (best <= kVertexMatchRadius) {
      r.mean_vertex_error += best;
      ++matched;
    }
  }
  if (matched > 0) r.mean_vertex_error /= matched;
  // A map wall is true when its ends match (within the radius) the two ends of one true wall.
  const auto rings = core::MapRings(world);
  auto nearest_ref = [&](const core::Vec2& p, core::VertexRef* ref) {
    double best = kVertexMatchRadius;
    bool found = false;
    for (size_t rr = 0; rr < rings.size(); ++rr)
      for (size_t i = 0; i < rings[rr]->size(); ++i) {
        const double d = core::Distance(p, (*rings[rr])[i]);
        if (d <= best) {
          best = d;
          *ref = {int(rr), int(i)};
          found = true;
        }
      }
    return found;
  };
  r.map_walls = int(r.view.walls.size());
  for (const auto& w : r.view.walls) {
    core::VertexRef a, b;
    bool ok = nearest_ref(w.pa, &a) && nearest_ref(w.pb, &b) && a.ring == b.ring;
    if (ok) {
      const int n = int(rings[size_t(a.ring)]->size());
      ok = (a.index + 1) % n == b.index || (b.index + 1) % n == a.index;
    }
    r.false_walls += !ok;
  }
  r.mean_update_ms = r.steps > 0 ? update_ms / r.steps : 0.0;
  r.mean_mcmc_ms = mcmc_calls > 0 ? mcmc_ms / mcmc_calls : 0.0;
  return r;
}

}  // namespace toponav::experiments

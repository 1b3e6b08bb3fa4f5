#include "experiments/map_drive.h"

#include <limits>
#include <optional>

#include "core/error.h"
#include "experiments/agent_loop.h"
#include "experiments/corridor_cuts.h"
#include "experiments/trial.h"
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

namespace {

// Follows a fixed path: waypoints within half a step of the agent are reached, one it cannot get to (clutter
// in the way) is skipped; the run ends when the path's end is reached.
class FollowPath : public planning::Navigator {
 public:
  explicit FollowPath(std::vector<core::Vec2> path) : path_(std::move(path)) {}
  bool Plan(const planning::NavigatorInput& input, std::vector<std::vector<core::Vec2>>* paths) override {
    if (next_ >= path_.size()) return false;
    (*paths)[0].assign(path_.begin() + long(next_), path_.end());
    return true;
  }
  planning::StepResponse AfterStep(const planning::NavigatorInput& input, int agent, const planning::MotionOutcome& s,
                                   core::Rng& rng) override {
    while (next_ < path_.size() && core::Distance(s.pose.position(), path_[next_]) < 0.5 * input.step_length) ++next_;
    if (s.blocked) ++next_;
    return {};
  }

 private:
  std::vector<core::Vec2> path_;
  size_t next_ = 1;
};

// Auto (0): 20, or half the maze's cell pitch in a guided maze (a coarser grid skips whole corridors).
double TourSpacing(const core::World& world, const MapDriveOptions& o) {
  if (o.tour_spacing > 0) return o.tour_spacing;
  return world.kind == core::WorldKind::kGuidedMaze ? 11.0 : 20.0;
}

std::vector<core::Vec2> DrivePath(const core::World& world, const Config& config, const MapDriveOptions& o) {
  std::vector<core::Vec2> path;
  const double clearance = config.motion.agent_radius + 1.0;  // room to pass clutter
  if (o.path == "guide") path = world.guide_path;
  else if (o.path == "goal") path = sim::FreePath(world, world.start.position(), world.goal, clearance);
  else if (o.path == "tour") path = sim::CoverageTour(world, world.start.position(), TourSpacing(world, o), clearance);
  else throw core::ConfigError("<command line>", "--path", o.path, "expected tour, guide or goal");
  if (path.size() < 2) throw core::DataError("<world>", "no drivable path of kind '" + o.path + "'");
  return path;
}

// Map vertices against the world's true vertices: false ones, and the mean error of the others.
void ScoreVertices(const core::World& world, MapDriveResult* out) {
  MapDriveResult& r = *out;
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
}

// 'radius': the agent's, for walls that cut a corridor.
void ScoreWalls(const core::World& world, double radius, MapDriveResult* out) {
  MapDriveResult& r = *out;
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
  std::optional<FreeSpaceRegions> regions;  // made when a wall reaches into free space
  for (const auto& w : r.view.walls) {
    core::VertexRef a, b;
    bool ok = nearest_ref(w.pa, &a) && nearest_ref(w.pb, &b) && a.ring == b.ring;
    if (ok) {
      const int n = int(rings[size_t(a.ring)]->size());
      ok = (a.index + 1) % n == b.index || (b.index + 1) % n == a.index;
    }
    r.false_walls += !ok;
    // Across free space: somewhere along it (sampled every unit) deeper than kAcrossDepth into true free space.
    const double length = core::Distance(w.pa, w.pb);
    bool across = false;
    for (double t = 0; t <= length && !across; t += 1.0)
      across = core::SignedDistance(world, w.pa + (w.pb - w.pa) * (t / std::max(length, 1e-9)), false) > kAcrossDepth;
    r.walls_across_free_space += across;
    if (!across) continue;
    if (!regions) regions.emplace(world, radius, kCutMinArea);
    r.walls_across_corridor += regions->Cuts({w.pa, w.pb});
  }
}

}  // namespace

MapDriveResult RunMapDrive(const core::World& world, const Config& config, const MapDriveOptions& o) {
  FollowPath policy(DrivePath(world, config, o));
  LoopOptions lo;
  lo.max_steps = o.max_steps;
  lo.mcmc_every = o.mcmc_every;
  const LoopResult loop = RunAgentLoop(world, config, lo, policy, o.seed);
  MapDriveResult r;
  r.agent_path = loop.paths[0];
  r.steps = loop.steps;
  r.mean_update_ms = r.steps > 0 ? 1e3 * (loop.observe_s + loop.view_s) / r.steps : 0.0;
  r.mean_mcmc_ms = loop.mcmc_calls > 0 ? 1e3 * loop.mcmc_s / loop.mcmc_calls : 0.0;
  r.view = loop.final_view;
  r.log_posterior = loop.mapper->LogPosterior();
  r.known_space_iou = KnownSpaceIoU(world, r.view);
  if (!world.has_boundary()) r.building_iou = BuildingPlacementIoU(world, r.view);
  ScoreVertices(world, &r);
  ScoreWalls(world, config.motion.agent_radius, &r);
  return r;
}

}  // namespace toponav::experiments

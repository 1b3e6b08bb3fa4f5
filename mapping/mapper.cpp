// The Mapper's front door: it keeps the map's evidence (mapping/internal/map_core.h) and hands the work to
// the concerns under mapping/internal/ (association and Kalman updates, wall evidence, posterior and MCMC,
// known space, frontiers).  References: the paper's Sec. III and vertexnav.md §2 (with the fixes of §10
// items 2-3, 7).
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>
#include <string>

#include "core/error.h"
#include "mapping/internal/frontiers.h"
#include "mapping/internal/known_space.h"
#include "mapping/internal/map_core.h"
#include "mapping/internal/mcmc.h"
#include "mapping/internal/posterior.h"
#include "mapping/internal/stars.h"
#include "mapping/internal/walls_past_vertices.h"
#include "mapping/mapping.h"

namespace toponav::mapping {

using core::Vec2;

namespace internal {

double Wrap2Pi(double a) {
  a = std::fmod(a, 2 * core::kPi);
  return a < 0 ? a + 2 * core::kPi : a;
}

}  // namespace internal

double MapView::known_area() const {
  double a = 0;
  for (const auto& p : known_space) a += core::Area(p);
  return a;
}

const core::OptionFields<MapperOptions>& MapperOptions::Fields() {
  using O = MapperOptions;
  static const core::OptionFields<O> fields{
      {"association_gate_chi2", &O::association_gate_chi2, 0.01, 1000.0},
      {"association_count_bias", &O::association_count_bias, 0.0, 100.0},
      {"false_positive_rate", &O::false_positive_rate, 1e-6, 0.999},
      {"false_negative_rate", &O::false_negative_rate, 1e-6, 0.999},
      {"vertex_log_prior", &O::vertex_log_prior, -100.0, 0.0},
      {"wall_log_prior", &O::wall_log_prior, -100.0, 0.0},
      {"min_detections", &O::min_detections, 1, 1000},
      {"wall_threshold", &O::wall_threshold, 0.01, 0.99},
      {"wall_skip_damping", &O::wall_skip_damping, 0.0, 1.0},
      {"wall_min_view_angle", &O::wall_min_view_angle, 0.0, 1.0},
      {"wall_on_segment_tolerance", &O::wall_on_segment_tolerance, 0.0, 100.0},
      {"wall_past_vertex_tolerance", &O::wall_past_vertex_tolerance, 0.0, 100.0},
      {"wall_front_vertex_tolerance", &O::wall_front_vertex_tolerance, 0.0, 100.0},
      {"wall_past_detection_min", &O::wall_past_detection_min},
      {"wall_evidence_min", &O::wall_evidence_min},
      {"edge_log_floor", &O::edge_log_floor, -100.0, -1e-6},
      {"mcmc_samples", &O::mcmc_samples, 0, 100000},
      {"mcmc_window", &O::mcmc_window, 1, 1000000},
      {"defer_to_mcmc", &O::defer_to_mcmc},
      {"max_range", &O::max_range, 1.0, 1e4},
      {"known_space_candidates", &O::known_space_candidates},
      {"star_rebuild_tolerance", &O::star_rebuild_tolerance, 0.0, 100.0},
      {"frontier_wall_tolerance", &O::frontier_wall_tolerance, 0.0, 100.0},
      {"frontier_split_angle", &O::frontier_split_angle, 0.0, core::kPi},
      {"frontier_split_min_length", &O::frontier_split_min_length, 0.0, 1000.0},
      {"open_frontier_reach", &O::open_frontier_reach, 0.0, 1000.0},
  };
  return fields;
}

void MapperOptions::Validate() const {
  core::CheckRanges(*this, Fields(), "mapping.");
  if (open_region && !(open_region->max.x > open_region->min.x && open_region->max.y > open_region->min.y))
    throw core::ConfigError("<options>", "mapping.open_region", std::to_string(open_region->width()),
                            "must have a positive width and height");
}

namespace {

void CheckObservation(const MapperOptions& o, const core::Observation& z) {
  auto bad = [](const std::string& what) { throw core::DataError("<observation>", what); };
  if (!std::isfinite(z.pose.x) || !std::isfinite(z.pose.y) || !std::isfinite(z.pose.yaw)) bad("pose is not finite");
  if (o.world_bounds && !o.world_bounds->Contains(z.pose.position()))
    bad("pose (" + std::to_string(z.pose.x) + ", " + std::to_string(z.pose.y) + ") is outside the world");
  for (size_t k = 0; k < z.detections.size(); ++k) {
    const auto& d = z.detections[k];
    const std::string at = "detection " + std::to_string(k) + ": ";
    if (!std::isfinite(d.range) || !std::isfinite(d.bearing) || d.range < 0)
      bad(at + "range/bearing is NaN, infinite or negative");
    const auto& c = d.polar;
    if (!std::isfinite(c.xx) || !std::isfinite(c.xy) || !std::isfinite(c.yy) || c.xx <= 0 || c.yy <= 0 ||
        c.xx * c.yy - c.xy * c.xy <= 0)
      bad(at + "covariance is not positive definite");
    for (double p : d.labels)
      if (!std::isfinite(p) || p < 0) bad(at + "label probabilities must be finite and non-negative");
  }
}

}  // namespace

struct Mapper::Impl {
  explicit Impl(const MapperOptions& options) : core(options) {}
  internal::MapCore core;
  internal::KnownSpace known;
  internal::FrontierTracker frontiers;
  // The map planners see (and known space is computed against): frozen at each MCMC call when
  // options.defer_to_mcmc, otherwise the live state.
  internal::MapState view_map;
  MapperStats stats;
  std::unordered_set<uint64_t> confirmed;  // walls (WallKey) an agent pressed against and could not pass

  const internal::MapState& ViewMap() {
    if (!core.o.defer_to_mcmc) view_map = core.walls.State(core.vertices);
    const size_t n = core.vertices.size();
    if (view_map.mapped.size() < n) view_map.mapped.resize(n, 0);  // newer vertices: not yet in
    return view_map;
  }
  void Add(const core::Observation& z);
  MapView MakeView(double tolerance);
};

void Mapper::Impl::Add(const core::Observation& z) {
  CheckObservation(core.o, z);
  internal::Obs ob;
  ob.pose = z.pose;
  ob.det = z.detections;
  std::sort(ob.det.begin(), ob.det.end(), [](const auto& a, const auto& b) { return a.bearing < b.bearing; });
  const size_t n = ob.det.size();
  std::vector<Eigen::Vector2d> zpos(n);
  std::vector<Eigen::Matrix2d> R(n);
  ob.at.resize(n);
  ob.cov.resize(n);
  for (size_t k = 0; k < n; ++k) {
    const Vec2 p = core::DetectionPosition(z.pose, ob.det[k]);
    ob.at[k] = p;
    zpos[k] = {p.x, p.y};
    R[k] = internal::ToEigen(core::DetectionCovariance(z.pose, ob.det[k]));
    ob.cov[k] = R[k].ldlt();
  }
  ob.vid = core.vertices.Update(zpos, R);
  core.walls.Add(ob, core.vertices);
  core.obs.push_back(std::move(ob));
  internal::RefreshStar(&core, core.obs.size() - 1);
}

MapView Mapper::Impl::MakeView(double tolerance) {
  internal::RefreshStars(&core, tolerance);
  internal::MapState drawn;
  const double past = core.o.wall_past_vertex_tolerance;
  if (past > 0) drawn = internal::WithoutWallsPastVertices(core, ViewMap(), past);
  const internal::MapState& ms = past > 0 ? drawn : ViewMap();
  known.Update(core, ms, tolerance);
  MapView view;
  for (size_t i = 0; i < core.vertices.size(); ++i) {
    if (!core.vertices.Seen(int(i))) continue;
    const auto& x = core.vertices[i];
    const MapVertex mv{int(i), internal::ToVec(x.x), internal::FromEigen(x.P), x.n};
    (ms.mapped[i] ? view.vertices : view.rejected).push_back(mv);
  }
  for (const auto& [a, b] : ms.walls) {
    const bool certain = confirmed.count(internal::WallKey(a, b)) > 0;
    view.walls.push_back({a, b, core.Pos(a), core.Pos(b), certain ? 1.0 : core.walls.Prob(a, b, ms.mapped), certain});
  }
  view.known_space = known.total().Polygons();
  view.known_set = std::make_shared<const PolygonSet>(known.total());
  view.frontiers = frontiers.Extract(core, ms, view.known_space);
  view.num_observations = int(core.obs.size());
  return view;
}

Mapper::Mapper(const MapperOptions& options) {
  options.Validate();
  impl_ = std::make_unique<Impl>(options);
}
Mapper::~Mapper() = default;

void Mapper::AddObservation(const core::Observation& z) { impl_->Add(z); }

bool Mapper::AddContact(const core::Contact& c) {
  const double length = core::Distance(c.at, c.toward);
  if (!(c.reach > 0) || !(length > 1e-9)) return false;
  const core::Segment2 way{c.at, c.at + (c.toward - c.at) * (c.reach / length)};
  const internal::MapState& ms = impl_->ViewMap();
  double nearest = std::numeric_limits<double>::infinity();
  uint64_t key = 0;
  for (const auto& [a, b] : ms.walls) {
    const core::Segment2 wall{impl_->core.Pos(a), impl_->core.Pos(b)};
    if (!core::SegmentsIntersect(way, wall)) continue;
    const double d = core::DistanceToSegment(c.at, wall);
    if (d < nearest) nearest = d, key = internal::WallKey(a, b);
  }
  if (!std::isfinite(nearest)) return false;
  impl_->confirmed.insert(key);
  return true;
}

double Mapper::SampleMostLikelyMap(core::Rng& rng, int samples) {
  const double gain = internal::SampleMostLikelyMap(&impl_->core, rng,
                                                    samples < 0 ? impl_->core.o.mcmc_samples : samples, &impl_->stats);
  impl_->view_map = impl_->core.walls.State(impl_->core.vertices);
  return gain;
}

double Mapper::LogPosterior() const {
  return internal::LogPosterior(impl_->core, impl_->core.walls.State(impl_->core.vertices));
}
double Mapper::LogPosteriorIf(const std::vector<std::pair<int, bool>>& inclusion) const {
  internal::MapState ms = impl_->core.walls.State(impl_->core.vertices);
  for (const auto& [id, on] : inclusion) {
    TOPONAV_CHECK(id >= 0 && size_t(id) < impl_->core.vertices.size(), "no potential vertex " << id);
    impl_->core.walls.SetMapped(id, on, &ms);
  }
  return internal::LogPosterior(impl_->core, ms);
}

const MapperOptions& Mapper::options() const { return impl_->core.o; }

std::vector<MapVertex> Mapper::PotentialVertices() const {
  std::vector<MapVertex> out;
  for (size_t i = 0; i < impl_->core.vertices.size(); ++i) {
    const auto& x = impl_->core.vertices[i];
    out.push_back({int(i), internal::ToVec(x.x), internal::FromEigen(x.P), x.n});
  }
  return out;
}

MapperStats Mapper::Stats() const {
  MapperStats s = impl_->stats;
  s.num_potential_vertices = int(impl_->core.vertices.size());
  s.num_walls_with_evidence = int(impl_->core.walls.size());
  return s;
}

MapView Mapper::View() { return impl_->MakeView(impl_->core.o.star_rebuild_tolerance); }
MapView Mapper::ExactView() { return impl_->MakeView(0.0); }

}  // namespace toponav::mapping

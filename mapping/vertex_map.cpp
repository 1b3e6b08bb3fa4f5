// The Mapper: association, Kalman updates, wall evidence, posterior, MCMC, known space and frontiers.
// References: the paper's Sec. III and vertexnav.md §2 (with the fixes of §10 items 2-3, 7).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "core/assignment.h"
#include "core/error.h"
#include "mapping/mapping.h"

namespace toponav::mapping {

using core::Vec2;

namespace {

Eigen::Matrix2d ToEigen(const core::Cov2& c) {
  Eigen::Matrix2d m;
  m << c.xx, c.xy, c.xy, c.yy;
  return m;
}
core::Cov2 FromEigen(const Eigen::Matrix2d& m) { return {m(0, 0), 0.5 * (m(0, 1) + m(1, 0)), m(1, 1)}; }
Vec2 ToVec(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
uint64_t WallKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
}
double Wrap2Pi(double a) {
  a = std::fmod(a, 2 * core::kPi);
  return a < 0 ? a + 2 * core::kPi : a;
}
using core::BoxHits;
using core::BoxHitsSegment;

}  // namespace

double MapView::known_area() const {
  double a = 0;
  for (const auto& p : known_space) a += core::Area(p);
  return a;
}

void MapperOptions::Validate() const {
  auto fail = [](const char* key, double v, const char* why) {
    throw core::ConfigError("<options>", key, std::to_string(v), why);
  };
  if (!(association_gate_chi2 > 0)) fail("mapping.association_gate_chi2", association_gate_chi2, "must be > 0");
  if (!(false_positive_rate > 0 && false_positive_rate < 1)) fail("mapping.false_positive_rate", false_positive_rate, "must be in (0, 1)");
  if (!(false_negative_rate > 0 && false_negative_rate < 1)) fail("mapping.false_negative_rate", false_negative_rate, "must be in (0, 1)");
  if (!(vertex_log_prior <= 0)) fail("mapping.vertex_log_prior", vertex_log_prior, "must be <= 0");
  if (!(wall_log_prior <= 0)) fail("mapping.wall_log_prior", wall_log_prior, "must be <= 0");
  if (min_detections < 1) fail("mapping.min_detections", min_detections, "must be >= 1");
  if (!(wall_threshold > 0 && wall_threshold < 1)) fail("mapping.wall_threshold", wall_threshold, "must be in (0, 1)");
  if (!(wall_skip_damping >= 0 && wall_skip_damping <= 1)) fail("mapping.wall_skip_damping", wall_skip_damping, "must be in [0, 1]");
  if (!(association_count_bias >= 0)) fail("mapping.association_count_bias", association_count_bias, "must be >= 0");
  if (!(wall_on_segment_tolerance >= 0)) fail("mapping.wall_on_segment_tolerance", wall_on_segment_tolerance, "must be >= 0");
  if (!(edge_log_floor < 0)) fail("mapping.edge_log_floor", edge_log_floor, "must be < 0");
  if (mcmc_samples < 0) fail("mapping.mcmc_samples", mcmc_samples, "must be >= 0");
  if (mcmc_window < 1) fail("mapping.mcmc_window", mcmc_window, "must be >= 1");
  if (!(max_range > 0)) fail("mapping.max_range", max_range, "must be > 0");
  if (!(star_rebuild_tolerance >= 0)) fail("mapping.star_rebuild_tolerance", star_rebuild_tolerance, "must be >= 0");
  if (union_block < 1) fail("mapping.union_block", union_block, "must be >= 1");
  if (!(frontier_wall_tolerance >= 0)) fail("mapping.frontier_wall_tolerance", frontier_wall_tolerance, "must be >= 0");
  if (!(frontier_split_angle >= 0 && frontier_split_angle <= core::kPi)) fail("mapping.frontier_split_angle", frontier_split_angle, "must be in [0, pi]");
  if (!(frontier_split_min_length >= 0)) fail("mapping.frontier_split_min_length", frontier_split_min_length, "must be >= 0");
  if (!(open_frontier_reach >= 0)) fail("mapping.open_frontier_reach", open_frontier_reach, "must be >= 0");
  if (!(open_sample_step > 0 && open_sample_step <= 0.5)) fail("mapping.open_sample_step", open_sample_step, "must be in (0, 0.5]");
  if (open_region && !(open_region->max.x > open_region->min.x && open_region->max.y > open_region->min.y))
    fail("mapping.open_region", open_region->width(), "must have a positive width and height");
}

std::vector<std::vector<Vec2>> SplitAtTurns(const std::vector<Vec2>& p, double max_turn, double min_length) {
  const size_t n = p.size();
  if (n < 3) return {p};
  std::vector<double> at(n, 0.0);  // length along the chain
  for (size_t i = 1; i < n; ++i) at[i] = at[i - 1] + core::Distance(p[i - 1], p[i]);
  const double total = at[n - 1];
  if (!(total > 0)) return {p};
  const bool closed = n > 3 && p.front() == p.back();  // a ring: it has no ends
  // Turns are measured over kSpan of chain on either side, not per edge (exact-to-double conversion leaves
  // tiny edges pointing anywhere): the points that far before / after point i (wrapping around a ring).
  constexpr double kSpan = 1.0;
  auto back = [&](size_t i) {
    for (size_t k = 1; k < n; ++k) {
      const size_t j = closed ? (i + (n - 1) - k) % (n - 1) : (i >= k ? i - k : 0);
      const double d = closed ? std::fmod(at[i] - at[j] + total, total) : at[i] - at[j];
      if (d >= kSpan || (!closed && j == 0)) return p[j];
    }
    return p[i];
  };
  auto ahead = [&](size_t i) {
    for (size_t k = 1; k < n; ++k) {
      const size_t j = closed ? (i + k) % (n - 1) : std::min(i + k, n - 1);
      const double d = closed ? std::fmod(at[j] - at[i] + total, total) : at[j] - at[i];
      if (d >= kSpan || (!closed && j == n - 1)) return p[j];
    }
    return p[i];
  };
  auto turn = [&](size_t i) {
    const Vec2 d0 = p[i] - back(i), d1 = ahead(i) - p[i];
    return std::abs(std::atan2(core::Cross(d0, d1), core::Dot(d0, d1)));
  };
  const double min_len = min_length + 1e-6;  // every piece keeps at least min_length
  std::vector<size_t> cuts;
  size_t from = 0;
  for (size_t i = 1; i + 1 < n; ++i)
    if (at[i] - at[from] >= min_len && total - at[i] >= min_len && turn(i) > max_turn) {
      cuts.push_back(i);
      from = i;
    }
  // A ring starts wherever it happened to start: its first and last pieces are one unless it turns there too.
  const bool rejoin = closed && !cuts.empty() && !(turn(0) > max_turn && at[cuts.front()] >= min_len);
  std::vector<std::vector<Vec2>> pieces;
  from = 0;
  for (size_t c : cuts) {
    pieces.emplace_back(p.begin() + long(from), p.begin() + long(c) + 1);
    from = c;
  }
  pieces.emplace_back(p.begin() + long(from), p.end());
  if (rejoin) {
    pieces.back().insert(pieces.back().end(), pieces.front().begin() + 1, pieces.front().end());
    pieces.erase(pieces.begin());
  }
  return pieces;
}

struct Mapper::Impl {
  struct Vertex {
    Eigen::Vector2d x;
    Eigen::Matrix2d P;
    int n = 0;
    bool in_map = true;  // the MCMC state; only counts once n >= min_detections
  };
  // Evidence for a wall: samples that do not depend on the map ('sum'), and samples with detections lying on
  // the segment between the two vertices, which damp the sample only while their vertex is in the map.
  struct CondSample {
    double value = 0.0;
    std::vector<int> on_segment;  // vertices of those detections
  };
  struct WallStats {
    double sum = 0.0;
    int count = 0;
    std::vector<CondSample> cond;
  };
  struct Obs {
    core::Pose2 pose;
    std::vector<core::Detection> det;
    std::vector<int> vid;          // vertex of each detection
    std::vector<Vec2> at;          // each detection's position in the world ...
    std::vector<Eigen::LDLT<Eigen::Matrix2d>> cov;  // ... and its covariance, factored (for the likelihood)
    // Star polygon of the real observation from the positions its vertices had when it was built.
    core::Ring star;
    core::Aabb2 box;
    std::vector<Vec2> star_src;
    // Cached conservative known space S_c of this observation, with what it was built from.
    std::vector<int> sc_ids;
    std::vector<uint64_t> sc_walls;  // open region: the map walls that bounded its hypothetical polygon
    PolygonSet sc;
    bool sc_valid = false;
  };

  // A proposed map: which vertices are in it and its walls (sorted pairs, a < b), with a key set for lookups.
  struct MapState {
    std::vector<char> mapped;
    std::vector<std::pair<int, int>> walls;
    std::unordered_set<uint64_t> wall_keys;
    int num_vertices = 0;
    bool HasWall(int a, int b) const { return wall_keys.count(WallKey(a, b)) > 0; }
  };

  MapperOptions o;
  std::vector<Vertex> v;
  std::unordered_map<uint64_t, WallStats> walls;
  std::vector<std::vector<uint64_t>> spans;  // vertex -> walls whose evidence it can damp (on their segment)
  std::vector<std::vector<int>> neighbours;  // vertex -> vertices it shares wall evidence with
  std::vector<Obs> obs;
  mutable std::vector<PolygonSet> blocks;
  bool star_cache = false;                            // set during Sample: star_members is valid
  mutable std::vector<std::vector<int>> star_members;  // observation -> potential vertices inside its star
  mutable std::vector<char> star_members_ok;
  mutable std::vector<PolygonSet> union_tree;  // binary tree over the blocks: node k = union of 2k and 2k+1
  mutable std::vector<char> tree_dirty;
  mutable std::vector<char> block_dirty;
  mutable PolygonSet total;
  mutable bool total_valid = false;           // false: rebuild from the blocks on the next update
  mutable std::vector<char> snap_mapped;      // map membership at the last update
  mutable std::vector<char> snap_member;      // ... and membership of hypothetical observations (map vertices,
                                              // and seen candidates with known_space_candidates)
  mutable std::vector<Vec2> drift_ref;        // where each vertex was when its drift was last flagged
  mutable std::vector<std::pair<int, int>> snap_walls;
  mutable std::vector<Frontier> last_frontiers;
  mutable int next_frontier_id = 0;
  MapperStats stats;
  // The map planners see (and known space is computed against): frozen at each MCMC call when
  // options.defer_to_mcmc, otherwise the live state.
  mutable MapState view_map;

  void FreezeViewMap() const { view_map = LiveState(); }
  const MapState& ViewMap() const {
    if (!o.defer_to_mcmc) FreezeViewMap();
    if (view_map.mapped.size() < v.size()) view_map.mapped.resize(v.size(), 0);  // newer vertices: not yet in
    return view_map;
  }

  bool Mapped(int i) const { return v[size_t(i)].n >= o.min_detections && v[size_t(i)].in_map; }

  MapState LiveState() const {
    MapState ms;
    ms.mapped.resize(v.size());
    for (size_t i = 0; i < v.size(); ++i) ms.num_vertices += ms.mapped[i] = Mapped(int(i));
    ms.walls = MappedWalls(ms.mapped);
    for (const auto& w : ms.walls) ms.wall_keys.insert(WallKey(w.first, w.second));
    return ms;
  }

  // Walls whose existence changes when vertex i flips in 'ms': its own walls to mapped vertices, and walls
  // between two mapped vertices whose evidence i damps while mapped (it lies on their segment).
  std::vector<std::pair<int, int>> ChangedWalls(int i, const MapState& ms) const {
    std::vector<std::pair<int, int>> out;
    const bool on = !ms.mapped[size_t(i)];
    for (int j : neighbours[size_t(i)])
      if (ms.mapped[size_t(j)] && WallProb(i, j, ms.mapped, i, on) > o.wall_threshold)
        out.push_back({std::min(i, j), std::max(i, j)});
    if (size_t(i) < spans.size())
      for (uint64_t key : spans[size_t(i)]) {
        const int a = int(key >> 32), b = int(key & 0xffffffffu);
        if (a == i || b == i || !ms.mapped[size_t(a)] || !ms.mapped[size_t(b)]) continue;
        const bool now = WallProb(a, b, ms.mapped) > o.wall_threshold;
        const bool then = WallProb(a, b, ms.mapped, i, on) > o.wall_threshold;
        if (now != then) out.push_back({a, b});
      }
    return out;
  }

  void SetMapped(int i, bool on, MapState* ms) const {
    if (bool(ms->mapped[size_t(i)]) == on) return;
    const auto changed = ChangedWalls(i, *ms);
    ms->mapped[size_t(i)] = on;
    ms->num_vertices += on ? 1 : -1;
    for (const auto& w : changed) {
      const uint64_t key = WallKey(w.first, w.second);
      if (!ms->wall_keys.count(key)) {
        ms->walls.insert(std::lower_bound(ms->walls.begin(), ms->walls.end(), w), w);
        ms->wall_keys.insert(key);
      } else {
        ms->walls.erase(std::lower_bound(ms->walls.begin(), ms->walls.end(), w));
        ms->wall_keys.erase(key);
      }
    }
  }
  // The wall's averaged evidence under the map 'mapped' (with vertex 'flip' set to 'flip_on' if given).
  double WallProb(int a, int b, const std::vector<char>& mapped, int flip = -1, bool flip_on = false) const {
    auto it = walls.find(WallKey(a, b));
    if (it == walls.end()) return 0.0;
    const WallStats& w = it->second;
    double sum = w.sum;
    for (const auto& c : w.cond) {
      int damp = 0;
      for (int id : c.on_segment) damp += id == flip ? flip_on : (size_t(id) < mapped.size() && mapped[size_t(id)]);
      sum += c.value * std::pow(o.wall_skip_damping, double(damp));
    }
    return sum / (w.count + 1);  // shrinks one sighting to 1/2
  }
  Vec2 Pos(int i) const { return ToVec(v[size_t(i)].x); }

  // ------------------------------------------------------------ adding observations

  void Validate(const core::Observation& z) const {
    auto bad = [](const std::string& what) { throw core::DataError("<observation>", what); };
    if (!std::isfinite(z.pose.x) || !std::isfinite(z.pose.y) || !std::isfinite(z.pose.yaw)) bad("pose is not finite");
    if (o.world_bounds && !o.world_bounds->Contains(z.pose.position()))
      bad("pose (" + std::to_string(z.pose.x) + ", " + std::to_string(z.pose.y) + ") is outside the world");
    for (size_t k = 0; k < z.detections.size(); ++k) {
      const auto& d = z.detections[k];
      const std::string at = "detection " + std::to_string(k) + ": ";
      if (!std::isfinite(d.range) || !std::isfinite(d.bearing) || d.range < 0) bad(at + "range/bearing is NaN, infinite or negative");
      const auto& c = d.polar;
      if (!std::isfinite(c.xx) || !std::isfinite(c.xy) || !std::isfinite(c.yy) || c.xx <= 0 || c.yy <= 0 ||
          c.xx * c.yy - c.xy * c.xy <= 0)
        bad(at + "covariance is not positive definite");
      for (double p : d.labels)
        if (!std::isfinite(p) || p < 0) bad(at + "label probabilities must be finite and non-negative");
    }
  }

  void Add(const core::Observation& z) {
    Validate(z);
    Obs ob;
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
      R[k] = ToEigen(core::DetectionCovariance(z.pose, ob.det[k]));
      ob.cov[k] = R[k].ldlt();
    }
    // Association: rows = detections, columns = gated candidate vertices + one "new vertex" slot per
    // detection.  Cost = squared Mahalanobis distance of the innovation (covariance P + R), plus a bias
    // towards well-supported vertices; a new vertex costs the gate itself.  The assignment is one-to-one: no two detections of one observation share a vertex.
    std::vector<int> cand;
    std::unordered_map<int, int> col_of;
    std::vector<std::vector<std::pair<int, double>>> gated(n);
    for (size_t k = 0; k < n; ++k) {
      for (size_t i = 0; i < v.size(); ++i) {
        const Eigen::Matrix2d S = v[i].P + R[k];
        const Eigen::Vector2d e = zpos[k] - v[i].x;
        // Cheap rejection: m^2 >= |e|^2 / lambda_max(S) >= |e|^2 / trace(S).
        if (e.squaredNorm() > o.association_gate_chi2 * S.trace()) continue;
        const double m2 = e.dot(S.ldlt().solve(e));
        if (m2 < o.association_gate_chi2) {
          if (!col_of.count(int(i))) {
            col_of[int(i)] = int(cand.size());
            cand.push_back(int(i));
          }
          gated[k].push_back({int(i), m2});
        }
      }
    }
    ob.vid.assign(n, -1);
    if (n > 0) {
      const double big = 1e9;
      std::vector<std::vector<double>> cost(n, std::vector<double>(cand.size() + n, big));
      for (size_t k = 0; k < n; ++k) {
        // Among the gated vertices, one with fewer detections than the best-supported one pays
        // association_count_bias * ln(ratio), kept below the gate (joining still beats a new vertex): a
        // duplicate born beside a vertex (a false detection next to it) starves instead of taking half of
        // its detections, which would leave both out of the map.
        int most = 1;
        for (const auto& g : gated[k]) most = std::max(most, v[size_t(g.first)].n);
        for (const auto& [vi, m2] : gated[k]) {
          const double penalty = o.association_count_bias * std::log(double(most) / std::max(1, v[size_t(vi)].n));
          cost[k][size_t(col_of[vi])] = std::min(m2 + penalty, 0.999 * o.association_gate_chi2);
        }
        cost[k][cand.size() + k] = o.association_gate_chi2;
      }
      const std::vector<int> col = core::SolveAssignment(cost);
      for (size_t k = 0; k < n; ++k)
        if (col[k] >= 0 && size_t(col[k]) < cand.size() && cost[k][size_t(col[k])] < big) ob.vid[k] = cand[size_t(col[k])];
    }
    // Kalman updates of matched vertices; new vertices for the rest.
    for (size_t k = 0; k < n; ++k) {
      if (ob.vid[k] >= 0) {
        Vertex& x = v[size_t(ob.vid[k])];
        const Eigen::Matrix2d K = x.P * (x.P + R[k]).inverse();
        x.x += K * (zpos[k] - x.x);
        x.P = (Eigen::Matrix2d::Identity() - K) * x.P;
        x.P = 0.5 * (x.P + x.P.transpose());
        x.n += 1;
      } else {
        Vertex nv;
        nv.x = zpos[k];
        nv.P = R[k];
        nv.n = 1;
        nv.in_map = !o.defer_to_mcmc;  // with MCMC, a vertex enters the map when a sample accepts it
        v.push_back(nv);
        neighbours.emplace_back();
        ob.vid[k] = int(v.size()) - 1;
      }
    }
    AddWallEvidence(ob);
    obs.push_back(std::move(ob));
    RefreshStar(obs.size() - 1);
    if (blocks.size() * size_t(o.union_block) < obs.size()) {
      blocks.emplace_back();
      block_dirty.push_back(1);
    }
  }

  // Wall evidence of one observation: every pair less than pi apart, R = i and L = j counter-clockwise of
  // it; each detection between them scales the evidence by wall_skip_damping (vertexnav.md §2.4) -- except,
  // beyond the reference, a detection lying on the segment between the two (within wall_on_segment_tolerance)
  // damps it only while its vertex is in the map: a false detection on a wall that the map rejects does not
  // hide the wall, while a doorway's jamb on the line does once it is mapped (evidence is conditional on
  // the map, so MCMC weighs the jamb and the wall across the door together), and such a pair's evidence
  // needs both ends to say a wall runs on (wall_past_detection_min).
  void AddWallEvidence(const Obs& ob) {
    const size_t n = ob.det.size();
    const std::vector<Vec2>& at = ob.at;
    auto on_segment = [&](const Vec2& p, const Vec2& a, const Vec2& b) {
      const Vec2 d = b - a;
      const double len2 = core::Dot(d, d);
      if (o.wall_on_segment_tolerance <= 0 || len2 < 1e-12) return false;
      const double t = core::Dot(p - a, d) / len2;
      return t > 0 && t < 1 && std::abs(core::Cross(d, p - a)) / std::sqrt(len2) < o.wall_on_segment_tolerance;
    };
    if (spans.size() < v.size()) spans.resize(v.size());
    for (size_t i = 0; i < n; ++i) {
      for (size_t s = 1; s < n; ++s) {
        const size_t j = (i + s) % n;
        if (Wrap2Pi(ob.det[j].bearing - ob.det[i].bearing) >= core::kPi) break;
        const int a = ob.vid[i], b = ob.vid[j];
        if (a == b) continue;
        int fixed = 0;
        CondSample c;
        for (size_t t = 1; t < s; ++t) {
          const size_t k = (i + t) % n;
          if (ob.vid[k] != a && ob.vid[k] != b && on_segment(at[k], at[i], at[j])) c.on_segment.push_back(ob.vid[k]);
          else ++fixed;
        }
        const uint64_t key = WallKey(a, b);
        WallStats& w = walls[key];
        if (w.count == 0) {
          neighbours[size_t(a)].push_back(b);
          neighbours[size_t(b)].push_back(a);
        }
        w.count += 1;
        const double no_i = core::NoWallCcw(ob.det[i].labels), no_j = core::NoWallCw(ob.det[j].labels);
        // Past a detection both ends must say wall (closed worlds: open-world buildings have no doorways).
        const bool both = !c.on_segment.empty() && o.wall_past_detection_min && !o.open_region;
        c.value = std::pow(o.wall_skip_damping, double(fixed)) * (both ? 1.0 - std::max(no_i, no_j) : 1.0 - 0.5 * (no_i + no_j));
        if (c.on_segment.empty() || c.value < 1e-9) {
          w.sum += c.value;
          continue;
        }
        for (int id : c.on_segment) {
          auto& sp = spans[size_t(id)];
          if (std::find(sp.begin(), sp.end(), key) == sp.end()) sp.push_back(key);
        }
        w.cond.push_back(std::move(c));
      }
    }
  }

  // ------------------------------------------------------------ stars, hypothetical observations, posterior

  // The star polygon of observation i's real detections at the vertices' current positions; in an open region
  // the detections' labels say where sight passes a vertex (no wall on that side).
  core::Ring RealStar(const Obs& ob) const {
    std::vector<StarPoint> pts;
    for (size_t k = 0; k < ob.vid.size(); ++k)
      pts.push_back({Pos(ob.vid[k]), core::NoWallCcw(ob.det[k].labels) > 0.5, core::NoWallCw(ob.det[k].labels) > 0.5});
    if (!o.open_region) {
      for (auto& p : pts) p.open_ccw = p.open_cw = false;
      return OpenStarPolygon(ob.pose.position(), pts, OpenSpace{});
    }
    return OpenStarPolygon(ob.pose.position(), pts, OpenSpace{*o.open_region, o.max_range, o.open_sample_step, {}});
  }

  // Open worlds: obstacles are closed polygons, so a chain of map walls that is still open (its last wall not
  // seen well enough yet) is closed between its two ends for the sight lines of known space -- otherwise the
  // hypothetical observation would see through the building to the chain's far vertices.  Planning and the
  // posterior use the map's walls only.
  std::vector<std::pair<int, int>> ClosingWalls(const MapState& ms) const {
    std::vector<std::pair<int, int>> out;
    if (!o.open_region) return out;
    std::unordered_map<int, std::vector<int>> adj;
    for (const auto& w : ms.walls) {
      adj[w.first].push_back(w.second);
      adj[w.second].push_back(w.first);
    }
    std::unordered_set<int> seen;
    std::vector<int> ends;
    for (const auto& [start, nb] : adj) {
      if (nb.size() != 1 || seen.count(start)) continue;
      // Walk the chain from this end; it is a simple chain if every inner vertex has two walls.
      int prev = -1, cur = start, length = 0;
      bool simple = true;
      seen.insert(cur);
      while (true) {
        const auto& n = adj.at(cur);
        int next = -1;
        for (int x : n)
          if (x != prev) next = x;
        if (next < 0 || (prev >= 0 && n.size() != 2)) {
          simple = simple && n.size() <= 2;
          break;
        }
        if (n.size() > 2) {
          simple = false;
          break;
        }
        prev = cur;
        cur = next;
        ++length;
        seen.insert(cur);
        if (adj.at(cur).size() == 1) break;
      }
      if (simple && length >= 2 && adj.at(cur).size() == 1) out.push_back({std::min(start, cur), std::max(start, cur)});
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  // The star polygon of a hypothetical observation H: in an open region, sight passes a mapped vertex on a side
  // where the map has no wall, and rays stop at the map's walls (whose keys go to *hit_walls).
  core::Ring HypotheticalStar(const Obs& ob, const std::vector<int>& H, const MapState& ms,
                              const std::vector<std::pair<int, int>>& closing, std::vector<uint64_t>* hit_walls) const {
    const Vec2 c = ob.pose.position();
    hit_walls->clear();
    std::unordered_map<int, std::vector<int>> extra;
    for (const auto& w : closing) {
      extra[w.first].push_back(w.second);
      extra[w.second].push_back(w.first);
    }
    std::vector<StarPoint> pts;
    for (int id : H) {
      // Sight passes a map vertex on a side with no wall (map walls and closing walls).
      StarPoint sp{Pos(id), bool(o.open_region), bool(o.open_region)};
      std::vector<int> others;
      for (int j : neighbours[size_t(id)])
        if (ms.HasWall(id, j)) others.push_back(j);
      if (const auto it = extra.find(id); it != extra.end()) others.insert(others.end(), it->second.begin(), it->second.end());
      for (int j : others) {
        const double side = core::Cross(sp.p - c, Pos(j) - sp.p);
        if (side >= 0) sp.open_ccw = false;
        if (side <= 0) sp.open_cw = false;
      }
      pts.push_back(sp);
    }
    if (!o.open_region) return OpenStarPolygon(c, pts, OpenSpace{});
    OpenSpace space{*o.open_region, o.max_range, o.open_sample_step, {}};
    const core::Aabb2 reach{c - Vec2{o.max_range, o.max_range}, c + Vec2{o.max_range, o.max_range}};
    std::vector<uint64_t> keys;
    for (const auto* list : {&ms.walls, &closing})
      for (const auto& w : *list)
        if (BoxHitsSegment(reach, Pos(w.first), Pos(w.second), 0.0)) {
          space.blockers.push_back({Pos(w.first), Pos(w.second)});
          keys.push_back(WallKey(w.first, w.second) ^ (list == &closing ? (uint64_t(1) << 63) : 0));
        }
    std::vector<int> hit;
    core::Ring ring = OpenStarPolygon(c, pts, space, &hit);
    for (int k : hit) hit_walls->push_back(keys[size_t(k)]);
    // The polygon also depends on which sides of each vertex are open: part of what it was built from.
    for (const auto& p : pts) hit_walls->push_back((uint64_t(0xF) << 60) | (uint64_t(p.open_ccw) << 1) | uint64_t(p.open_cw));
    return ring;
  }

  void RefreshStar(size_t i) {
    Obs& ob = obs[i];
    std::vector<Vec2> pts;
    for (int id : ob.vid) pts.push_back(Pos(id));
    ob.star = RealStar(ob);
    ob.star_src = pts;
    ob.box = ob.star.empty() ? core::Aabb2{ob.pose.position(), ob.pose.position()} : core::Bounds(ob.star);
    ob.box = core::Bounds(std::vector<Vec2>{ob.pose.position()}, ob.box);
  }

  // Rebuilds star polygons whose vertices moved more than the tolerance.
  void RefreshStars(double tolerance) {
    for (size_t i = 0; i < obs.size(); ++i) {
      const Obs& ob = obs[i];
      bool moved = false;
      for (size_t k = 0; k < ob.vid.size() && !moved; ++k)
        moved = core::Distance(Pos(ob.vid[k]), ob.star_src[k]) > tolerance;
      if (moved) RefreshStar(i);
    }
  }

  std::vector<std::pair<int, int>> MappedWalls(const std::vector<char>& mapped) const {
    std::vector<std::pair<int, int>> out;
    for (const auto& [key, w] : walls) {
      const int a = int(key >> 32), b = int(key & 0xffffffffu);
      if (mapped[size_t(a)] && mapped[size_t(b)] && WallProb(a, b, mapped) > o.wall_threshold) out.push_back({a, b});
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  // The hypothetical observation of observation i (paper Sec. III-B; vertexnav.md §2.6): mapped vertices in
  // range, inside or on the real observation's star polygon, not hidden by a mapped wall; by bearing.  With
  // 'with_candidates' (known space only, never the posterior) also the vertices the observation itself
  // detected that have enough detections but are not in the map.
  std::vector<int> Hypothetical(const Obs& ob, const MapState& ms,
                                const std::vector<std::pair<int, int>>& extra_walls = {},
                                bool with_candidates = false) const {
    const Vec2 p = ob.pose.position();
    std::vector<std::pair<int, int>> near_walls;
    for (const auto* list : {&ms.walls, &extra_walls})
      for (const auto& w : *list)
        if (BoxHitsSegment(ob.box, Pos(w.first), Pos(w.second), 1e-6)) near_walls.push_back(w);
    std::vector<std::pair<double, int>> h;
    auto consider = [&](int id, bool on_star) {
      const Vec2 x = Pos(id);
      if (core::Distance(x, p) >= o.max_range) return;
      if (!on_star && !(BoxHits(ob.box, x, 1e-6) && (core::Contains(ob.star, x) || core::NearRing(x, ob.star, 1e-6))))
        return;
      const core::Aabb2 sight = core::SegmentBox(p, x);
      for (const auto& w : near_walls) {
        if (w.first == id || w.second == id) continue;
        const Vec2 a = Pos(w.first), b = Pos(w.second);
        if (BoxHitsSegment(sight, a, b) && core::SegmentsIntersect({p, x}, {a, b})) return;
      }
      h.push_back({std::atan2(x.y - p.y, x.x - p.x), id});
    };
    for (size_t k = 0; k < ob.vid.size(); ++k) {
      const int id = ob.vid[k];
      const bool candidate = with_candidates && v[size_t(id)].n >= o.min_detections;
      if ((ms.mapped[size_t(id)] || candidate) &&
          std::find(ob.vid.begin(), ob.vid.begin() + long(k), id) == ob.vid.begin() + long(k))
        consider(id, true);
    }
    if (!ob.star.empty() && star_cache) {
      // Within a Sample call: the potential map vertices this star polygon holds, found once.
      const size_t k = size_t(&ob - obs.data());
      TOPONAV_CHECK(k < star_members_ok.size(), "observation outside the star-membership cache");
      if (!star_members_ok[k]) {
        for (size_t id = 0; id < v.size(); ++id) {
          const Vec2 x = Pos(int(id));
          if (v[id].n >= o.min_detections && std::find(ob.vid.begin(), ob.vid.end(), int(id)) == ob.vid.end() &&
              BoxHits(ob.box, x, 1e-6) && (core::Contains(ob.star, x) || core::NearRing(x, ob.star, 1e-6)))
            star_members[k].push_back(int(id));
        }
        star_members_ok[k] = 1;
      }
      for (int id : star_members[k])
        if (ms.mapped[size_t(id)]) consider(id, true);
    } else if (!ob.star.empty()) {
      for (size_t id = 0; id < v.size(); ++id)
        if (ms.mapped[id] && std::find(ob.vid.begin(), ob.vid.end(), int(id)) == ob.vid.end()) consider(int(id), false);
    }
    std::sort(h.begin(), h.end());
    std::vector<int> out;
    for (const auto& e : h) out.push_back(e.second);
    return out;
  }

  // log P(z_i | m): false positives and negatives against the hypothetical observation, a truncated
  // position term for matches, and edge terms along consecutive hypothetical vertices (Sec. III-C).
  double ObservationLogLikelihood(const Obs& ob, const MapState& ms) const {
    const std::vector<int> H = Hypothetical(ob, ms);
    const double log_fp = std::log(o.false_positive_rate), log_fn = std::log(o.false_negative_rate);
    std::vector<int> det_of(H.size(), -1);
    int fp = 0, matched = 0;
    double ll = 0.0;
    for (size_t k = 0; k < ob.det.size(); ++k) {
      const auto it = std::find(H.begin(), H.end(), ob.vid[k]);
      const size_t slot = size_t(it - H.begin());
      if (it == H.end() || det_of[slot] >= 0) {
        ++fp;
        continue;
      }
      det_of[slot] = int(k);
      ++matched;
      const Vec2& z = ob.at[k];
      const Eigen::Vector2d e(z.x - v[size_t(ob.vid[k])].x.x(), z.y - v[size_t(ob.vid[k])].x.y());
      ll += std::max(-0.5 * e.dot(ob.cov[k].solve(e)), log_fp);
    }
    ll += fp * log_fp + (int(H.size()) - matched) * log_fn;
    if (H.size() >= 2) {
      const Vec2 p = ob.pose.position();
      const double floor = o.edge_log_floor;
      for (size_t j = 0; j < H.size(); ++j) {
        const size_t l = (j + 1) % H.size();
        const Vec2 a = Pos(H[j]), b = Pos(H[l]);
        const double gap = Wrap2Pi(std::atan2(b.y - p.y, b.x - p.x) - std::atan2(a.y - p.y, a.x - p.x));
        if (gap >= core::kPi || H[j] == H[l]) continue;
        const double no_ccw = det_of[j] >= 0 ? core::NoWallCcw(ob.det[size_t(det_of[j])].labels) : 0.5;
        const double no_cw = det_of[l] >= 0 ? core::NoWallCw(ob.det[size_t(det_of[l])].labels) : 0.5;
        const double q = 1.0 - 0.5 * (no_ccw + no_cw);
        const double a_wall = ms.HasWall(H[j], H[l]) ? 1.0 : 0.0;
        ll += std::max(std::log(std::max(1.0 - std::abs(q - a_wall), 1e-300)), floor);
      }
    }
    return ll;
  }

  double LogPrior(const MapState& ms) const {
    return ms.num_vertices * o.vertex_log_prior + double(ms.walls.size()) * o.wall_log_prior;
  }

  double LogPosterior() const {
    const MapState ms = LiveState();
    double lp = LogPrior(ms);
    for (const auto& ob : obs) lp += ObservationLogLikelihood(ob, ms);
    return lp;
  }

  // True if the segment a-b meets the observation's star polygon (inside or crossing its boundary).
  static bool StarMeets(const Obs& ob, const Vec2& a, const Vec2& b) {
    if (ob.star.empty() || !BoxHitsSegment(ob.box, a, b, 1e-6)) return false;
    if (core::Contains(ob.star, a) || core::Contains(ob.star, b)) return true;
    // The same boundary tolerance as Hypothetical(): a vertex on the polygon counts as inside.
    if (core::NearRing(a, ob.star, 1e-6) || core::NearRing(b, ob.star, 1e-6)) return true;
    for (size_t i = 0; i < ob.star.size(); ++i)
      if (core::SegmentsIntersect({a, b}, {ob.star[i], ob.star[(i + 1) % ob.star.size()]})) return true;
    return false;
  }

  // Observations whose likelihood can change when vertex i flips: their star polygon meets the vertex or a
  // wall that comes or goes with it (sight lines and hypothetical vertices all lie inside the star polygon).
  std::vector<int> Affected(int i, const MapState& ms) const {
    std::vector<int> out;
    const Vec2 x = Pos(i);
    std::vector<std::pair<int, int>> walls = ChangedWalls(i, ms);
    for (size_t k = 0; k < obs.size(); ++k) {
      const Obs& ob = obs[k];
      bool hit = std::find(ob.vid.begin(), ob.vid.end(), i) != ob.vid.end() || StarMeets(ob, x, x);
      for (size_t m = 0; m < walls.size() && !hit; ++m) hit = StarMeets(ob, Pos(walls[m].first), Pos(walls[m].second));
      if (hit) out.push_back(int(k));
    }
    return out;
  }

  double Sample(core::Rng& rng, int samples) {
    RefreshStars(o.star_rebuild_tolerance);
    // Positions and star polygons stay put until the call returns: cache which vertices each star holds.
    struct CacheOff {
      bool& on;
      ~CacheOff() { on = false; }
    } cache_off{star_cache};
    star_cache = true;
    star_members.assign(obs.size(), {});
    star_members_ok.assign(obs.size(), 0);
    // Candidates: vertices with enough detections seen in the recent window of observations.
    std::vector<int> cand;
    {
      std::vector<char> recent(v.size(), 0);
      const size_t first = obs.size() > size_t(o.mcmc_window) ? obs.size() - size_t(o.mcmc_window) : 0;
      for (size_t k = first; k < obs.size(); ++k)
        for (int id : obs[k].vid) recent[size_t(id)] = 1;
      for (size_t i = 0; i < v.size(); ++i)
        if (recent[i] && v[i].n >= o.min_detections) cand.push_back(int(i));
    }
    MapState ms = LiveState();
    std::vector<double> ll(obs.size(), std::numeric_limits<double>::quiet_NaN());
    stats.last_mcmc_accepted = 0;
    stats.last_mcmc_evaluated_observations = 0;
    auto cached_ll = [&](int k) {
      if (std::isnan(ll[size_t(k)])) ll[size_t(k)] = ObservationLogLikelihood(obs[size_t(k)], ms);
      return ll[size_t(k)];
    };
    std::vector<char> best_state(v.size());
    for (size_t i = 0; i < v.size(); ++i) best_state[i] = v[i].in_map;
    double delta_total = 0, best_delta = 0;  // relative to the starting state
    // Random-order systematic scan: every candidate is proposed once per pass (in a fresh random order), so a
    // vertex that just gathered enough detections is considered at the next call, whatever the window size.
    std::vector<int> order;
    for (int s = 0; s < samples && !cand.empty(); ++s) {
      if (order.empty()) {
        order = cand;
        rng.Shuffle(order);
      }
      const int i = order.back();
      order.pop_back();
      const bool on = !ms.mapped[size_t(i)];
      const std::vector<int> affected = Affected(i, ms);
      double delta = -LogPrior(ms);
      std::vector<double> old_ll(affected.size());
      for (size_t a = 0; a < affected.size(); ++a) old_ll[a] = cached_ll(affected[a]);
      SetMapped(i, on, &ms);
      delta += LogPrior(ms);
      std::vector<double> new_ll(affected.size());
      for (size_t a = 0; a < affected.size(); ++a) {
        new_ll[a] = ObservationLogLikelihood(obs[size_t(affected[a])], ms);
        delta += new_ll[a] - old_ll[a];
      }
      stats.last_mcmc_evaluated_observations += int(affected.size());
      if (delta >= 0 || std::log(rng.Uniform()) < delta) {  // Metropolis (symmetric proposal)
        v[size_t(i)].in_map = on;
        delta_total += delta;
        for (size_t a = 0; a < affected.size(); ++a) ll[size_t(affected[a])] = new_ll[a];
        ++stats.last_mcmc_accepted;
        if (delta_total > best_delta) {
          best_delta = delta_total;
          for (size_t k = 0; k < v.size(); ++k) best_state[k] = v[k].in_map;
        }
      } else {
        SetMapped(i, !on, &ms);
      }
    }
    for (size_t k = 0; k < v.size(); ++k) v[k].in_map = best_state[k];
    FreezeViewMap();
    return best_delta;  // (the full posterior would cost a hypothetical observation per past observation)
  }

  // ------------------------------------------------------------ known space and frontiers

  // The map view, its known space rebuilt around vertices that drifted farther than 'tolerance'.
  MapView MakeView(double tolerance);

  // Known space, incrementally (paper Eq. 2, S_c = union of s(z_i) & s(z_h,i)).  An observation's S_c is
  // recomputed only when what its hypothetical observation is built from changes: vertices or walls entering
  // or leaving the map (at MCMC calls), a vertex becoming a seen candidate (known_space_candidates), or one
  // of these drifting farther than 'tolerance' (star_rebuild_tolerance; 0 for an exact view) by Kalman
  // updates.  An S_c that grew (or is new) is joined into the union directly; one that shrank forces the
  // union to be rebuilt from the cached per-block unions.
  void UpdateKnownSpace(double tolerance) const {
    const MapState& ms = ViewMap();
    const std::vector<std::pair<int, int>> closing = ClosingWalls(ms);
    std::vector<std::pair<int, int>> mw = ms.walls;  // what sight lines stop at
    mw.insert(mw.end(), closing.begin(), closing.end());
    std::sort(mw.begin(), mw.end());
    mw.erase(std::unique(mw.begin(), mw.end()), mw.end());
    // What changed since the last update: vertices that entered or left the hypothetical observations (the
    // map, and with candidates the seen candidates) or drifted farther than the tolerance since they were
    // last flagged, and walls that entered or left the map.
    // A map vertex is in the hypothetical observation of every observation that sees it; a candidate only in
    // those of the observations that detected it, so its changes send only those back.
    const bool with_candidates = o.known_space_candidates && !o.open_region;
    std::vector<int> changed_vertices, changed_candidates;  // (ascending)
    snap_mapped.resize(v.size(), 0);
    snap_member.resize(v.size(), 0);
    drift_ref.resize(v.size(), Vec2{std::numeric_limits<double>::quiet_NaN(), 0});
    for (size_t i = 0; i < v.size(); ++i) {
      const bool drifted = std::isnan(drift_ref[i].x) || core::Distance(drift_ref[i], Pos(int(i))) > tolerance;
      if (drifted) drift_ref[i] = Pos(int(i));
      const bool mapped = ms.mapped[i];
      const bool member = mapped || (with_candidates && v[i].n >= o.min_detections);
      if (mapped != bool(snap_mapped[i]) || (drifted && mapped))
        changed_vertices.push_back(int(i));
      else if (member != bool(snap_member[i]) || (drifted && member))
        changed_candidates.push_back(int(i));
      snap_mapped[i] = mapped;
      snap_member[i] = member;
    }
    std::vector<std::pair<int, int>> changed_walls;
    std::set_symmetric_difference(mw.begin(), mw.end(), snap_walls.begin(), snap_walls.end(),
                                  std::back_inserter(changed_walls));
    snap_walls = mw;
    bool rebuild = false;
    std::vector<const PolygonSet*> grown;  // new pieces that only add to the known space
    for (size_t i = 0; i < obs.size(); ++i) {
      Obs& ob = const_cast<Obs&>(obs[i]);
      bool check = !ob.sc_valid;
      for (size_t k = 0; k < changed_vertices.size() && !check; ++k)
        check = BoxHits(ob.box, Pos(changed_vertices[k]), 1e-6);
      for (size_t k = 0; k < changed_walls.size() && !check; ++k)
        check = BoxHitsSegment(ob.box, Pos(changed_walls[k].first), Pos(changed_walls[k].second), 1e-6);
      for (size_t k = 0; k < ob.vid.size() && !check && !changed_candidates.empty(); ++k)
        check = std::binary_search(changed_candidates.begin(), changed_candidates.end(), ob.vid[k]);
      if (!check) continue;
      const std::vector<int> H = Hypothetical(ob, ms, closing, with_candidates);
      bool moved = false;  // a vertex of this S_c got a new known-space position
      for (int id : ob.sc_ids)
        moved = moved || std::binary_search(changed_vertices.begin(), changed_vertices.end(), id) ||
                std::binary_search(changed_candidates.begin(), changed_candidates.end(), id);
      std::vector<uint64_t> hit_walls;
      const core::Ring sh = HypotheticalStar(ob, H, ms, closing, &hit_walls);
      if (ob.sc_valid && ob.sc_ids == H && ob.sc_walls == hit_walls && !moved) continue;
      const core::Ring sz = RealStar(ob);
      PolygonSet sc;
      if (!sh.empty() && !sz.empty()) {
        try {
          sc = PolygonSet::FromRing(sz);
          sc.Intersect(PolygonSet::FromRing(sh));
        } catch (const core::DataError&) {
          sc = PolygonSet();  // a degenerate polygon adds nothing (the conservative choice)
        }
      }
      bool grew = true;  // a new S_c, or one that contains the old one: joining it is enough
      if (ob.sc_valid && !ob.sc.empty()) {
        ob.sc.Difference(sc);  // what the old one loses (it is replaced below)
        grew = ob.sc.empty();
      }
      if (grew && total_valid) {
        if (!sc.empty()) grown.push_back(&ob.sc);  // (obs does not reallocate during the update)
      } else {
        rebuild = true;
      }
      ob.sc = std::move(sc);
      ob.sc_ids = H;
      ob.sc_walls = std::move(hit_walls);
      ob.sc_valid = true;
      block_dirty[i / size_t(o.union_block)] = 1;
    }
    if (!rebuild && total_valid) {
      if (!grown.empty()) total.Join(PolygonSet::JoinAll(grown));  // the small pieces first, then one join with the big union
      return;
    }
    // Blocks are the leaves of a binary tree whose inner nodes cache the union of their subtree: a rebuild
    // redoes the dirty blocks and the nodes above them only.
    size_t leaves = 1;
    while (leaves < blocks.size()) leaves *= 2;
    if (union_tree.size() != 2 * leaves) {  // more blocks than leaves: a bigger tree, every node redone
      union_tree.assign(2 * leaves, PolygonSet());
      tree_dirty.assign(2 * leaves, 1);
      for (size_t b = 0; b < blocks.size(); ++b) union_tree[leaves + b] = blocks[b];
    }
    for (size_t b = 0; b < blocks.size(); ++b) {
      if (!block_dirty[b]) continue;
      std::vector<const PolygonSet*> members;
      for (size_t i = b * size_t(o.union_block); i < std::min(obs.size(), (b + 1) * size_t(o.union_block)); ++i)
        members.push_back(&obs[i].sc);
      blocks[b] = PolygonSet::JoinAll(members);
      block_dirty[b] = 0;
      union_tree[leaves + b] = blocks[b];
      for (size_t node = (leaves + b) / 2; node >= 1; node /= 2) tree_dirty[node] = 1;
    }
    for (size_t node = leaves - 1; node >= 1; --node) {
      if (!tree_dirty[node]) continue;
      union_tree[node] = union_tree[2 * node];
      if (!union_tree[2 * node + 1].empty()) union_tree[node].Join(union_tree[2 * node + 1]);
      tree_dirty[node] = 0;
    }
    total = union_tree[1];
    total_valid = true;
  }

  std::vector<Frontier> Frontiers(const std::vector<core::Polygon>& known) const {
    const auto& mw = ViewMap().walls;
    auto on_wall = [&](const Vec2& a, const Vec2& b) {
      for (const auto& w : mw) {
        const core::Segment2 s{Pos(w.first), Pos(w.second)};
        if (core::DistanceToSegment(a, s) <= o.frontier_wall_tolerance &&
            core::DistanceToSegment(b, s) <= o.frontier_wall_tolerance)
          return true;
      }
      return false;
    };
    // The open region's edge is where the search ends, not where unknown space begins.
    auto on_region_edge = [&](const Vec2& a, const Vec2& b) {
      if (!o.open_region) return false;
      const auto& r = *o.open_region;
      constexpr double tol = 1e-3;
      return (std::abs(a.x - r.min.x) < tol && std::abs(b.x - r.min.x) < tol) ||
             (std::abs(a.x - r.max.x) < tol && std::abs(b.x - r.max.x) < tol) ||
             (std::abs(a.y - r.min.y) < tol && std::abs(b.y - r.min.y) < tol) ||
             (std::abs(a.y - r.max.y) < tol && std::abs(b.y - r.max.y) < tol);
    };
    // ... and so is open ground far from every vertex with enough detections.
    std::vector<Vec2> structure;
    if (o.open_region && o.open_frontier_reach > 0)
      for (size_t i = 0; i < v.size(); ++i)
        if (v[i].n >= o.min_detections) structure.push_back(Pos(int(i)));
    auto far_from_structure = [&](const Vec2& a, const Vec2& b) {
      if (structure.empty()) return false;  // nothing found yet: all of the boundary is frontier
      const core::Aabb2 box = core::SegmentBox(a, b);
      for (const Vec2& p : structure)
        if (core::BoxHits(box, p, o.open_frontier_reach) && core::DistanceToSegment(p, {a, b}) <= o.open_frontier_reach)
          return false;
      return true;
    };
    std::vector<Frontier> out;
    auto walk = [&](const core::Ring& ring) {
      const size_t n = ring.size();
      std::vector<char> free_edge(n);
      for (size_t i = 0; i < n; ++i)
        free_edge[i] = !on_wall(ring[i], ring[(i + 1) % n]) && !on_region_edge(ring[i], ring[(i + 1) % n]) &&
                       !far_from_structure(ring[i], ring[(i + 1) % n]);
      // Start at a wall edge so chains do not wrap (a ring with no wall is one closed frontier).
      size_t start = 0;
      while (start < n && free_edge[start]) ++start;
      const bool all_free = start == n;
      if (all_free) start = 0;
      Frontier cur;
      for (size_t k = 0; k < n; ++k) {
        const size_t i = (start + k) % n;
        if (free_edge[i]) {
          if (cur.points.empty()) cur.points.push_back(ring[i]);
          cur.points.push_back(ring[(i + 1) % n]);
        } else if (!cur.points.empty()) {
          out.push_back(cur);
          cur = Frontier();
        }
      }
      if (!cur.points.empty()) out.push_back(cur);
    };
    for (const auto& p : known) {
      walk(p.outer);
      for (const auto& h : p.holes) walk(h);
    }
    // A chain that turns sharply (two chords meeting at a corner of the walls, one across a doorway, one
    // across a corridor) is two frontiers: one target at the chain's middle would sit in the corner, where
    // neither opening shows.  (Not in open worlds: there the boundary bends around every building's shadow,
    // and the extra pieces left single agents zigzagging between them.)
    if (o.frontier_split_angle > 0 && !o.open_region) {
      std::vector<Frontier> split;
      for (const auto& f : out) {
        const bool ring = f.points.size() > 3 && f.points.front() == f.points.back();
        const auto pieces = SplitAtTurns(f.points, o.frontier_split_angle, o.frontier_split_min_length);
        auto chord = [&](size_t k) { return pieces[k].back() - pieces[k].front(); };
        auto turn = [&](size_t k0, size_t k1) {  // from piece k0 into piece k1
          const Vec2 d0 = chord(k0), d1 = chord(k1);
          return std::max(1e-9, std::abs(std::atan2(core::Cross(d0, d1), core::Dot(d0, d1))));
        };
        const size_t m = pieces.size();
        for (size_t k = 0; k < m; ++k) {
          Frontier piece;
          if (k > 0 || (ring && m > 1)) piece.front_turn = turn((k + m - 1) % m, k);
          if (k + 1 < m || (ring && m > 1)) piece.back_turn = turn(k, (k + 1) % m);
          if (ring && m == 1) piece.front_turn = piece.back_turn = core::kPi;  // a whole ring has no ends
          piece.points = pieces[k];
          split.push_back(std::move(piece));
        }
      }
      out = std::move(split);
    }
    for (auto& f : out) {
      for (size_t i = 1; i < f.points.size(); ++i) f.length += core::Distance(f.points[i - 1], f.points[i]);
      double half = f.length / 2, acc = 0;
      f.midpoint = f.points.front();
      for (size_t i = 1; i < f.points.size(); ++i) {
        const double d = core::Distance(f.points[i - 1], f.points[i]);
        if (acc + d >= half) {
          f.midpoint = f.points[i - 1] + (f.points[i] - f.points[i - 1]) * ((half - acc) / std::max(d, 1e-12));
          break;
        }
        acc += d;
      }
    }
    // Stable identities: a frontier keeps the id of the previous one whose midpoint is nearest, if close.
    std::vector<char> taken(last_frontiers.size());
    for (auto& f : out) {
      int best = -1;
      double best_d = std::max(2.0, 0.5 * f.length);
      for (size_t j = 0; j < last_frontiers.size(); ++j) {
        const double d = core::Distance(f.midpoint, last_frontiers[j].midpoint);
        if (!taken[j] && d < best_d) {
          best_d = d;
          best = int(j);
        }
      }
      if (best >= 0) {
        taken[size_t(best)] = 1;
        f.id = last_frontiers[size_t(best)].id;
      } else {
        f.id = next_frontier_id++;
      }
    }
    last_frontiers = out;
    return out;
  }
};

Mapper::Mapper(const MapperOptions& options) : impl_(std::make_unique<Impl>()) {
  options.Validate();
  impl_->o = options;
}
Mapper::~Mapper() = default;

void Mapper::AddObservation(const core::Observation& z) { impl_->Add(z); }
double Mapper::SampleMostLikelyMap(core::Rng& rng, int samples) {
  return impl_->Sample(rng, samples < 0 ? impl_->o.mcmc_samples : samples);
}
double Mapper::LogPosterior() const { return impl_->LogPosterior(); }
const MapperOptions& Mapper::options() const { return impl_->o; }

std::vector<MapVertex> Mapper::PotentialVertices() const {
  std::vector<MapVertex> out;
  for (size_t i = 0; i < impl_->v.size(); ++i) {
    const auto& x = impl_->v[i];
    out.push_back({int(i), ToVec(x.x), FromEigen(x.P), x.n});
  }
  return out;
}

MapperStats Mapper::Stats() const {
  MapperStats s = impl_->stats;
  s.num_potential_vertices = int(impl_->v.size());
  s.num_walls_with_evidence = int(impl_->walls.size());
  return s;
}

MapView Mapper::View() const { return impl_->MakeView(impl_->o.star_rebuild_tolerance); }
MapView Mapper::ExactView() const { return impl_->MakeView(0.0); }

MapView Mapper::Impl::MakeView(double tolerance) {
  Impl& m = *this;
  m.RefreshStars(tolerance);
  m.UpdateKnownSpace(tolerance);
  MapView view;
  const Impl::MapState& ms = m.ViewMap();
  for (size_t i = 0; i < m.v.size(); ++i) {
    if (m.v[i].n < m.o.min_detections) continue;
    const MapVertex mv{int(i), ToVec(m.v[i].x), FromEigen(m.v[i].P), m.v[i].n};
    (ms.mapped[i] ? view.vertices : view.rejected).push_back(mv);
  }
  for (const auto& [a, b] : ms.walls) view.walls.push_back({a, b, m.Pos(a), m.Pos(b), m.WallProb(a, b, ms.mapped)});
  view.known_space = m.total.Polygons();
  view.known_set = std::make_shared<const PolygonSet>(m.total);
  view.frontiers = m.Frontiers(view.known_space);
  view.num_observations = int(m.obs.size());
  return view;
}

}  // namespace toponav::mapping

#include "mapping/internal/posterior.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace toponav::mapping::internal {

using core::BoxHits;
using core::BoxHitsSegment;
using core::Vec2;

namespace {

bool InStar(const Obs& ob, const Vec2& x) {
  return BoxHits(ob.box, x, 1e-6) && (core::Contains(ob.star, x) || core::NearRing(x, ob.star, 1e-6));
}

bool Detected(const Obs& ob, int id) { return std::find(ob.vid.begin(), ob.vid.end(), id) != ob.vid.end(); }

// True if the segment a-b meets the observation's star polygon (inside or crossing its boundary).
bool StarMeets(const Obs& ob, const Vec2& a, const Vec2& b) {
  if (ob.star.empty() || !BoxHitsSegment(ob.box, a, b, 1e-6)) return false;
  if (core::Contains(ob.star, a) || core::Contains(ob.star, b)) return true;
  // The same boundary tolerance as Hypothetical(): a vertex on the polygon counts as inside.
  if (core::NearRing(a, ob.star, 1e-6) || core::NearRing(b, ob.star, 1e-6)) return true;
  for (size_t i = 0; i < ob.star.size(); ++i)
    if (core::SegmentsIntersect({a, b}, {ob.star[i], ob.star[(i + 1) % ob.star.size()]})) return true;
  return false;
}

}  // namespace

const std::vector<int>& StarMembers::Of(const MapCore& m, size_t k) {
  TOPONAV_CHECK(k < ok_.size(), "observation outside the star-membership cache");
  if (!ok_[k]) {
    const Obs& ob = m.obs[k];
    for (size_t id = 0; id < m.vertices.size(); ++id)
      if (m.vertices.Seen(int(id)) && !Detected(ob, int(id)) && InStar(ob, m.Pos(int(id))))
        members_[k].push_back(int(id));
    ok_[k] = 1;
  }
  return members_[k];
}

std::vector<int> Hypothetical(const MapCore& m, size_t k, const MapState& ms, const std::vector<Wall>& extra_walls,
                              bool with_candidates, StarMembers* cache) {
  const Obs& ob = m.obs[k];
  const Vec2 p = ob.pose.position();
  std::vector<Wall> near_walls;
  for (const auto* list : {&ms.walls, &extra_walls})
    for (const auto& w : *list)
      if (BoxHitsSegment(ob.box, m.Pos(w.first), m.Pos(w.second), 1e-6)) near_walls.push_back(w);
  std::vector<std::pair<double, int>> h;
  auto consider = [&](int id, bool on_star) {
    const Vec2 x = m.Pos(id);
    if (core::Distance(x, p) >= m.o.max_range) return;
    if (!on_star && !InStar(ob, x)) return;
    const core::Aabb2 sight = core::SegmentBox(p, x);
    for (const auto& w : near_walls) {
      if (w.first == id || w.second == id) continue;
      const Vec2 a = m.Pos(w.first), b = m.Pos(w.second);
      if (BoxHitsSegment(sight, a, b) && core::SegmentsIntersect({p, x}, {a, b})) return;
    }
    h.push_back({std::atan2(x.y - p.y, x.x - p.x), id});
  };
  for (size_t j = 0; j < ob.vid.size(); ++j) {
    const int id = ob.vid[j];
    const bool candidate = with_candidates && m.vertices.Seen(id);
    if ((ms.mapped[size_t(id)] || candidate) &&
        std::find(ob.vid.begin(), ob.vid.begin() + long(j), id) == ob.vid.begin() + long(j))
      consider(id, true);
  }
  if (!ob.star.empty() && cache) {
    for (int id : cache->Of(m, k))
      if (ms.mapped[size_t(id)]) consider(id, true);
  } else if (!ob.star.empty()) {
    for (size_t id = 0; id < m.vertices.size(); ++id)
      if (ms.mapped[id] && !Detected(ob, int(id))) consider(int(id), false);
  }
  std::sort(h.begin(), h.end());
  std::vector<int> out;
  for (const auto& e : h) out.push_back(e.second);
  return out;
}

double ObservationLogLikelihood(const MapCore& m, size_t k, const MapState& ms, StarMembers* cache) {
  const Obs& ob = m.obs[k];
  const std::vector<int> H = Hypothetical(m, k, ms, {}, false, cache);
  const double log_fp = std::log(m.o.false_positive_rate), log_fn = std::log(m.o.false_negative_rate);
  std::vector<int> det_of(H.size(), -1);
  int fp = 0, matched = 0;
  double ll = 0.0;
  for (size_t d = 0; d < ob.det.size(); ++d) {
    const auto it = std::find(H.begin(), H.end(), ob.vid[d]);
    const size_t slot = size_t(it - H.begin());
    if (it == H.end() || det_of[slot] >= 0) {
      ++fp;
      continue;
    }
    det_of[slot] = int(d);
    ++matched;
    const Vec2& z = ob.at[d];
    const Eigen::Vector2d& x = m.vertices[size_t(ob.vid[d])].x;
    const Eigen::Vector2d e(z.x - x.x(), z.y - x.y());
    ll += std::max(-0.5 * e.dot(ob.cov[d].solve(e)), log_fp);
  }
  ll += fp * log_fp + (int(H.size()) - matched) * log_fn;
  if (H.size() < 2) return ll;
  const Vec2 p = ob.pose.position();
  for (size_t j = 0; j < H.size(); ++j) {
    const size_t l = (j + 1) % H.size();
    const Vec2 a = m.Pos(H[j]), b = m.Pos(H[l]);
    const double gap = Wrap2Pi(std::atan2(b.y - p.y, b.x - p.x) - std::atan2(a.y - p.y, a.x - p.x));
    if (gap >= core::kPi || H[j] == H[l] || gap < m.o.wall_min_view_angle) continue;
    const double no_ccw = det_of[j] >= 0 ? core::NoWallCcw(ob.det[size_t(det_of[j])].labels) : 0.5;
    const double no_cw = det_of[l] >= 0 ? core::NoWallCw(ob.det[size_t(det_of[l])].labels) : 0.5;
    const double q = 1.0 - 0.5 * (no_ccw + no_cw);
    const double a_wall = ms.HasWall(H[j], H[l]) ? 1.0 : 0.0;
    ll += std::max(std::log(std::max(1.0 - std::abs(q - a_wall), 1e-300)), m.o.edge_log_floor);
  }
  return ll;
}

double LogPrior(const MapperOptions& o, const MapState& ms) {
  return ms.num_vertices * o.vertex_log_prior + double(ms.walls.size()) * o.wall_log_prior;
}

double LogPosterior(const MapCore& m, const MapState& ms) {
  double lp = LogPrior(m.o, ms);
  for (size_t k = 0; k < m.obs.size(); ++k) lp += ObservationLogLikelihood(m, k, ms);
  return lp;
}

std::vector<int> Affected(const MapCore& m, int i, const MapState& ms) {
  std::vector<int> out;
  const Vec2 x = m.Pos(i);
  const std::vector<Wall> walls = m.walls.ChangedWalls(i, ms);
  for (size_t k = 0; k < m.obs.size(); ++k) {
    const Obs& ob = m.obs[k];
    bool hit = Detected(ob, i) || StarMeets(ob, x, x);
    for (size_t w = 0; w < walls.size() && !hit; ++w)
      hit = StarMeets(ob, m.Pos(walls[w].first), m.Pos(walls[w].second));
    if (hit) out.push_back(int(k));
  }
  return out;
}

}  // namespace toponav::mapping::internal

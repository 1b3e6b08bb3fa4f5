#include "planning/internal/given_up_frontiers.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace toponav::planning {

using core::Vec2;

namespace {

bool Near(const std::vector<core::Segment2>& edges, const Vec2& p, double reach) {
  for (const auto& e : edges)
    if (core::DistanceToSegment(p, e) < reach) return true;
  return false;
}

// Middle and both ends near: a longer frontier reaching past (an opening beside the unmapped wall piece) is not.
bool LiesOn(const std::vector<core::Segment2>& edges, const mapping::Frontier& f, double reach) {
  return !f.points.empty() && Near(edges, f.midpoint, reach) && Near(edges, f.points.front(), reach) &&
         Near(edges, f.points.back(), reach);
}

std::vector<core::Segment2> Edges(const std::vector<Vec2>& polyline) {
  std::vector<core::Segment2> out;
  for (size_t i = 1; i < polyline.size(); ++i) out.push_back({polyline[i - 1], polyline[i]});
  return out;
}

// The part of segment ab within 'radius' of c (false if none).
bool ClipToDisc(const Vec2& a, const Vec2& b, const Vec2& c, double radius, core::Segment2* out) {
  const Vec2 d = b - a;
  const double dd = core::Dot(d, d);
  if (dd < 1e-18) {
    *out = {a, b};
    return core::Distance(a, c) <= radius;
  }
  // |a + t d - c|^2 = radius^2
  const Vec2 f = a - c;
  const double bq = 2 * core::Dot(f, d), cq = core::Dot(f, f) - radius * radius;
  const double disc = bq * bq - 4 * dd * cq;
  if (disc < 0) return false;
  const double t0 = std::max(0.0, (-bq - std::sqrt(disc)) / (2 * dd));
  const double t1 = std::min(1.0, (-bq + std::sqrt(disc)) / (2 * dd));
  if (t0 > t1) return false;
  *out = {a + d * t0, a + d * t1};
  return true;
}

// The longest run of 'f' whose sample points (every 'spacing' along it) lie 'reach' or more from 'edges', as arc
// lengths [s0, s1]; s1 <= s0 when there is none.
std::pair<double, double> LongestClearRun(const mapping::Frontier& f, const std::vector<core::Segment2>& edges,
                                          double reach, double spacing) {
  const double length = core::PolylineLength(f.points);
  const int n = std::max(1, int(std::ceil(length / spacing)));
  std::pair<double, double> best{0, -1};
  double start = -1;
  for (int k = 0; k <= n + 1; ++k) {
    const double s = std::min(length, k * length / n);
    const bool clear = k <= n && !Near(edges, core::PointAlong(f.points, s), reach);
    if (clear && start < 0) start = s;
    if (!clear && start >= 0) {
      const double end = std::min(length, (k - 1) * length / n);
      if (end - start > best.second - best.first) best = {start, end};
      start = -1;
    }
  }
  return best;
}

}  // namespace

std::vector<mapping::Frontier> GivenUpFrontiers::Unprobed(const std::vector<mapping::Frontier>& frontiers) const {
  std::vector<mapping::Frontier> out;
  for (const auto& f : frontiers) {
    if (f.points.size() < 2 || edges_.empty()) {
      out.push_back(f);
      continue;
    }
    const double length = core::PolylineLength(f.points);
    const auto [s0, s1] = LongestClearRun(f, edges_, reach_, kUnprobedSpacing);
    if (s1 - s0 >= length - 1e-9) {
      out.push_back(f);  // nothing probed near it
    } else if (s1 > s0) {
      mapping::Frontier piece = f;
      piece.points = core::SubPolyline(f.points, s0, s1);
      piece.length = s1 - s0;
      piece.midpoint = core::PointAlong(f.points, 0.5 * (s0 + s1));
      if (s0 > 0) piece.front_turn = 0.0;  // a cut end is bounded (by the probed part, a wall to the planners)
      if (s1 < length) piece.back_turn = 0.0;
      out.push_back(std::move(piece));
    }
  }
  return out;
}

void GivenUpFrontiers::AddPieces(const mapping::Frontier& f, const Vec2* probed_at) {
  for (const auto& e : Edges(f.points)) {
    core::Segment2 piece = e;
    if (!probed_at || probe_radius_ <= 0 || ClipToDisc(e.a, e.b, *probed_at, probe_radius_, &piece))
      edges_.push_back(piece);
  }
}

void GivenUpFrontiers::GiveUp(int id, const std::vector<mapping::Frontier>& frontiers, const Vec2* probed_at) {
  const bool fresh = ids_.insert(id).second;
  given_up_ += fresh;
  for (const auto& f : frontiers) {
    if (f.id != id) continue;
    if (fresh) extent_[id] = Edges(f.points);
    AddPieces(f, probed_at);
  }
}

std::vector<int> GivenUpFrontiers::Update(const std::vector<mapping::Frontier>& frontiers) {
  std::vector<int> back;
  if (reach_ <= 0) return back;
  for (const auto& f : frontiers) {
    if (Contains(f.id)) {
      const auto it = extent_.find(f.id);
      // Well past (the boundary of known space wobbles by a few units as the map changes), and once.
      if (it != extent_.end() && !it->second.empty() && !LiesOn(it->second, f, kRegrowth * reach_) &&
          taken_back_.insert(f.id).second) {
        ids_.erase(f.id);
        extent_.erase(it);
        back.push_back(f.id);
      }
    } else if (LiesOn(edges_, f, reach_)) {
      ids_.insert(f.id);
      extent_[f.id] = Edges(f.points);
    }
  }
  return back;
}

}  // namespace toponav::planning

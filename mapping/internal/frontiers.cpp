#include "mapping/internal/frontiers.h"

#include <algorithm>
#include <cmath>

namespace toponav::mapping {

using core::Vec2;

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

}  // namespace toponav::mapping

namespace toponav::mapping::internal {

using core::Vec2;

namespace {

// Which edges of the known-space boundary are frontier (open to unknown space).
class BoundaryRules {
 public:
  BoundaryRules(const MapCore& m, const MapState& ms) : m_(m), ms_(ms) {
    // Open worlds: open ground far from every vertex with enough detections is no frontier.
    if (m.o.open_region && m.o.open_frontier_reach > 0)
      for (size_t i = 0; i < m.vertices.size(); ++i)
        if (m.vertices.Seen(int(i))) structure_.push_back(m.Pos(int(i)));
  }
  bool Frontier(const Vec2& a, const Vec2& b) const {
    return !OnWall(a, b) && !OnRegionEdge(a, b) && !FarFromStructure(a, b);
  }

 private:
  bool OnWall(const Vec2& a, const Vec2& b) const {
    const double tol = m_.o.frontier_wall_tolerance;
    for (const auto& w : ms_.walls) {
      const core::Segment2 s{m_.Pos(w.first), m_.Pos(w.second)};
      if (core::DistanceToSegment(a, s) <= tol && core::DistanceToSegment(b, s) <= tol) return true;
    }
    return false;
  }
  // The open region's edge is where the search ends, not where unknown space begins.
  bool OnRegionEdge(const Vec2& a, const Vec2& b) const {
    if (!m_.o.open_region) return false;
    const auto& r = *m_.o.open_region;
    constexpr double tol = 1e-3;
    return (std::abs(a.x - r.min.x) < tol && std::abs(b.x - r.min.x) < tol) ||
           (std::abs(a.x - r.max.x) < tol && std::abs(b.x - r.max.x) < tol) ||
           (std::abs(a.y - r.min.y) < tol && std::abs(b.y - r.min.y) < tol) ||
           (std::abs(a.y - r.max.y) < tol && std::abs(b.y - r.max.y) < tol);
  }
  bool FarFromStructure(const Vec2& a, const Vec2& b) const {
    if (structure_.empty()) return false;  // nothing found yet: all of the boundary is frontier
    const double reach = m_.o.open_frontier_reach;
    const core::Aabb2 box = core::SegmentBox(a, b);
    for (const Vec2& p : structure_)
      if (core::BoxHits(box, p, reach) && core::DistanceToSegment(p, {a, b}) <= reach) return false;
    return true;
  }
  const MapCore& m_;
  const MapState& ms_;
  std::vector<Vec2> structure_;
};

// The chains of frontier edges along one ring of the known-space boundary.
void WalkRing(const core::Ring& ring, const BoundaryRules& rules, std::vector<Frontier>* out) {
  const size_t n = ring.size();
  std::vector<char> free_edge(n);
  for (size_t i = 0; i < n; ++i) free_edge[i] = rules.Frontier(ring[i], ring[(i + 1) % n]);
  // Start at a wall edge so chains do not wrap (a ring with no wall is one closed frontier).
  size_t start = 0;
  while (start < n && free_edge[start]) ++start;
  if (start == n) start = 0;
  Frontier cur;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = (start + k) % n;
    if (free_edge[i]) {
      if (cur.points.empty()) cur.points.push_back(ring[i]);
      cur.points.push_back(ring[(i + 1) % n]);
    } else if (!cur.points.empty()) {
      out->push_back(cur);
      cur = Frontier();
    }
  }
  if (!cur.points.empty()) out->push_back(cur);
}

// A chain that turns sharply (two chords meeting at a corner of the walls, one across a doorway, one across a
// corridor) is two frontiers: one target at the chain's middle would sit in the corner, where neither opening
// shows.  Each piece records how sharply it turns at an end where it was cut.
std::vector<Frontier> SplitAtSharpTurns(const std::vector<Frontier>& chains, double max_turn, double min_length) {
  std::vector<Frontier> split;
  for (const auto& f : chains) {
    const bool ring = f.points.size() > 3 && f.points.front() == f.points.back();
    const auto pieces = SplitAtTurns(f.points, max_turn, min_length);
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
  return split;
}

// Length and the point halfway along.
void Measure(Frontier* f) {
  for (size_t i = 1; i < f->points.size(); ++i) f->length += core::Distance(f->points[i - 1], f->points[i]);
  double half = f->length / 2, acc = 0;
  f->midpoint = f->points.front();
  for (size_t i = 1; i < f->points.size(); ++i) {
    const double d = core::Distance(f->points[i - 1], f->points[i]);
    if (acc + d >= half) {
      f->midpoint = f->points[i - 1] + (f->points[i] - f->points[i - 1]) * ((half - acc) / std::max(d, 1e-12));
      break;
    }
    acc += d;
  }
}

}  // namespace

std::vector<Frontier> FrontierTracker::Extract(const MapCore& m, const MapState& ms,
                                               const std::vector<core::Polygon>& known) {
  const BoundaryRules rules(m, ms);
  std::vector<Frontier> out;
  for (const auto& p : known) {
    WalkRing(p.outer, rules, &out);
    for (const auto& h : p.holes) WalkRing(h, rules, &out);
  }
  // Not in open worlds: there the boundary bends around every building's shadow, and the extra pieces left
  // single agents zigzagging between them.
  if (m.o.frontier_split_angle > 0 && !m.o.open_region)
    out = SplitAtSharpTurns(out, m.o.frontier_split_angle, m.o.frontier_split_min_length);
  for (auto& f : out) Measure(&f);
  AssignIds(&out);
  last_ = out;
  return out;
}

// Stable identities: a frontier keeps the id of the previous one whose midpoint is nearest, if close.
void FrontierTracker::AssignIds(std::vector<Frontier>* frontiers) {
  std::vector<char> taken(last_.size());
  for (auto& f : *frontiers) {
    int best = -1;
    double best_d = std::max(2.0, 0.5 * f.length);
    for (size_t j = 0; j < last_.size(); ++j) {
      const double d = core::Distance(f.midpoint, last_[j].midpoint);
      if (!taken[j] && d < best_d) {
        best_d = d;
        best = int(j);
      }
    }
    if (best >= 0) {
      taken[size_t(best)] = 1;
      f.id = last_[size_t(best)].id;
    } else {
      f.id = next_id_++;
    }
  }
}

}  // namespace toponav::mapping::internal

// Frontier targets (planning/navigation.h): where an agent goes to explore each frontier, and which frontiers
// are taken for walls the map has not accepted yet.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/error.h"
#include "planning/navigation.h"

namespace toponav::planning {

using core::Vec2;

namespace {

// True if every point of 'f' lies within 'tol' of its chord, and the chord has a length.
bool Straight(const mapping::Frontier& f, double tol) {
  if (f.points.size() < 2) return false;
  const Vec2 a = f.points.front(), b = f.points.back();
  if (core::Distance(a, b) < 1e-9) return false;
  for (const auto& p : f.points)
    if (core::DistanceToSegment(p, {a, b}) > tol) return false;
  return true;
}

}  // namespace

bool AlongVertexRow(const mapping::Frontier& f, const mapping::MapView& view, const PlannerOptions& options) {
  const double tol = options.frontier_row_tolerance;
  if (options.frontier_row_gap <= 0 || f.points.size() < 2) return false;
  const Vec2 a = f.points.front(), b = f.points.back();
  const double length = core::Distance(a, b);
  if (!Straight(f, tol)) return false;  // bent: not a straight wall
  // Where the detected vertices next to the chord lie along it, with both ends counted -- but not an end where a
  // chain was cut at a gentle turn (an opening that goes on round the turn) unless a detected vertex sits there.
  // (A sharp one, a notch in known space, bounds it like a vertex.)
  const Vec2 u = (b - a) / length;
  auto bounded = [](double turn) { return turn == 0.0 || turn >= core::kPi / 2; };
  std::vector<double> along;
  if (bounded(f.front_turn)) along.push_back(0.0);
  if (bounded(f.back_turn)) along.push_back(length);
  for (const auto* list : {&view.vertices, &view.rejected})
    for (const auto& v : *list)
      if (core::DistanceToSegment(v.position, {a, b}) <= tol) along.push_back(core::Dot(v.position - a, u));
  std::sort(along.begin(), along.end());
  if (along.empty() || along.front() > tol || along.back() < length - tol) return false;
  for (size_t i = 1; i < along.size(); ++i)
    if (along[i] - along[i - 1] > options.frontier_row_gap) return false;
  return true;
}

bool ClosesWallChain(const mapping::Frontier& f, const mapping::MapView& view, const PlannerOptions& options) {
  constexpr double kSquareCos = 0.26;  // cos 75 degrees: a wall meeting the side within 15 degrees of square
  const double tol = options.frontier_row_tolerance;
  if (!Straight(f, tol)) return false;
  const Vec2 a = f.points.front(), b = f.points.back();
  auto vertex_at = [&](const Vec2& p) {
    for (const auto& v : view.vertices)
      if (core::Distance(v.position, p) <= tol) return v.id;
    return -1;
  };
  const int from = vertex_at(a), to = vertex_at(b);
  if (from < 0 || to < 0 || from == to) return false;
  const Vec2 chord = (b - a) / core::Distance(a, b);
  std::map<int, std::vector<int>> next;
  for (const auto& w : view.walls) {
    if ((w.a == from && w.b == to) || (w.a == to && w.b == from)) continue;  // the short way
    const bool at_end = w.a == from || w.b == from || w.a == to || w.b == to;
    const double len = core::Distance(w.pa, w.pb);
    if (at_end && (len < 1e-9 || std::abs(core::Dot(w.pb - w.pa, chord)) > kSquareCos * len)) return false;
    next[w.a].push_back(w.b);
    next[w.b].push_back(w.a);
  }
  std::set<int> seen{from};
  std::vector<int> open{from};
  while (!open.empty()) {
    const int v = open.back();
    open.pop_back();
    if (v == to) return true;
    for (int u : next[v])
      if (seen.insert(u).second) open.push_back(u);
  }
  return false;
}

namespace {

// True if the segment from a to b crosses none of the view's walls.
bool CrossesNoWall(const mapping::MapView& view, const Vec2& a, const Vec2& b) {
  for (const auto& w : view.walls)
    if (core::SegmentsIntersect({a, b}, {w.pa, w.pb})) return false;
  return true;
}

// The target for a frontier at 'point' on it, where its local direction is 'dir': on the known side (the
// side known space lies on within 2 units, or within the setback if smaller), the deepest of 'frontier_setback',
// its half, quarter, ... (down to that probe depth) that lies in known space with no wall between it and
// the frontier; the point itself where known space is thinner than the probe.
FrontierTarget TargetAt(const mapping::MapView& view, const mapping::Frontier& f, const Vec2& point, const Vec2& dir,
                        const PlannerOptions& options) {
  const Vec2 normal{-dir.y, dir.x};
  const double probe = std::min(options.frontier_setback, 2.0);
  for (const double side : {1.0, -1.0}) {
    if (!InKnown(view, point + normal * (side * probe))) continue;
    double depth = probe;
    for (double d = options.frontier_setback; d > probe; d *= 0.5) {
      const Vec2 p = point + normal * (side * d);
      if (InKnown(view, p) && CrossesNoWall(view, point, p)) {
        depth = d;
        break;
      }
    }
    return {f.id, point + normal * (side * depth), f.length, normal * -side, depth};
  }
  return {f.id, point, f.length, normal, 0.0};
}

// The target at the frontier's midpoint (the direction of the segment under it).
FrontierTarget MidpointTarget(const mapping::MapView& view, const mapping::Frontier& f, const PlannerOptions& options) {
  double best = std::numeric_limits<double>::infinity();
  Vec2 dir{1, 0};
  for (size_t i = 1; i < f.points.size(); ++i) {
    const double d = core::DistanceToSegment(f.midpoint, {f.points[i - 1], f.points[i]});
    if (d < best && core::Distance(f.points[i - 1], f.points[i]) > 1e-9) {
      best = d;
      dir = (f.points[i] - f.points[i - 1]) / core::Distance(f.points[i - 1], f.points[i]);
    }
  }
  return TargetAt(view, f, f.midpoint, dir, options);
}

}  // namespace

std::vector<FrontierTarget> FrontierTargets(const mapping::MapView& view, const PlannerOptions& options) {
  std::vector<FrontierTarget> out;
  for (const auto& f : view.frontiers) {
    if (f.length < options.frontier_min_length || f.points.size() < 2) continue;
    if (AlongVertexRow(f, view, options)) continue;
    out.push_back(MidpointTarget(view, f, options));
  }
  return out;
}

std::vector<const mapping::Frontier*> TargetFrontiers(const mapping::MapView& view,
                                                      const std::vector<FrontierTarget>& targets) {
  std::vector<const mapping::Frontier*> out;
  for (const auto& t : targets)
    for (const auto& f : view.frontiers)
      if (f.id == t.frontier_id) out.push_back(&f);
  return out;
}

}  // namespace toponav::planning

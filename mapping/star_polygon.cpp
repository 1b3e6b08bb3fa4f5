#include <algorithm>
#include <cmath>
#include <limits>

#include "mapping/mapping.h"

namespace toponav::mapping {

using core::Vec2;

namespace {

struct Polar {
  double angle, range;
  StarPoint s;
};

// Points by bearing from the center, one per bearing (the nearest: the conservative choice, since a spike
// would not be a simple polygon), none at the center.
std::vector<Polar> SortedByBearing(const Vec2& center, const std::vector<StarPoint>& points) {
  std::vector<Polar> pts;
  for (const auto& s : points) {
    const double r = core::Distance(s.p, center);
    if (r < 1e-9) continue;
    pts.push_back({std::atan2(s.p.y - center.y, s.p.x - center.x), r, s});
  }
  std::sort(pts.begin(), pts.end(), [](const Polar& a, const Polar& b) {
    return a.angle != b.angle ? a.angle < b.angle : a.range < b.range;
  });
  std::vector<Polar> uniq;
  for (const auto& p : pts)
    if (uniq.empty() || p.angle - uniq.back().angle > 1e-12) uniq.push_back(p);
  if (uniq.size() > 1 && uniq.front().angle + 2 * core::kPi - uniq.back().angle <= 1e-12) {
    if (uniq.back().range < uniq.front().range) uniq.front() = uniq.back();  // same bearing across -pi/pi
    uniq.pop_back();
  }
  return uniq;
}

// Distance along the unit direction d from c to the segment a-b, whose ends may be missed by 'slack' (as a
// fraction of its length); infinity if the ray misses it or runs parallel to it.
double RayToSegment(const Vec2& c, const Vec2& d, const Vec2& a, const Vec2& b, double slack) {
  const Vec2 e = b - a, w = a - c;
  const double den = d.x * e.y - d.y * e.x;
  if (std::abs(den) < 1e-15) return std::numeric_limits<double>::infinity();
  const double t = (w.x * e.y - w.y * e.x) / den, u = (w.x * d.y - w.y * d.x) / den;
  return t > 0 && u >= -slack && u <= 1 + slack ? t : std::numeric_limits<double>::infinity();
}

// Distance along the unit direction d from c to the nearest of the box's edge, max_range and the blockers;
// *which = the blocker that is nearest (or -1).
double RayReach(const Vec2& c, const Vec2& d, const OpenSpace& s, int* which) {
  double t = s.max_range;
  const auto& b = s.region;
  if (b.Contains(c)) {  // (seen from outside the region, as a clipped chord may be, only blockers stop it)
    if (d.x > 1e-15) t = std::min(t, (b.max.x - c.x) / d.x);
    if (d.x < -1e-15) t = std::min(t, (b.min.x - c.x) / d.x);
    if (d.y > 1e-15) t = std::min(t, (b.max.y - c.y) / d.y);
    if (d.y < -1e-15) t = std::min(t, (b.min.y - c.y) / d.y);
  }
  *which = -1;
  for (size_t k = 0; k < s.blockers.size(); ++k) {
    const double tk = RayToSegment(c, d, s.blockers[k].a, s.blockers[k].b, 0.0);
    if (tk > 1e-9 && tk < t) {
      t = tk;
      *which = int(k);
    }
  }
  return t;
}

// True if a blocker enters the triangle c-a-b (touching it only at a or b does not count).
bool BlockerInTriangle(const Vec2& c, const Vec2& a, const Vec2& b, const std::vector<core::Segment2>& blockers) {
  const Vec2 m = (c + a + b) / 3.0;
  const Vec2 t0 = c + (m - c) * 1e-7, t1 = a + (m - a) * 1e-7, t2 = b + (m - b) * 1e-7;
  const core::Ring tri{t0, t1, t2};
  const double minx = std::min({t0.x, t1.x, t2.x}), maxx = std::max({t0.x, t1.x, t2.x});
  const double miny = std::min({t0.y, t1.y, t2.y}), maxy = std::max({t0.y, t1.y, t2.y});
  for (const auto& s : blockers) {
    if (std::max(s.a.x, s.b.x) < minx || std::min(s.a.x, s.b.x) > maxx || std::max(s.a.y, s.b.y) < miny ||
        std::min(s.a.y, s.b.y) > maxy)
      continue;
    if (core::Contains(tri, s.a) || core::Contains(tri, s.b)) return true;
    if (core::SegmentsIntersect(s, {t0, t1}) || core::SegmentsIntersect(s, {t1, t2}) ||
        core::SegmentsIntersect(s, {t2, t0}))
      return true;
  }
  return false;
}

}  // namespace

core::Ring StarPolygon(const Vec2& center, const std::vector<Vec2>& points) {
  std::vector<StarPoint> s;
  for (const auto& p : points) s.push_back({p, false, false});
  return OpenStarPolygon(center, s, OpenSpace{});
}

core::Ring OpenStarPolygon(const Vec2& center, const std::vector<StarPoint>& points, const OpenSpace& space,
                           std::vector<int>* hit) {
  if (hit) hit->clear();
  const std::vector<Polar> uniq = SortedByBearing(center, points);
  if (uniq.size() < 2) return {};
  const bool can_open = space.region.width() > 0 && space.region.height() > 0 && space.region.Contains(center) &&
                        space.max_range > 0 && space.sample_step > 0;
  std::vector<double> corners;
  if (can_open) {
    const auto& b = space.region;
    for (const Vec2& q : {b.min, Vec2{b.max.x, b.min.y}, b.max, Vec2{b.min.x, b.max.y}})
      if (core::Distance(q, center) > 1e-9) corners.push_back(std::atan2(q.y - center.y, q.x - center.x));
  }
  std::vector<double> ends;  // bearings of the blockers' ends
  for (const auto& b : space.blockers)
    for (const Vec2& e : {b.a, b.b})
      if (core::Distance(e, center) >= 1e-9) ends.push_back(std::atan2(e.y - center.y, e.x - center.x));
  constexpr double kEdge = 1e-4;  // the first and last rays of a window leave this far inside it
  core::Ring ring;
  for (size_t i = 0; i < uniq.size(); ++i) {
    ring.push_back(uniq[i].s.p);
    const double a0 = uniq[i].angle;
    const double a1 = i + 1 < uniq.size() ? uniq[i + 1].angle : uniq[0].angle + 2 * core::kPi;
    const Vec2 next_p = uniq[(i + 1) % uniq.size()].s.p;
    const bool open = can_open && uniq[i].s.open_ccw && uniq[(i + 1) % uniq.size()].s.open_cw && a1 - a0 > 4 * kEdge;
    // A closed window is the chord, unless a blocker cuts into the triangle under it: then rays trace the
    // nearer of the two.
    const bool clipped = !open && a1 - a0 < core::kPi && a1 - a0 > 4 * kEdge && !space.blockers.empty() &&
                         BlockerInTriangle(center, uniq[i].s.p, next_p, space.blockers);
    if (!open && !clipped) {
      if (a1 - a0 >= core::kPi) ring.push_back(center);
      continue;
    }
    const double lo = a0 + kEdge, hi = a1 - kEdge;
    const int n = std::max(1, int(std::ceil((hi - lo) / space.sample_step)));
    std::vector<double> rays;
    for (int k = 0; k <= n; ++k) rays.push_back(lo + (hi - lo) * k / n);
    if (open)
      for (double c : corners)
        for (double w = c; w < hi; w += 2 * core::kPi)
          if (w > lo) rays.push_back(w);
    // Where a blocker ends inside the window the traced boundary turns a corner: rays just either side of
    // its end keep that corner (sampled rays alone would cut across it).
    for (double c : ends)
      for (double w = c; w < hi + 1e-6; w += 2 * core::kPi)
        for (double side : {-1e-5, 1e-5})
          if (w + side > lo && w + side < hi) rays.push_back(w + side);
    std::sort(rays.begin(), rays.end());
    rays.erase(std::unique(rays.begin(), rays.end(), [](double x, double y) { return y - x < 1e-9; }), rays.end());
    int added = 0;  // ray points of this window so far
    for (double a : rays) {
      const Vec2 d{std::cos(a), std::sin(a)};
      int which = -1;
      double t = RayReach(center, d, space, &which);
      if (clipped) {
        const double chord = RayToSegment(center, d, uniq[i].s.p, next_p, 1e-9);
        if (chord <= t) {
          t = chord;
          which = -1;
        }
      }
      if (which >= 0 && hit) hit->push_back(which);
      const Vec2 q = center + d * std::max(t, 1e-6);
      // Rays that end on one straight edge (a wall, the region's side) need only its two ends.
      if (added >= 2) {
        const Vec2 p1 = ring[ring.size() - 2], p2 = ring.back();
        const Vec2 u = p2 - p1, w = q - p2;
        if (std::abs(core::Cross(u, w)) <= 1e-9 * core::Norm(u) * core::Norm(w) && core::Dot(u, w) > 0) {
          ring.back() = q;
          continue;
        }
      }
      ring.push_back(q);
      ++added;
    }
  }
  if (hit) {
    std::sort(hit->begin(), hit->end());
    hit->erase(std::unique(hit->begin(), hit->end()), hit->end());
  }
  // Exact Booleans want no repeated points and no straight-through or doubled-back corners.
  ring = core::RemoveCollinear(ring, 1e-12);
  if (ring.size() < 3 || std::abs(core::SignedArea(ring)) < 1e-12) return {};
  return ring;
}

}  // namespace toponav::mapping

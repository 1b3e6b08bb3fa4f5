#include "core/geometry.h"

#include <algorithm>
#include <limits>

namespace toponav::core {

double WrapAngle(double a) {
  a = std::fmod(a + kPi, 2.0 * kPi);
  if (a < 0) a += 2.0 * kPi;
  return a - kPi;
}

double SignedArea(const Ring& ring) {
  double s = 0.0;
  for (size_t i = 0, n = ring.size(); i < n; ++i) s += Cross(ring[i], ring[(i + 1) % n]);
  return 0.5 * s;
}

double Area(const Polygon& polygon) {
  double a = std::abs(SignedArea(polygon.outer));
  for (const auto& h : polygon.holes) a -= std::abs(SignedArea(h));
  return a;
}

void Reverse(Ring& ring) { std::reverse(ring.begin(), ring.end()); }

bool Contains(const Ring& ring, const Vec2& p) {
  bool inside = false;
  for (size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

bool Contains(const Polygon& polygon, const Vec2& p) {
  if (!Contains(polygon.outer, p)) return false;
  for (const auto& h : polygon.holes)
    if (Contains(h, p)) return false;
  return true;
}

Aabb2 Bounds(const std::vector<Vec2>& points, const Aabb2& start) {
  Aabb2 b = start;
  for (const auto& p : points) {
    b.min.x = std::min(b.min.x, p.x);
    b.min.y = std::min(b.min.y, p.y);
    b.max.x = std::max(b.max.x, p.x);
    b.max.y = std::max(b.max.y, p.y);
  }
  return b;
}

double PolylineLength(const std::vector<Vec2>& points) {
  double length = 0;
  for (size_t i = 1; i < points.size(); ++i) length += Norm(points[i] - points[i - 1]);
  return length;
}

Vec2 PointAlong(const std::vector<Vec2>& polyline, double s) {
  for (size_t i = 1; i < polyline.size(); ++i) {
    const double len = Distance(polyline[i - 1], polyline[i]);
    if (s <= len && len > 1e-12) return polyline[i - 1] + (polyline[i] - polyline[i - 1]) * (std::max(s, 0.0) / len);
    s -= len;
  }
  return polyline.back();
}

std::vector<Vec2> SubPolyline(const std::vector<Vec2>& polyline, double s0, double s1) {
  std::vector<Vec2> out;
  double s = 0;
  for (size_t i = 1; i < polyline.size(); ++i) {
    const Vec2 a = polyline[i - 1], b = polyline[i];
    const double len = Distance(a, b), next = s + len;
    if (len > 1e-12 && next > s0 && s < s1) {
      const auto at = [&](double t) { return a + (b - a) * ((std::clamp(t, s, next) - s) / len); };
      if (out.empty()) out.push_back(at(s0));
      out.push_back(at(s1));
    }
    s = next;
  }
  return out;
}

Aabb2 Bounds(const Ring& ring) {
  const double inf = std::numeric_limits<double>::infinity();
  return Bounds(ring, Aabb2{{inf, inf}, {-inf, -inf}});
}

double DistanceToSegment(const Vec2& p, const Segment2& s) {
  const Vec2 d = s.b - s.a;
  const double len2 = Dot(d, d);
  double t = len2 > 0 ? Dot(p - s.a, d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return Distance(p, s.a + d * t);
}

bool NearSegmentInterior(const Vec2& p, const Segment2& s, double tolerance) {
  const Vec2 d = s.b - s.a;
  const double len2 = Dot(d, d);
  if (len2 < 1e-12) return false;
  const double t = Dot(p - s.a, d) / len2;
  return t > 0 && t < 1 && std::abs(Cross(d, p - s.a)) < tolerance * std::sqrt(len2);
}

double DistanceToRing(const Vec2& p, const Ring& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, n = ring.size(); i < n; ++i)
    best = std::min(best, DistanceToSegment(p, {ring[i], ring[(i + 1) % n]}));
  return best;
}

bool NearRing(const Vec2& p, const Ring& ring, double tol) {
  for (size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    if (BoxHits(SegmentBox(a, b), p, tol) && DistanceToSegment(p, {a, b}) < tol) return true;
  }
  return false;
}

namespace {
int Orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = Cross(b - a, c - a);
  return (v > 0) - (v < 0);
}
bool OnSegment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
}  // namespace

bool SegmentsIntersect(const Segment2& s, const Segment2& t) {
  const int o1 = Orient(s.a, s.b, t.a), o2 = Orient(s.a, s.b, t.b);
  const int o3 = Orient(t.a, t.b, s.a), o4 = Orient(t.a, t.b, s.b);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && OnSegment(s.a, s.b, t.a)) return true;
  if (o2 == 0 && OnSegment(s.a, s.b, t.b)) return true;
  if (o3 == 0 && OnSegment(t.a, t.b, s.a)) return true;
  if (o4 == 0 && OnSegment(t.a, t.b, s.b)) return true;
  return false;
}

double SegmentDistance(const Segment2& s, const Segment2& t) {
  if (SegmentsIntersect(s, t)) return 0.0;
  return std::min({DistanceToSegment(s.a, t), DistanceToSegment(s.b, t), DistanceToSegment(t.a, s),
                   DistanceToSegment(t.b, s)});
}

double RingDistance(const Ring& a, const Ring& b) {
  if ((!b.empty() && Contains(a, b[0])) || (!a.empty() && Contains(b, a[0]))) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j)
      best = std::min(best, SegmentDistance({a[i], a[(i + 1) % a.size()]}, {b[j], b[(j + 1) % b.size()]}));
  return best;
}

bool IsSimple(const Ring& ring) {
  const size_t n = ring.size();
  if (n < 3) return false;
  for (size_t i = 0; i < n; ++i)
    if (ring[i] == ring[(i + 1) % n]) return false;
  if (std::abs(SignedArea(ring)) <= 0.0) return false;
  for (size_t i = 0; i < n; ++i) {
    const Segment2 e{ring[i], ring[(i + 1) % n]};
    for (size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Segment2 f{ring[j], ring[(j + 1) % n]};
      if (adjacent) {
        // Adjacent edges share one endpoint; they must not fold back onto each other.
        const Vec2 shared = (j == i + 1) ? e.b : e.a;
        const Vec2 u = ((j == i + 1) ? e.a : e.b) - shared;
        const Vec2 v = ((j == i + 1) ? f.b : f.a) - shared;
        if (std::abs(Cross(u, v)) <= 1e-12 * Norm(u) * Norm(v) && Dot(u, v) > 0) return false;
        continue;
      }
      if (SegmentsIntersect(e, f)) return false;
    }
  }
  return true;
}

Ring RemoveCollinear(const Ring& ring, double tolerance) {
  Ring pts;
  for (const auto& p : ring)
    if (pts.empty() || p != pts.back()) pts.push_back(p);
  while (pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
  bool changed = true;
  while (changed && pts.size() > 3) {
    changed = false;
    for (size_t i = 0; i < pts.size() && pts.size() > 3; ++i) {
      const size_t n = pts.size();
      const Vec2& a = pts[(i + n - 1) % n];
      const Vec2& b = pts[i];
      const Vec2& c = pts[(i + 1) % n];
      if (std::abs(Cross(b - a, c - b)) <= tolerance * Norm(b - a) * Norm(c - b)) {
        pts.erase(pts.begin() + long(i));
        changed = true;
        --i;
      }
    }
  }
  return pts;
}

}  // namespace toponav::core

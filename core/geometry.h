#pragma once
// Plain 2D value types shared by every layer, and free functions on them.
// Conventions: angles in radians, counter-clockwise positive, atan2 convention; a Ring is a closed polygon
// boundary stored without repeating its first point; polygon outer rings are counter-clockwise, holes clockwise.
#include <algorithm>
#include <cmath>
#include <vector>

namespace toponav::core {

constexpr double kPi = 3.14159265358979323846;

struct Vec2 {
  double x = 0.0, y = 0.0;
  Vec2 operator+(const Vec2& o) const { return {x + o.x, y + o.y}; }
  Vec2 operator-(const Vec2& o) const { return {x - o.x, y - o.y}; }
  Vec2 operator*(double s) const { return {x * s, y * s}; }
  Vec2 operator/(double s) const { return {x / s, y / s}; }
  bool operator==(const Vec2& o) const { return x == o.x && y == o.y; }
  bool operator!=(const Vec2& o) const { return !(*this == o); }
};

inline double Dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
inline double Cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
// Not hypot: hot, and coordinates are small.
inline double Norm(const Vec2& a) { return std::sqrt(a.x * a.x + a.y * a.y); }
inline double Distance(const Vec2& a, const Vec2& b) { return Norm(a - b); }
inline Vec2 Rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
// Wraps an angle to [-pi, pi).
double WrapAngle(double a);

struct Pose2 {
  double x = 0.0, y = 0.0, yaw = 0.0;
  Vec2 position() const { return {x, y}; }
};

struct Segment2 {
  Vec2 a, b;
};

struct Aabb2 {
  Vec2 min, max;
  double width() const { return max.x - min.x; }
  double height() const { return max.y - min.y; }
  bool Contains(const Vec2& p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
};

// Cheap box tests (exact comparisons, so disjoint boxes prove there is no contact): 'p' in 'box' grown by
// 'grow' on every side (a negative grow shrinks it); the box of segment p-q meets 'box' grown by 'grow'.
inline Aabb2 SegmentBox(const Vec2& p, const Vec2& q) {
  return {{std::min(p.x, q.x), std::min(p.y, q.y)}, {std::max(p.x, q.x), std::max(p.y, q.y)}};
}
inline bool BoxHits(const Aabb2& box, const Vec2& p, double grow = 0.0) {
  return p.x >= box.min.x - grow && p.x <= box.max.x + grow && p.y >= box.min.y - grow && p.y <= box.max.y + grow;
}
inline bool BoxHitsSegment(const Aabb2& box, const Vec2& p, const Vec2& q, double grow = 0.0) {
  return std::max(p.x, q.x) >= box.min.x - grow && std::min(p.x, q.x) <= box.max.x + grow &&
         std::max(p.y, q.y) >= box.min.y - grow && std::min(p.y, q.y) <= box.max.y + grow;
}

struct Circle {
  Vec2 center;
  double radius = 0.0;
};

using Ring = std::vector<Vec2>;

// A polygon with holes: 'outer' counter-clockwise, each hole clockwise.
struct Polygon {
  Ring outer;
  std::vector<Ring> holes;
};

double SignedArea(const Ring& ring);            // > 0 for counter-clockwise
double Area(const Polygon& polygon);            // outer minus holes
void Reverse(Ring& ring);
bool Contains(const Ring& ring, const Vec2& p);  // strict interior (boundary points may go either way)
bool Contains(const Polygon& polygon, const Vec2& p);
Aabb2 Bounds(const Ring& ring);
Aabb2 Bounds(const std::vector<Vec2>& points, const Aabb2& start);
double PolylineLength(const std::vector<Vec2>& points);  // summed segment lengths (0 for fewer than 2 points)
// The point at arc length s along 'polyline' (one point or more; s is clamped to [0, length]).
Vec2 PointAlong(const std::vector<Vec2>& polyline, double s);
// The part of 'polyline' between arc lengths s0 < s1 (empty where they miss it).
std::vector<Vec2> SubPolyline(const std::vector<Vec2>& polyline, double s0, double s1);

double DistanceToSegment(const Vec2& p, const Segment2& s);
// True if p projects strictly between s.a and s.b and lies less than 'tolerance' from the line through them
// (false for a segment of zero length).
bool NearSegmentInterior(const Vec2& p, const Segment2& s, double tolerance);
double DistanceToRing(const Vec2& p, const Ring& ring);  // to the boundary
bool NearRing(const Vec2& p, const Ring& ring, double tol);  // DistanceToRing(p, ring) < tol, faster
double SegmentDistance(const Segment2& s, const Segment2& t);
// Distance between two ring-bounded regions: 0 if they overlap or one contains the other.
double RingDistance(const Ring& a, const Ring& b);
// True if the open segments cross or touch (shared endpoints of adjacent edges are not passed in).
bool SegmentsIntersect(const Segment2& s, const Segment2& t);
// True if the ring has at least 3 points, no repeated consecutive points, non-zero area and no two
// non-adjacent edges that touch or cross.  O(n^2): meant for validation, not hot paths.
bool IsSimple(const Ring& ring);
// Removes consecutive duplicates and points collinear with their neighbours.
Ring RemoveCollinear(const Ring& ring, double tolerance = 1e-9);

}  // namespace toponav::core

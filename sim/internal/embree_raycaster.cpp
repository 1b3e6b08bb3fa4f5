// The Embree 3 scene behind sim::RayCaster.  Embree finds which primitive a ray hits first; positions that
// must be exact (visibility polygon points) are then recomputed in double from the hit wall's segment.
#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "core/error.h"
#include "sim/raycast.h"
#include "sim/sim.h"

namespace toponav::sim {

using core::Ring;
using core::Vec2;

namespace {

constexpr unsigned kMaskWalls = 1, kMaskClutter = 2, kMaskFar = 4;
constexpr int kCylinderSides = 32;

RTCDevice Device() {
  static std::once_flag once;
  static RTCDevice device = nullptr;
  std::call_once(once, [] {
    device = rtcNewDevice("threads=1");
    if (!device) throw core::InternalError("Embree: rtcNewDevice failed (error " +
                                           std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    // Walls, clutter and the far box are told apart by ray masks: an Embree built without them would let
    // clutter hide vertices silently.
    if (!rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED))
      throw core::InternalError("Embree was built without ray-mask support (EMBREE_RAY_MASK=ON is required)");
  });
  return device;
}

// Vertical quads standing on 2D segments, z in [-1, 1]; rays travel in the z = 0 plane.
RTCGeometry QuadGeometry(RTCDevice dev, const std::vector<core::Segment2>& segs, unsigned mask) {
  RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_QUAD);
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * segs.size()));
  auto* idx = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), segs.size()));
  for (size_t i = 0; i < segs.size(); ++i) {
    const auto& s = segs[i];
    const float pts[4][3] = {{float(s.a.x), float(s.a.y), -1.f},
                             {float(s.b.x), float(s.b.y), -1.f},
                             {float(s.b.x), float(s.b.y), 1.f},
                             {float(s.a.x), float(s.a.y), 1.f}};
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) v[12 * i + 3 * size_t(k) + size_t(c)] = pts[k][c];
    for (unsigned k = 0; k < 4; ++k) idx[4 * i + k] = unsigned(4 * i) + k;
  }
  rtcSetGeometryMask(g, mask);
  rtcCommitGeometry(g);
  return g;
}

std::vector<core::Segment2> ClutterSegments(const std::vector<core::Clutter>& clutter) {
  std::vector<core::Segment2> segs;
  for (const auto& c : clutter) {
    Ring r;
    if (c.shape == core::ClutterShape::kBox) {
      for (const Vec2 corner : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}})
        r.push_back(c.center + core::Rotate(corner * c.size, c.yaw));
    } else {  // circumscribed polygon, so rays never pass through the true disc
      const double rr = c.size / std::cos(core::kPi / kCylinderSides);
      for (int k = 0; k < kCylinderSides; ++k) {
        const double a = 2 * core::kPi * k / kCylinderSides;
        r.push_back(c.center + Vec2{rr * std::cos(a), rr * std::sin(a)});
      }
    }
    for (size_t i = 0; i < r.size(); ++i) segs.push_back({r[i], r[(i + 1) % r.size()]});
  }
  return segs;
}

double Wrap2Pi(double a) {
  a = std::fmod(a, 2 * core::kPi);
  return a < 0 ? a + 2 * core::kPi : a;
}

}  // namespace

struct RayCaster::Impl {
  core::World world;
  std::vector<const Ring*> rings;          // map rings in VertexRef order
  std::vector<bool> ring_is_boundary;
  std::vector<core::Segment2> walls;       // primID -> wall
  std::vector<core::VertexRef> wall_start; // primID -> (ring, index of the wall's first vertex)
  std::vector<Ring> far_rings;             // the far box (open worlds only), for the visibility polygon
  RTCScene scene = nullptr;

  struct Hit {
    double t = 0.0;
    unsigned geom = RTC_INVALID_GEOMETRY_ID;
    unsigned prim = 0;
    bool valid() const { return geom != RTC_INVALID_GEOMETRY_ID; }
  };

  Hit Intersect(const Vec2& o, const Vec2& dir, double tnear, double tfar, unsigned mask) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray.org_x = float(o.x);
    rh.ray.org_y = float(o.y);
    rh.ray.org_z = 0.f;
    rh.ray.dir_x = float(dir.x);
    rh.ray.dir_y = float(dir.y);
    rh.ray.dir_z = 0.f;
    rh.ray.tnear = float(tnear);
    rh.ray.tfar = std::isfinite(tfar) ? float(tfar) : std::numeric_limits<float>::infinity();
    rh.ray.mask = mask;
    rh.ray.flags = 0;
    rh.ray.time = 0.f;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &ctx, &rh);
    return {double(rh.ray.tfar), rh.hit.geomID, rh.hit.primID};
  }

  // Wall segment hit by a ray (for geometry 0 = walls, 2 = far box).
  core::Segment2 HitSegment(const Hit& h) const {
    if (h.geom == 0) return walls[h.prim];
    const Ring& box = far_rings[0];
    return {box[h.prim], box[(h.prim + 1) % box.size()]};
  }

  bool IncidentToVertex(const Hit& h, const core::VertexRef& v) const {
    if (h.geom != 0) return false;
    const core::VertexRef& s = wall_start[h.prim];
    if (s.ring != v.ring) return false;
    const int n = int(rings[size_t(v.ring)]->size());
    return s.index == v.index || (s.index + 1) % n == v.index;
  }

  // True if nothing blocks the open segment from p to vertex v, and the ray arrives at v from the region p is in.
  bool Sees(const Vec2& p, bool p_in_solid, const core::VertexRef& v) const {
    const Ring& ring = *rings[size_t(v.ring)];
    const Vec2 pv = ring[size_t(v.index)];
    const double dist = core::Distance(p, pv);
    if (dist < 1e-12) return true;
    // Exact local test: which side of the ring the ray's last stretch lies on.
    const Vec2 prev = ring[size_t((v.index + int(ring.size()) - 1) % int(ring.size()))];
    const Vec2 next = ring[size_t((v.index + 1) % int(ring.size()))];
    const double a_next = std::atan2(next.y - pv.y, next.x - pv.x);
    const double wedge = Wrap2Pi(std::atan2(prev.y - pv.y, prev.x - pv.x) - a_next);
    const double back = Wrap2Pi(std::atan2(p.y - pv.y, p.x - pv.x) - a_next);
    const bool in_interior = back > 0 && back < wedge;  // the ring's left (interior) side
    const bool arrives_in_solid = ring_is_boundary[size_t(v.ring)] ? !in_interior : in_interior;
    if (arrives_in_solid != p_in_solid) return false;
    // Embree for everything between; hits on v's own walls are rounding noise (a line through v meets them
    // only at v) and are stepped over.
    const Vec2 dir = (pv - p) / dist;
    double tnear = 0.0;
    for (int guard = 0; guard < 16; ++guard) {
      const Hit h = Intersect(p, dir, tnear, dist, kMaskWalls);
      if (!h.valid()) return true;
      if (!IncidentToVertex(h, v)) return false;
      tnear = h.t * (1 + 1e-6) + 1e-6;
      if (tnear >= dist) return true;
    }
    return false;
  }

  // One point of a visibility polygon: its angle from the viewpoint, and where along that ray it comes when the
  // ray meets a vertex and a farther wall (0: before the vertex, 1: the vertex, 2: after it).
  struct VisibilityEntry {
    double angle;
    int order;
    Vec2 point;
  };
  // The visibility polygon's points that ring vertex i (map vertex 'ref') gives from p: the vertex, and where
  // it is a tangent one, the farther wall the ray grazes on to.
  void VisitVertex(const Vec2& p, const Ring& ring, size_t i, bool check_visible, const core::VertexRef& ref,
                   std::vector<VisibilityEntry>* entries) const;
};

RayCaster::RayCaster(const core::World& world) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.world = world;
  m.rings = core::MapRings(m.world);
  for (size_t r = 0; r < m.rings.size(); ++r) {
    m.ring_is_boundary.push_back(m.world.has_boundary() && r == 0);
    const Ring& ring = *m.rings[r];
    for (size_t i = 0; i < ring.size(); ++i) {
      m.walls.push_back({ring[i], ring[(i + 1) % ring.size()]});
      m.wall_start.push_back({int(r), int(i)});
    }
  }
  RTCDevice dev = Device();
  m.scene = rtcNewScene(dev);
  struct SceneGuard {  // releases the scene if anything below throws
    Impl* m;
    bool armed = true;
    ~SceneGuard() {
      if (armed && m->scene) {
        rtcReleaseScene(m->scene);
        m->scene = nullptr;
      }
    }
  } guard{&m};
  rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST);
  auto attach = [&](const std::vector<core::Segment2>& segs, unsigned mask, unsigned expected_id) {
    std::vector<core::Segment2> s = segs;
    if (s.empty()) s.push_back({{1e7, 1e7}, {1e7 + 1, 1e7}});  // placeholder far away keeps ids stable
    RTCGeometry g = QuadGeometry(dev, s, mask);
    const unsigned id = rtcAttachGeometry(m.scene, g);
    rtcReleaseGeometry(g);
    TOPONAV_CHECK(id == expected_id, "unexpected Embree geometry id " << id);
  };
  attach(m.walls, kMaskWalls, 0);
  attach(ClutterSegments(m.world.clutter), kMaskClutter, 1);
  std::vector<core::Segment2> far;
  if (!m.world.has_boundary()) {
    const double g = 1000.0 + std::max(m.world.bounds.width(), m.world.bounds.height());
    const auto& b = m.world.bounds;
    m.far_rings.push_back({{b.min.x - g, b.min.y - g}, {b.max.x + g, b.min.y - g}, {b.max.x + g, b.max.y + g},
                           {b.min.x - g, b.max.y + g}});
    const Ring& r = m.far_rings[0];
    for (size_t i = 0; i < r.size(); ++i) far.push_back({r[i], r[(i + 1) % r.size()]});
  }
  attach(far, kMaskFar, 2);
  rtcCommitScene(m.scene);
  if (rtcGetDeviceError(dev) != RTC_ERROR_NONE)
    throw core::InternalError("Embree: building the scene failed (error " +
                              std::to_string(int(rtcGetDeviceError(dev))) + ")");
  guard.armed = false;
}

RayCaster::~RayCaster() {
  if (impl_ && impl_->scene) rtcReleaseScene(impl_->scene);
}

std::vector<VisibleVertex> RayCaster::VisibleVertices(const core::Pose2& pose, double max_range) const {
  const Impl& m = *impl_;
  const Vec2 p = pose.position();
  bool p_in_solid = m.world.has_boundary() && !core::Contains(m.world.boundary, p);
  for (const auto& o : m.world.obstacles) p_in_solid = p_in_solid || core::Contains(o, p);
  std::vector<VisibleVertex> out;
  for (size_t r = 0; r < m.rings.size(); ++r) {
    const Ring& ring = *m.rings[r];
    for (size_t i = 0; i < ring.size(); ++i) {
      const double range = core::Distance(p, ring[i]);
      if (!(range < max_range)) continue;
      const core::VertexRef ref{int(r), int(i)};
      if (!m.Sees(p, p_in_solid, ref)) continue;
      VisibleVertex v;
      v.ref = ref;
      v.position = ring[i];
      v.range = range;
      v.bearing = core::WrapAngle(std::atan2(ring[i].y - p.y, ring[i].x - p.x) - pose.yaw);
      out.push_back(v);
    }
  }
  std::sort(out.begin(), out.end(), [](const VisibleVertex& a, const VisibleVertex& b) {
    return a.bearing < b.bearing;
  });
  // Labels from angular neighbours: a wall joins two consecutive visible vertices when they are adjacent on
  // one ring and less than pi apart (vertexnav.md §3.1).
  const size_t n = out.size();
  auto joined = [&](const VisibleVertex& a, const VisibleVertex& b) {
    if (a.ref.ring != b.ref.ring) return false;
    const int len = int(m.rings[size_t(a.ref.ring)]->size());
    return (a.ref.index + 1) % len == b.ref.index || (b.ref.index + 1) % len == a.ref.index;
  };
  for (size_t i = 0; i < n && n > 1; ++i) {
    const VisibleVertex& ccw = out[(i + 1) % n];
    const VisibleVertex& cw = out[(i + n - 1) % n];
    const bool wall_ccw = Wrap2Pi(ccw.bearing - out[i].bearing) < core::kPi && joined(out[i], ccw);
    const bool wall_cw = Wrap2Pi(out[i].bearing - cw.bearing) < core::kPi && joined(out[i], cw);
    out[i].label = core::LabelFromWalls(wall_ccw, wall_cw);
  }
  return out;
}

void RayCaster::Impl::VisitVertex(const Vec2& p, const Ring& ring, size_t i, bool check_visible,
                                  const core::VertexRef& ref, std::vector<VisibilityEntry>* entries) const {
  const Vec2 v = ring[i];
  if (check_visible && !Sees(p, false, ref)) return;
  const double dist = core::Distance(p, v);
  if (dist < 1e-12) return;
  const Vec2 dir = (v - p) / dist;
  const double angle = std::atan2(dir.y, dir.x);
  const Vec2 prev = ring[(i + ring.size() - 1) % ring.size()];
  const Vec2 next = ring[(i + 1) % ring.size()];
  const double sa = core::Cross(dir, prev - v), sb = core::Cross(dir, next - v);
  if (!(sa * sb > 0)) {  // the ring continues on both sides of the ray: v itself is on the polygon
    entries->push_back({angle, 1, v});
    return;
  }
  // Tangent vertex: the ray grazes v and continues to a farther wall.
  // Hits on v's own walls are rounding noise at v: step over them.
  double tnear = dist * (1 + 1e-7) + 1e-7;
  Hit h;
  for (int guard = 0; guard < 16; ++guard) {
    h = Intersect(p, dir, tnear, std::numeric_limits<double>::infinity(), kMaskWalls | kMaskFar);
    if (!h.valid() || !IncidentToVertex(h, ref)) break;
    tnear = h.t * (1 + 1e-6) + 1e-6;
  }
  if (!h.valid()) {
    entries->push_back({angle, 1, v});
    return;
  }
  const core::Segment2 s = HitSegment(h);
  const double denom = core::Cross(dir, s.b - s.a);
  const double t = std::abs(denom) > 1e-15 ? core::Cross(s.a - p, s.b - s.a) / denom : h.t;
  const Vec2 far = p + dir * std::max(t, dist);
  // Ring edges on the counter-clockwise side of the ray: sweeping counter-clockwise meets the far wall first.
  if (sa > 0) {
    entries->push_back({angle, 0, far});
    entries->push_back({angle, 1, v});
  } else {
    entries->push_back({angle, 1, v});
    entries->push_back({angle, 2, far});
  }
}

Ring RayCaster::VisibilityPolygon(const Vec2& p) const {
  const Impl& m = *impl_;
  for (const auto& o : m.world.obstacles)
    if (core::Contains(o, p)) return o;
  if (m.world.has_boundary() && !core::Contains(m.world.boundary, p)) return {};
  using Entry = Impl::VisibilityEntry;
  std::vector<Entry> entries;
  for (size_t r = 0; r < m.rings.size(); ++r)
    for (size_t i = 0; i < m.rings[r]->size(); ++i) m.VisitVertex(p, *m.rings[r], i, true, {int(r), int(i)}, &entries);
  for (const auto& box : m.far_rings)
    for (size_t i = 0; i < box.size(); ++i) {
      // Far-box corners: visible unless a wall blocks the way.
      const Vec2 v = box[i];
      const double dist = core::Distance(p, v);
      if (m.Intersect(p, (v - p) / dist, 0.0, dist * (1 - 1e-9), kMaskWalls).valid()) continue;
      m.VisitVertex(p, box, i, false, {-1, int(i)}, &entries);
    }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.angle != b.angle ? a.angle < b.angle : a.order < b.order;
  });
  Ring poly;
  for (const auto& e : entries)
    if (poly.empty() || core::Distance(poly.back(), e.point) > 1e-12) poly.push_back(e.point);
  if (poly.size() > 1 && core::Distance(poly.front(), poly.back()) <= 1e-12) poly.pop_back();
  return poly;
}

double RayCaster::CastRay(const Vec2& origin, double angle, double max_range, bool include_clutter) const {
  const Impl::Hit h = impl_->Intersect(origin, {std::cos(angle), std::sin(angle)}, 0.0, max_range,
                                       kMaskWalls | (include_clutter ? kMaskClutter : 0u));
  return h.valid() ? std::min(h.t, max_range) : max_range;
}

std::vector<double> RayCaster::DepthScan(const core::Pose2& pose, int num_rays, double max_range,
                                         bool include_clutter) const {
  TOPONAV_CHECK(num_rays > 0, "num_rays " << num_rays);
  std::vector<RTCRayHit> rays(static_cast<size_t>(num_rays));
  const unsigned mask = kMaskWalls | (include_clutter ? kMaskClutter : 0u);
  for (int j = 0; j < num_rays; ++j) {
    const double a = pose.yaw + core::ColumnToBearing(j, num_rays);
    RTCRayHit& rh = rays[size_t(j)];
    rh.ray.org_x = float(pose.x);
    rh.ray.org_y = float(pose.y);
    rh.ray.org_z = 0.f;
    rh.ray.dir_x = float(std::cos(a));
    rh.ray.dir_y = float(std::sin(a));
    rh.ray.dir_z = 0.f;
    rh.ray.tnear = 0.f;
    rh.ray.tfar = float(max_range);
    rh.ray.mask = mask;
    rh.ray.flags = 0;
    rh.ray.time = 0.f;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect1M(impl_->scene, &ctx, rays.data(), unsigned(num_rays), sizeof(RTCRayHit));
  std::vector<double> out(static_cast<size_t>(num_rays));
  for (size_t j = 0; j < rays.size(); ++j)
    out[j] = rays[j].hit.geomID == RTC_INVALID_GEOMETRY_ID ? max_range : std::min(double(rays[j].ray.tfar), max_range);
  return out;
}

}  // namespace toponav::sim

namespace toponav::sim {
std::string RayCasterLibraryInfo() { return "Embree " RTC_VERSION_STRING; }
}  // namespace toponav::sim

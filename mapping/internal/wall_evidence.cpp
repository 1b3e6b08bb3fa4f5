#include "mapping/internal/wall_evidence.h"

#include <algorithm>
#include <cmath>

namespace toponav::mapping::internal {

using core::Vec2;

bool WallEvidence::OnSegment(const Vec2& p, const Vec2& a, const Vec2& b) const {
  return o_.wall_on_segment_tolerance > 0 && core::NearSegmentInterior(p, {a, b}, o_.wall_on_segment_tolerance);
}

std::vector<WallEvidence::FrontCandidate> WallEvidence::FrontCandidates(const Obs& ob,
                                                                         const VertexStore& vertices) const {
  std::vector<FrontCandidate> out;
  if (o_.wall_front_vertex_tolerance <= 0) return out;
  std::vector<int> detection(vertices.size(), -1);  // one detection a vertex at most (association is 1:1)
  for (size_t k = 0; k < ob.vid.size(); ++k) detection[size_t(ob.vid[k])] = int(k);
  const Vec2 p = ob.pose.position();
  for (size_t id = 0; id < vertices.size(); ++id)
    if (vertices.Seen(int(id)) && core::Distance(vertices.Pos(int(id)), p) < o_.max_range)
      out.push_back({int(id), detection[id]});
  return out;
}

void WallEvidence::AddFront(const Obs& ob, size_t i, size_t steps, const std::vector<FrontCandidate>& candidates,
                            const VertexStore& vertices, std::vector<int>* out) const {
  const double tol = o_.wall_front_vertex_tolerance;
  const size_t n = ob.det.size();
  const Vec2 p = ob.pose.position(), a = ob.at[i], b = ob.at[(i + steps) % n], ab = b - a;
  const double len = core::Norm(ab);
  if (len < 1e-9) return;
  const double pose_side = core::Cross(ab, p - a);
  for (const auto [id, det] : candidates) {
    // The pair's ends and the detections between them count already; a vertex detected out of bearing
    // order (outside the pair's interval, its map position in front) does not.
    if (det >= 0 && (size_t(det) + n - i) % n <= steps) continue;
    const Vec2 x = vertices.Pos(id);
    const double side = core::Cross(ab, x - a) / len;  // signed distance from the segment's line
    if (side * pose_side <= 0 || std::abs(side) <= tol) continue;
    if (core::Distance(x, a) <= tol || core::Distance(x, b) <= tol) continue;
    const bool in_wedge = core::Cross(a - p, x - p) >= 0 && core::Cross(x - p, b - p) >= 0;
    if (in_wedge || core::DistanceToSegment(x, {p, a}) < tol || core::DistanceToSegment(x, {p, b}) < tol)
      out->push_back(id);
  }
}

// Every pair less than pi apart, R = i and L = j counter-clockwise of it; each detection between them scales
// the evidence by wall_skip_damping (vertexnav.md §2.4) -- except, beyond the reference, a detection lying on
// the segment between the two (within wall_on_segment_tolerance) damps it only while its vertex is in the
// map: a false detection on a wall that the map rejects does not hide the wall, while a doorway's jamb on the
// line does once it is mapped, and such a pair's evidence needs both ends to say a wall runs on
// (wall_past_detection_min).  A sample whose observation missed a vertex lying between its pose and the
// segment (wall_front_vertex_tolerance) does not count while that vertex is in the map: seen along a wall
// edge-on, the wall's far end shows just past its near corner, and when the sensor misses that corner, the
// far end and the corner's other neighbour are a pair across the solid corner.
void WallEvidence::Add(const Obs& ob, const VertexStore& vertices) {
  const size_t n = ob.det.size(), num_vertices = vertices.size();
  const std::vector<Vec2>& at = ob.at;
  const std::vector<FrontCandidate> candidates = FrontCandidates(ob, vertices);
  if (spans_.size() < num_vertices) spans_.resize(num_vertices);
  if (neighbours_.size() < num_vertices) neighbours_.resize(num_vertices);
  for (size_t i = 0; i < n; ++i) {
    for (size_t s = 1; s < n; ++s) {
      const size_t j = (i + s) % n;
      if (Wrap2Pi(ob.det[j].bearing - ob.det[i].bearing) >= core::kPi) break;
      const int a = ob.vid[i], b = ob.vid[j];
      if (a == b || Wrap2Pi(ob.det[j].bearing - ob.det[i].bearing) < o_.wall_min_view_angle) continue;
      int fixed = 0;
      CondSample c;
      for (size_t t = 1; t < s; ++t) {
        const size_t k = (i + t) % n;
        if (ob.vid[k] != a && ob.vid[k] != b && OnSegment(at[k], at[i], at[j])) c.damping.push_back(ob.vid[k]);
        else ++fixed;
      }
      AddFront(ob, i, s, candidates, vertices, &c.front);
      const uint64_t key = WallKey(a, b);
      Stats& w = walls_[key];
      if (w.count == 0) {
        neighbours_[size_t(a)].push_back(b);
        neighbours_[size_t(b)].push_back(a);
      }
      w.count += 1;
      const double no_i = core::NoWallCcw(ob.det[i].labels), no_j = core::NoWallCw(ob.det[j].labels);
      // Past a detection both ends must say wall (closed worlds: open-world buildings have no doorways).
      const bool both =
          !o_.open_region && (o_.wall_evidence_min || (!c.damping.empty() && o_.wall_past_detection_min));
      c.value = std::pow(o_.wall_skip_damping, double(fixed)) *
                (both ? 1.0 - std::max(no_i, no_j) : 1.0 - 0.5 * (no_i + no_j));
      if (c.front.empty() && (c.damping.empty() || c.value < 1e-9)) {
        w.sum += c.value;
        continue;
      }
      for (const auto* ids : {&c.damping, &c.front})
        for (int id : *ids) {
          auto& sp = spans_[size_t(id)];
          if (std::find(sp.begin(), sp.end(), key) == sp.end()) sp.push_back(key);
        }
      w.cond.push_back(std::move(c));
    }
  }
}

double WallEvidence::Prob(int a, int b, const std::vector<char>& mapped, int flip, bool flip_on) const {
  auto it = walls_.find(WallKey(a, b));
  if (it == walls_.end()) return 0.0;
  const Stats& w = it->second;
  auto in_map = [&](int id) { return id == flip ? flip_on : (size_t(id) < mapped.size() && mapped[size_t(id)]); };
  double sum = w.sum;
  int count = w.count;
  for (const auto& c : w.cond) {
    if (std::any_of(c.front.begin(), c.front.end(), in_map)) {
      --count;
      continue;
    }
    const auto damp = std::count_if(c.damping.begin(), c.damping.end(), in_map);
    sum += c.value * std::pow(o_.wall_skip_damping, double(damp));
  }
  return sum / (count + 1);  // shrinks one sighting to 1/2
}

std::vector<Wall> WallEvidence::MappedWalls(const std::vector<char>& mapped) const {
  std::vector<Wall> out;
  for (const auto& [key, w] : walls_) {
    const auto [a, b] = WallEnds(key);
    if (mapped[size_t(a)] && mapped[size_t(b)] && Prob(a, b, mapped) > o_.wall_threshold) out.push_back({a, b});
  }
  std::sort(out.begin(), out.end());
  return out;
}

MapState WallEvidence::State(const VertexStore& vertices) const {
  MapState ms;
  ms.mapped.resize(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) ms.num_vertices += ms.mapped[i] = vertices.Mapped(int(i));
  ms.walls = MappedWalls(ms.mapped);
  for (const auto& w : ms.walls) ms.wall_keys.insert(WallKey(w.first, w.second));
  return ms;
}

std::vector<Wall> WallEvidence::ChangedWalls(int i, const MapState& ms) const {
  std::vector<Wall> out;
  const bool on = !ms.mapped[size_t(i)];
  for (int j : neighbours_[size_t(i)])
    if (ms.mapped[size_t(j)] && Prob(i, j, ms.mapped, i, on) > o_.wall_threshold)
      out.push_back({std::min(i, j), std::max(i, j)});
  if (size_t(i) < spans_.size())
    for (uint64_t key : spans_[size_t(i)]) {
      const auto [a, b] = WallEnds(key);
      if (a == i || b == i || !ms.mapped[size_t(a)] || !ms.mapped[size_t(b)]) continue;
      const bool now = Prob(a, b, ms.mapped) > o_.wall_threshold;
      const bool then = Prob(a, b, ms.mapped, i, on) > o_.wall_threshold;
      if (now != then) out.push_back({a, b});
    }
  return out;
}

void WallEvidence::SetMapped(int i, bool on, MapState* ms) const {
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

}  // namespace toponav::mapping::internal

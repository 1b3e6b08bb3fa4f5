#include "mapping/internal/stars.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace toponav::mapping::internal {

using core::BoxHitsSegment;
using core::Vec2;

core::Ring RealStar(const MapCore& m, const Obs& ob) {
  std::vector<StarPoint> pts;
  for (size_t k = 0; k < ob.vid.size(); ++k)
    pts.push_back({m.Pos(ob.vid[k]), core::NoWallCcw(ob.det[k].labels) > 0.5, core::NoWallCw(ob.det[k].labels) > 0.5});
  if (!m.o.open_region) {
    for (auto& p : pts) p.open_ccw = p.open_cw = false;
    return OpenStarPolygon(ob.pose.position(), pts, OpenSpace{});
  }
  return OpenStarPolygon(ob.pose.position(), pts, OpenSpace{*m.o.open_region, m.o.max_range, kOpenSampleStep, {}});
}

void RefreshStar(MapCore* m, size_t i) {
  Obs& ob = m->obs[i];
  std::vector<Vec2> pts;
  for (int id : ob.vid) pts.push_back(m->Pos(id));
  ob.star = RealStar(*m, ob);
  ob.star_src = pts;
  ob.box = ob.star.empty() ? core::Aabb2{ob.pose.position(), ob.pose.position()} : core::Bounds(ob.star);
  ob.box = core::Bounds(std::vector<Vec2>{ob.pose.position()}, ob.box);
}

// Rebuilds star polygons whose vertices moved more than the tolerance.
void RefreshStars(MapCore* m, double tolerance) {
  for (size_t i = 0; i < m->obs.size(); ++i) {
    const Obs& ob = m->obs[i];
    bool moved = false;
    for (size_t k = 0; k < ob.vid.size() && !moved; ++k)
      moved = core::Distance(m->Pos(ob.vid[k]), ob.star_src[k]) > tolerance;
    if (moved) RefreshStar(m, i);
  }
}

namespace {

// True if an observation was made inside the polygon of the chain of vertices 'chain' closed between its
// ends: no one stands inside a building, so such a chain is a recess seen from within, not a building.
bool EnclosesAPose(const MapCore& m, const std::vector<int>& chain) {
  core::Ring ring;
  for (int id : chain) ring.push_back(m.Pos(id));
  const core::Aabb2 box = core::Bounds(ring);
  for (const Obs& ob : m.obs)
    if (box.Contains(ob.pose.position()) && core::Contains(ring, ob.pose.position())) return true;
  return false;
}

}  // namespace

std::vector<Wall> ClosingWalls(const MapCore& m, const MapState& ms) {
  std::vector<Wall> out;
  if (!m.o.open_region) return out;
  std::unordered_map<int, std::vector<int>> adj;
  for (const auto& w : ms.walls) {
    adj[w.first].push_back(w.second);
    adj[w.second].push_back(w.first);
  }
  std::unordered_set<int> seen;
  for (const auto& [start, nb] : adj) {
    if (nb.size() != 1 || seen.count(start)) continue;
    // Walk the chain from this end; it is a simple chain if every inner vertex has two walls.
    int prev = -1, cur = start, length = 0;
    bool simple = true;
    seen.insert(cur);
    std::vector<int> chain{cur};
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
      chain.push_back(cur);
      if (adj.at(cur).size() == 1) break;
    }
    if (simple && length >= 2 && adj.at(cur).size() == 1 && !EnclosesAPose(m, chain))
      out.push_back({std::min(start, cur), std::max(start, cur)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

core::Ring HypotheticalStar(const MapCore& m, const Obs& ob, const std::vector<int>& H, const MapState& ms,
                            const std::vector<Wall>& closing, std::vector<uint64_t>* hit_walls) {
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
    StarPoint sp{m.Pos(id), bool(m.o.open_region), bool(m.o.open_region)};
    std::vector<int> others;
    for (int j : m.walls.Neighbours(id))
      if (ms.HasWall(id, j)) others.push_back(j);
    if (const auto it = extra.find(id); it != extra.end())
      others.insert(others.end(), it->second.begin(), it->second.end());
    for (int j : others) {
      const double side = core::Cross(sp.p - c, m.Pos(j) - sp.p);
      if (side >= 0) sp.open_ccw = false;
      if (side <= 0) sp.open_cw = false;
    }
    pts.push_back(sp);
  }
  if (!m.o.open_region) return OpenStarPolygon(c, pts, OpenSpace{});
  OpenSpace space{*m.o.open_region, m.o.max_range, kOpenSampleStep, {}};
  const core::Aabb2 reach{c - Vec2{m.o.max_range, m.o.max_range}, c + Vec2{m.o.max_range, m.o.max_range}};
  std::vector<uint64_t> keys;
  for (const auto* list : {&ms.walls, &closing})
    for (const auto& w : *list)
      if (BoxHitsSegment(reach, m.Pos(w.first), m.Pos(w.second), 0.0)) {
        space.blockers.push_back({m.Pos(w.first), m.Pos(w.second)});
        keys.push_back(WallKey(w.first, w.second) ^ (list == &closing ? (uint64_t(1) << 63) : 0));
      }
  std::vector<int> hit;
  core::Ring ring = OpenStarPolygon(c, pts, space, &hit);
  for (int k : hit) hit_walls->push_back(keys[size_t(k)]);
  // The polygon also depends on which sides of each vertex are open: part of what it was built from.
  for (const auto& p : pts)
    hit_walls->push_back((uint64_t(0xF) << 60) | (uint64_t(p.open_ccw) << 1) | uint64_t(p.open_cw));
  return ring;
}

}  // namespace toponav::mapping::internal

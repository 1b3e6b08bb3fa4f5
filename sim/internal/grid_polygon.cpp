#include "sim/internal/grid_polygon.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"

namespace toponav::sim::internal {

using core::Ring;
using core::Vec2;

std::vector<Ring> TraceFreeRegion(const std::vector<double>& xs, const std::vector<double>& ys,
                                  const std::vector<char>& free) {
  const int nx = int(xs.size()) - 1, ny = int(ys.size()) - 1;
  TOPONAV_CHECK(nx > 0 && ny > 0 && free.size() == size_t(nx) * size_t(ny), "grid size mismatch");
  auto is_free = [&](int ix, int iy) {
    return ix >= 0 && iy >= 0 && ix < nx && iy < ny && free[size_t(iy) * nx + ix];
  };
  // Directed boundary edges between integer grid corners, free cell on the left.
  using Corner = std::pair<int, int>;
  std::multimap<Corner, Corner> edges;
  for (int iy = 0; iy < ny; ++iy)
    for (int ix = 0; ix < nx; ++ix) {
      if (!is_free(ix, iy)) continue;
      if (!is_free(ix, iy - 1)) edges.insert({{ix, iy}, {ix + 1, iy}});
      if (!is_free(ix + 1, iy)) edges.insert({{ix + 1, iy}, {ix + 1, iy + 1}});
      if (!is_free(ix, iy + 1)) edges.insert({{ix + 1, iy + 1}, {ix, iy + 1}});
      if (!is_free(ix - 1, iy)) edges.insert({{ix, iy + 1}, {ix, iy}});
    }
  std::vector<Ring> rings;
  while (!edges.empty()) {
    auto it = edges.begin();
    const Corner first = it->first;
    Corner prev = it->first, cur = it->second;
    edges.erase(it);
    std::vector<Corner> corners{first};
    while (cur != first) {
      corners.push_back(cur);
      auto range = edges.equal_range(cur);
      TOPONAV_CHECK(range.first != range.second, "open boundary chain at grid corner");
      // At a pinch corner (two outgoing edges) turn left, which keeps diagonal free cells apart.
      auto pick = range.first;
      if (std::next(range.first) != range.second) {
        const int dx = cur.first - prev.first, dy = cur.second - prev.second;
        for (auto e = range.first; e != range.second; ++e) {
          const int ex = e->second.first - cur.first, ey = e->second.second - cur.second;
          if (dx * ey - dy * ex > 0) pick = e;
        }
      }
      prev = cur;
      cur = pick->second;
      edges.erase(pick);
    }
    Ring ring;
    for (const auto& c : corners) ring.push_back({xs[size_t(c.first)], ys[size_t(c.second)]});
    rings.push_back(core::RemoveCollinear(ring));
  }
  return rings;
}

bool SplitBoundaryAndObstacles(std::vector<Ring> rings, Ring* boundary, std::vector<Ring>* obstacles) {
  boundary->clear();
  obstacles->clear();
  for (auto& r : rings) {
    if (core::SignedArea(r) > 0) {
      if (!boundary->empty()) return false;  // a second outer ring: free space is not connected
      *boundary = std::move(r);
    } else {
      core::Reverse(r);
      obstacles->push_back(std::move(r));
    }
  }
  return !boundary->empty();
}

int CountComponents(int nx, int ny, const std::vector<char>& free) {
  std::vector<int> label(free.size(), -1);
  int count = 0;
  std::vector<int> stack;
  for (int start = 0; start < nx * ny; ++start) {
    if (!free[size_t(start)] || label[size_t(start)] >= 0) continue;
    stack.push_back(start);
    label[size_t(start)] = count;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int cx = c % nx, cy = c / nx;
      const int nb[4][2] = {{cx + 1, cy}, {cx - 1, cy}, {cx, cy + 1}, {cx, cy - 1}};
      for (const auto& n : nb) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= nx || n[1] >= ny) continue;
        const int k = n[1] * nx + n[0];
        if (free[size_t(k)] && label[size_t(k)] < 0) {
          label[size_t(k)] = count;
          stack.push_back(k);
        }
      }
    }
    ++count;
  }
  return count;
}

}  // namespace toponav::sim::internal

#include "planning/raster.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "core/error.h"

namespace toponav::planning {

using core::Vec2;

Raster Raster::Covering(const core::Aabb2& box, double cell, double margin) {
  TOPONAV_CHECK(cell > 0 && margin >= 0, "raster cell " << cell << ", margin " << margin);
  Raster r;
  r.cell = cell;
  r.origin = box.min - Vec2{margin, margin};
  r.width = std::max(1, int(std::ceil((box.max.x - box.min.x + 2 * margin) / cell)));
  r.height = std::max(1, int(std::ceil((box.max.y - box.min.y + 2 * margin) / cell)));
  TOPONAV_CHECK(r.size() <= size_t(1) << 26, "a raster of " << r.width << " x " << r.height << " cells");
  return r;
}

int Raster::CellOf(const Vec2& p) const {
  const int x = int(std::floor((p.x - origin.x) / cell)), y = int(std::floor((p.y - origin.y) / cell));
  return x < 0 || y < 0 || x >= width || y >= height ? -1 : Index(x, y);
}

Vec2 Raster::Center(int index) const {
  return origin + Vec2{(index % width + 0.5) * cell, (index / width + 0.5) * cell};
}

std::vector<char> FillPolygons(const Raster& r, const std::vector<core::Polygon>& polygons) {
  std::vector<char> out(r.size(), 0);
  std::vector<const core::Ring*> rings;
  for (const auto& p : polygons) {
    rings.push_back(&p.outer);
    for (const auto& h : p.holes) rings.push_back(&h);
  }
  std::vector<double> xs;
  for (int y = 0; y < r.height; ++y) {
    const double yc = r.origin.y + (y + 0.5) * r.cell;
    xs.clear();
    for (const core::Ring* ring : rings)
      for (size_t i = 0, n = ring->size(); i < n; ++i) {
        const Vec2 p = (*ring)[i], q = (*ring)[(i + 1) % n];
        if ((p.y > yc) != (q.y > yc)) xs.push_back(p.x + (yc - p.y) * (q.x - p.x) / (q.y - p.y));
      }
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      // Cells whose centre x lies in [xs[k], xs[k+1]).
      const int x0 = std::max(0, int(std::ceil((xs[k] - r.origin.x) / r.cell - 0.5)));
      const int x1 = std::min(r.width - 1, int(std::ceil((xs[k + 1] - r.origin.x) / r.cell - 0.5)) - 1);
      for (int x = x0; x <= x1; ++x) out[size_t(r.Index(x, y))] = 1;
    }
  }
  return out;
}

std::vector<int> CellsNear(const Raster& r, const std::vector<Vec2>& polyline, double radius) {
  std::vector<char> mark(r.size(), 0);
  std::vector<int> out;
  for (size_t i = 0; i < polyline.size(); ++i) {
    const core::Segment2 s{polyline[i], polyline[i + 1 < polyline.size() ? i + 1 : i]};
    const core::Aabb2 box = core::SegmentBox(s.a, s.b);
    const int x0 = std::max(0, int(std::floor((box.min.x - radius - r.origin.x) / r.cell)));
    const int x1 = std::min(r.width - 1, int(std::floor((box.max.x + radius - r.origin.x) / r.cell)));
    const int y0 = std::max(0, int(std::floor((box.min.y - radius - r.origin.y) / r.cell)));
    const int y1 = std::min(r.height - 1, int(std::floor((box.max.y + radius - r.origin.y) / r.cell)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const int c = r.Index(x, y);
        if (!mark[size_t(c)] && core::DistanceToSegment(r.Center(c), s) <= radius) {
          mark[size_t(c)] = 1;
          out.push_back(c);
        }
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<double> CellDistances(const Raster& r, const std::vector<char>& passable, const std::vector<int>& sources,
                                  const std::vector<int>* until) {
  TOPONAV_CHECK(passable.size() == r.size(), "passable mask of " << passable.size() << " for " << r.size() << " cells");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(r.size(), kInf);
  std::vector<char> wanted;  // the cells of 'until' not settled yet
  size_t left = 0;
  if (until) {
    wanted.assign(r.size(), 0);
    for (int c : *until)
      if (c >= 0 && size_t(c) < r.size() && !wanted[size_t(c)]) wanted[size_t(c)] = 1, ++left;
  }
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  for (int s : sources)
    if (s >= 0 && size_t(s) < r.size() && passable[size_t(s)] && dist[size_t(s)] > 0) {
      dist[size_t(s)] = 0;
      open.push({0.0, s});
    }
  const double straight = r.cell, diagonal = r.cell * std::sqrt(2.0);
  const auto ok = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < r.width && y < r.height && passable[size_t(r.Index(x, y))];
  };
  while (!open.empty()) {
    const auto [d, c] = open.top();
    open.pop();
    if (d > dist[size_t(c)]) continue;  // a cell is settled at its first pop: pushes need a strictly shorter way
    if (until && wanted[size_t(c)] && (wanted[size_t(c)] = 0, --left == 0)) break;
    const int x = c % r.width, y = c / r.width;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !ok(x + dx, y + dy)) continue;
        if (dx != 0 && dy != 0 && !(ok(x + dx, y) && ok(x, y + dy))) continue;
        const int n = r.Index(x + dx, y + dy);
        const double nd = d + (dx != 0 && dy != 0 ? diagonal : straight);
        if (nd < dist[size_t(n)]) {
          dist[size_t(n)] = nd;
          open.push({nd, n});
        }
      }
  }
  return dist;
}

}  // namespace toponav::planning

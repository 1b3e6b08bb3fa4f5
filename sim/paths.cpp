#include "sim/paths.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "core/error.h"

namespace toponav::sim {

using core::Vec2;

std::vector<Vec2> FreePath(const core::World& w, const Vec2& from, const Vec2& to, double clearance, double cell) {
  TOPONAV_CHECK(cell > 0, "cell " << cell);
  const core::Aabb2& b = w.bounds;
  const int nx = int(std::ceil(b.width() / cell)) + 1, ny = int(std::ceil(b.height() / cell)) + 1;
  TOPONAV_CHECK(double(nx) * ny < 4e6, "grid too fine: " << nx << " x " << ny);
  auto centre = [&](int i, int j) { return Vec2{b.min.x + i * cell, b.min.y + j * cell}; };
  auto index_of = [&](const Vec2& p) {
    const int i = std::clamp(int(std::lround((p.x - b.min.x) / cell)), 0, nx - 1);
    const int j = std::clamp(int(std::lround((p.y - b.min.y) / cell)), 0, ny - 1);
    return j * nx + i;
  };
  std::vector<char> ok(size_t(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p = centre(i, j);
      ok[size_t(j) * nx + i] = core::IsFree(w, p) && core::SignedDistance(w, p) >= clearance;
    }
  const int s = index_of(from), t = index_of(to);
  if (!ok[size_t(s)] || !ok[size_t(t)]) return {};
  // Dijkstra on the 8-connected grid (A* would save little at these sizes).
  std::vector<double> dist(ok.size(), std::numeric_limits<double>::infinity());
  std::vector<int> parent(ok.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[size_t(s)] = 0;
  open.push({0, s});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[size_t(u)]) continue;
    if (u == t) break;
    const int ui = u % nx, uj = u / nx;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int vi = ui + di, vj = uj + dj;
        if ((di == 0 && dj == 0) || vi < 0 || vj < 0 || vi >= nx || vj >= ny) continue;
        const int v = vj * nx + vi;
        if (!ok[size_t(v)]) continue;
        if (di != 0 && dj != 0 && (!ok[size_t(uj * nx + vi)] || !ok[size_t(vj * nx + ui)])) continue;
        const double nd = d + cell * std::hypot(di, dj);
        if (nd < dist[size_t(v)]) {
          dist[size_t(v)] = nd;
          parent[size_t(v)] = u;
          open.push({nd, v});
        }
      }
  }
  if (parent[size_t(t)] < 0 && s != t) return {};
  std::vector<int> cells;
  for (int v = t; v != -1; v = parent[size_t(v)]) cells.insert(cells.begin(), v);
  std::vector<Vec2> path{from};
  for (size_t k = 1; k + 1 < cells.size(); ++k) {
    const int a = cells[k - 1], c = cells[k], n = cells[k + 1];
    if ((c - a) != (n - c)) path.push_back(centre(c % nx, c / nx));  // keep only turning cells
  }
  path.push_back(to);
  return path;
}

std::vector<core::Pose2> PosesAlong(const std::vector<Vec2>& path, int count) {
  TOPONAV_CHECK(count >= 1 && !path.empty(), "PosesAlong(" << path.size() << " points, " << count << ")");
  std::vector<double> cum{0.0};
  for (size_t i = 1; i < path.size(); ++i) cum.push_back(cum.back() + core::Distance(path[i - 1], path[i]));
  std::vector<core::Pose2> poses;
  for (int k = 0; k < count; ++k) {
    const double s = count == 1 ? 0.0 : cum.back() * k / (count - 1);
    size_t i = 1;
    while (i + 1 < path.size() && cum[i] < s) ++i;
    if (path.size() == 1) {
      poses.push_back({path[0].x, path[0].y, 0.0});
      continue;
    }
    const double seg = cum[i] - cum[i - 1];
    const double f = seg > 0 ? std::clamp((s - cum[i - 1]) / seg, 0.0, 1.0) : 0.0;
    const Vec2 p = path[i - 1] + (path[i] - path[i - 1]) * f;
    poses.push_back({p.x, p.y, std::atan2(path[i].y - path[i - 1].y, path[i].x - path[i - 1].x)});
  }
  return poses;
}

}  // namespace toponav::sim

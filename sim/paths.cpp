#include "sim/paths.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "core/error.h"

namespace toponav::sim {

using core::Vec2;

namespace {

// An 8-connected grid over the world's bounds marking cells whose centre keeps the clearance.
struct ClearGrid {
  core::Aabb2 b;
  double cell = 1.0;
  int nx = 0, ny = 0;
  std::vector<char> ok;

  ClearGrid(const core::World& w, double clearance, double cell_size) : b(w.bounds), cell(cell_size) {
    TOPONAV_CHECK(cell > 0, "cell " << cell);
    nx = int(std::ceil(b.width() / cell)) + 1;
    ny = int(std::ceil(b.height() / cell)) + 1;
    TOPONAV_CHECK(double(nx) * ny < 4e6, "grid too fine: " << nx << " x " << ny);
    ok.resize(size_t(nx) * ny);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec2 p = Centre(j * nx + i);
        ok[size_t(j) * nx + i] = core::IsFree(w, p) && core::SignedDistance(w, p) >= clearance;
      }
  }
  Vec2 Centre(int c) const { return {b.min.x + (c % nx) * cell, b.min.y + (c / nx) * cell}; }
  int IndexOf(const Vec2& p) const {
    const int i = std::clamp(int(std::lround((p.x - b.min.x) / cell)), 0, nx - 1);
    const int j = std::clamp(int(std::lround((p.y - b.min.y) / cell)), 0, ny - 1);
    return j * nx + i;
  }
  // Dijkstra from cell s (stops early at 'target' if given): distances and parents.
  void Search(int s, int target, std::vector<double>* dist, std::vector<int>* parent) const {
    dist->assign(ok.size(), std::numeric_limits<double>::infinity());
    parent->assign(ok.size(), -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
    (*dist)[size_t(s)] = 0;
    open.push({0, s});
    while (!open.empty()) {
      const auto [d, u] = open.top();
      open.pop();
      if (d > (*dist)[size_t(u)]) continue;
      if (u == target) break;
      const int ui = u % nx, uj = u / nx;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int vi = ui + di, vj = uj + dj;
          if ((di == 0 && dj == 0) || vi < 0 || vj < 0 || vi >= nx || vj >= ny) continue;
          const int v = vj * nx + vi;
          if (!ok[size_t(v)]) continue;
          if (di != 0 && dj != 0 && (!ok[size_t(uj * nx + vi)] || !ok[size_t(vj * nx + ui)])) continue;
          const double nd = d + cell * std::hypot(di, dj);
          if (nd < (*dist)[size_t(v)]) {
            (*dist)[size_t(v)] = nd;
            (*parent)[size_t(v)] = u;
            open.push({nd, v});
          }
        }
    }
  }
  // Cell centres from s to t (parents from a search started at s), with straight runs merged.
  std::vector<Vec2> Trace(int t, const std::vector<int>& parent) const {
    std::vector<int> cells;
    for (int v = t; v != -1; v = parent[size_t(v)]) cells.insert(cells.begin(), v);
    std::vector<Vec2> path;
    for (size_t k = 0; k < cells.size(); ++k) {
      const bool turn = k == 0 || k + 1 == cells.size() || (cells[k] - cells[k - 1]) != (cells[k + 1] - cells[k]);
      if (turn) path.push_back(Centre(cells[k]));
    }
    return path;
  }
};

}  // namespace

std::vector<Vec2> FreePath(const core::World& w, const Vec2& from, const Vec2& to, double clearance, double cell) {
  const ClearGrid g(w, clearance, cell);
  const int s = g.IndexOf(from), t = g.IndexOf(to);
  if (!g.ok[size_t(s)] || !g.ok[size_t(t)]) return {};
  std::vector<double> dist;
  std::vector<int> parent;
  g.Search(s, t, &dist, &parent);
  if (!std::isfinite(dist[size_t(t)])) return {};
  std::vector<Vec2> path = g.Trace(t, parent);
  path.front() = from;
  path.back() = to;
  return path;
}

std::vector<Vec2> CoverageTour(const core::World& w, const Vec2& from, double spacing, double clearance,
                               double cell) {
  const ClearGrid g(w, clearance, cell);
  int cur = g.IndexOf(from);
  if (!g.ok[size_t(cur)]) return {};
  std::vector<int> targets;
  for (double y = w.bounds.min.y + spacing / 2; y < w.bounds.max.y; y += spacing)
    for (double x = w.bounds.min.x + spacing / 2; x < w.bounds.max.x; x += spacing) {
      const int c = g.IndexOf({x, y});
      if (g.ok[size_t(c)]) targets.push_back(c);
    }
  std::vector<Vec2> tour{from};
  std::vector<double> dist;
  std::vector<int> parent;
  while (!targets.empty()) {
    g.Search(cur, -1, &dist, &parent);
    size_t best = targets.size();
    for (size_t k = 0; k < targets.size(); ++k)
      if (std::isfinite(dist[size_t(targets[k])]) &&
          (best == targets.size() || dist[size_t(targets[k])] < dist[size_t(targets[best])]))
        best = k;
    if (best == targets.size()) break;  // the rest is unreachable
    const std::vector<Vec2> leg = g.Trace(targets[best], parent);
    tour.insert(tour.end(), leg.begin() + 1, leg.end());
    cur = targets[best];
    targets.erase(targets.begin() + long(best));
  }
  return tour;
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

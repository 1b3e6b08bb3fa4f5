#include <algorithm>
#include <cmath>
#include <limits>

#include "mapping/mapping.h"

namespace toponav::mapping {

using core::Vec2;

core::Ring StarPolygon(const Vec2& center, const std::vector<Vec2>& points) {
  struct Polar {
    double angle, range;
    Vec2 p;
  };
  std::vector<Polar> pts;
  for (const auto& p : points) {
    const double r = core::Distance(p, center);
    if (r < 1e-9) continue;
    pts.push_back({std::atan2(p.y - center.y, p.x - center.x), r, p});
  }
  std::sort(pts.begin(), pts.end(), [](const Polar& a, const Polar& b) {
    return a.angle != b.angle ? a.angle < b.angle : a.range < b.range;
  });
  // Same bearing: keep the nearest (the conservative choice; a spike would not be a simple polygon).
  std::vector<Polar> uniq;
  for (const auto& p : pts)
    if (uniq.empty() || p.angle - uniq.back().angle > 1e-12) uniq.push_back(p);
  if (uniq.size() > 1 && uniq.front().angle + 2 * core::kPi - uniq.back().angle <= 1e-12) {
    if (uniq.back().range < uniq.front().range) uniq.front() = uniq.back();  // same bearing across -pi/pi
    uniq.pop_back();
  }
  if (uniq.size() < 2) return {};
  core::Ring ring;
  for (size_t i = 0; i < uniq.size(); ++i) {
    ring.push_back(uniq[i].p);
    const double next = i + 1 < uniq.size() ? uniq[i + 1].angle : uniq[0].angle + 2 * core::kPi;
    if (next - uniq[i].angle >= core::kPi) ring.push_back(center);
  }
  if (std::abs(core::SignedArea(ring)) < 1e-12) return {};
  return ring;
}

std::vector<int> SolveAssignment(const std::vector<std::vector<double>>& a) {
  // Hungarian algorithm (potentials, O(n^2 m)) for n rows <= m columns.
  const int n = int(a.size());
  if (n == 0) return {};
  const int m = int(a[0].size());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(size_t(n) + 1, 0), v(size_t(m) + 1, 0), minv(size_t(m) + 1);
  std::vector<int> p(size_t(m) + 1, 0), way(size_t(m) + 1, 0);
  std::vector<char> used(size_t(m) + 1);
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::fill(minv.begin(), minv.end(), inf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[size_t(j0)] = 1;
      const int i0 = p[size_t(j0)];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[size_t(j)]) continue;
        const double cur = a[size_t(i0 - 1)][size_t(j - 1)] - u[size_t(i0)] - v[size_t(j)];
        if (cur < minv[size_t(j)]) {
          minv[size_t(j)] = cur;
          way[size_t(j)] = j0;
        }
        if (minv[size_t(j)] < delta) {
          delta = minv[size_t(j)];
          j1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (used[size_t(j)]) {
          u[size_t(p[size_t(j)])] += delta;
          v[size_t(j)] -= delta;
        } else {
          minv[size_t(j)] -= delta;
        }
      }
      j0 = j1;
    } while (p[size_t(j0)] != 0);
    do {
      const int j1 = way[size_t(j0)];
      p[size_t(j0)] = p[size_t(j1)];
      j0 = j1;
    } while (j0);
  }
  std::vector<int> col(size_t(n), -1);
  for (int j = 1; j <= m; ++j)
    if (p[size_t(j)] != 0) col[size_t(p[size_t(j)] - 1)] = j - 1;
  return col;
}

}  // namespace toponav::mapping

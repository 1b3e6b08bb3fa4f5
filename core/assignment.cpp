#include "core/assignment.h"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace toponav::core {

using std::size_t;

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

}  // namespace toponav::core

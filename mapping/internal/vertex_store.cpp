#include "mapping/internal/vertex_store.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/assignment.h"

namespace toponav::mapping::internal {

// Association: rows = detections, columns = gated candidate vertices + one "new vertex" slot per detection.
// Cost = squared Mahalanobis distance of the innovation (covariance P + R), plus a bias towards well-supported
// vertices; a new vertex costs the gate itself.  The assignment is one-to-one: no two detections of one
// observation share a vertex.  Returns the vertex of each detection, -1 for a new one.
std::vector<int> VertexStore::Associate(const std::vector<Eigen::Vector2d>& z,
                                        const std::vector<Eigen::Matrix2d>& R) const {
  const size_t n = z.size();
  std::vector<int> cand;
  std::unordered_map<int, int> col_of;
  std::vector<std::vector<std::pair<int, double>>> gated(n);
  for (size_t k = 0; k < n; ++k) {
    for (size_t i = 0; i < v_.size(); ++i) {
      const Eigen::Matrix2d S = v_[i].P + R[k];
      const Eigen::Vector2d e = z[k] - v_[i].x;
      // Cheap rejection: m^2 >= |e|^2 / lambda_max(S) >= |e|^2 / trace(S).
      if (e.squaredNorm() > o_.association_gate_chi2 * S.trace()) continue;
      const double m2 = e.dot(S.ldlt().solve(e));
      if (m2 < o_.association_gate_chi2) {
        if (!col_of.count(int(i))) {
          col_of[int(i)] = int(cand.size());
          cand.push_back(int(i));
        }
        gated[k].push_back({int(i), m2});
      }
    }
  }
  std::vector<int> vid(n, -1);
  if (n == 0) return vid;
  const double big = 1e9;
  std::vector<std::vector<double>> cost(n, std::vector<double>(cand.size() + n, big));
  for (size_t k = 0; k < n; ++k) {
    // Among the gated vertices, one with fewer detections than the best-supported one pays
    // association_count_bias * ln(ratio), kept below the gate (joining still beats a new vertex): a duplicate
    // born beside a vertex (a false detection next to it) starves instead of taking half of its detections,
    // which would leave both out of the map.
    int most = 1;
    for (const auto& g : gated[k]) most = std::max(most, v_[size_t(g.first)].n);
    for (const auto& [vi, m2] : gated[k]) {
      const double penalty = o_.association_count_bias * std::log(double(most) / std::max(1, v_[size_t(vi)].n));
      cost[k][size_t(col_of.at(vi))] = std::min(m2 + penalty, 0.999 * o_.association_gate_chi2);
    }
    cost[k][cand.size() + k] = o_.association_gate_chi2;
  }
  const std::vector<int> col = core::SolveAssignment(cost);
  for (size_t k = 0; k < n; ++k)
    if (col[k] >= 0 && size_t(col[k]) < cand.size() && cost[k][size_t(col[k])] < big) vid[k] = cand[size_t(col[k])];
  return vid;
}

std::vector<int> VertexStore::Update(const std::vector<Eigen::Vector2d>& z, const std::vector<Eigen::Matrix2d>& R) {
  std::vector<int> vid = Associate(z, R);
  for (size_t k = 0; k < z.size(); ++k) {
    if (vid[k] >= 0) {
      Vertex& x = v_[size_t(vid[k])];
      const Eigen::Matrix2d K = x.P * (x.P + R[k]).inverse();
      x.x += K * (z[k] - x.x);
      x.P = (Eigen::Matrix2d::Identity() - K) * x.P;
      x.P = 0.5 * (x.P + x.P.transpose());
      x.n += 1;
    } else {
      Vertex nv;
      nv.x = z[k];
      nv.P = R[k];
      nv.n = 1;
      nv.in_map = !o_.defer_to_mcmc;  // with MCMC, a vertex enters the map when a sample accepts it
      v_.push_back(nv);
      vid[k] = int(v_.size()) - 1;
    }
  }
  return vid;
}

}  // namespace toponav::mapping::internal

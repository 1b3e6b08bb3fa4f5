#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "core/error.h"
#include "planning/graph.h"

namespace toponav::planning {

const char* ToString(PlanStatus status) {
  switch (status) {
    case PlanStatus::kFound: return "found";
    case PlanStatus::kNoPath: return "no_path";
    case PlanStatus::kNothingToExplore: return "nothing_to_explore";
  }
  return "?";
}

void Graph::AddEdge(int a, int b, double cost) {
  TOPONAV_CHECK(a >= 0 && b >= 0 && a < num_nodes() && b < num_nodes(), "edge " << a << "-" << b);
  TOPONAV_CHECK(std::isfinite(cost) && cost >= 0, "edge cost " << cost);
  adjacency[size_t(a)].push_back({b, cost});
  adjacency[size_t(b)].push_back({a, cost});
}

namespace {
void Dijkstra(const Graph& g, int source, int target, std::vector<double>* dist, std::vector<int>* parent) {
  TOPONAV_CHECK(source >= 0 && source < g.num_nodes(), "source " << source);
  dist->assign(size_t(g.num_nodes()), std::numeric_limits<double>::infinity());
  parent->assign(size_t(g.num_nodes()), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  (*dist)[size_t(source)] = 0;
  open.push({0.0, source});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > (*dist)[size_t(u)]) continue;
    if (u == target) return;
    for (const auto& e : g.adjacency[size_t(u)]) {
      const double nd = d + e.cost;
      if (nd < (*dist)[size_t(e.to)]) {
        (*dist)[size_t(e.to)] = nd;
        (*parent)[size_t(e.to)] = u;
        open.push({nd, e.to});
      }
    }
  }
}
}  // namespace

GraphPath ShortestPath(const Graph& graph, int source, int target) {
  TOPONAV_CHECK(target >= 0 && target < graph.num_nodes(), "target " << target);
  std::vector<double> dist;
  std::vector<int> parent;
  Dijkstra(graph, source, target, &dist, &parent);
  GraphPath path;
  if (!std::isfinite(dist[size_t(target)])) return path;
  path.status = PlanStatus::kFound;
  path.cost = dist[size_t(target)];
  for (int v = target; v != -1; v = parent[size_t(v)]) path.nodes.insert(path.nodes.begin(), v);
  return path;
}

std::vector<double> ShortestCosts(const Graph& graph, int source) {
  std::vector<double> dist;
  std::vector<int> parent;
  Dijkstra(graph, source, -1, &dist, &parent);
  return dist;
}

std::vector<int> ShortestOpenTour(const std::vector<double>& from_start,
                                  const std::vector<std::vector<double>>& between, int exact_max) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<int> nodes;
  for (size_t i = 0; i < from_start.size(); ++i)
    if (std::isfinite(from_start[i])) nodes.push_back(int(i));
  const size_t n = nodes.size();
  if (n <= 1) return nodes;
  auto d = [&](size_t a, size_t b) { return between[size_t(nodes[a])][size_t(nodes[b])]; };
  std::vector<size_t> order;
  if (int(n) <= exact_max) {
    // best[mask][i]: cheapest way to visit 'mask' ending at i.
    const size_t full = (size_t(1) << n) - 1;
    std::vector<std::vector<double>> best(full + 1, std::vector<double>(n, inf));
    std::vector<std::vector<int>> prev(full + 1, std::vector<int>(n, -1));
    for (size_t i = 0; i < n; ++i) best[size_t(1) << i][i] = from_start[size_t(nodes[i])];
    for (size_t mask = 1; mask <= full; ++mask)
      for (size_t i = 0; i < n; ++i) {
        if (!(mask & (size_t(1) << i)) || !std::isfinite(best[mask][i])) continue;
        for (size_t j = 0; j < n; ++j) {
          if (mask & (size_t(1) << j)) continue;
          const double c = best[mask][i] + d(i, j);
          const size_t m2 = mask | (size_t(1) << j);
          if (c < best[m2][j]) {
            best[m2][j] = c;
            prev[m2][j] = int(i);
          }
        }
      }
    // Visit as many as can be reached (a node that cannot be left for the rest ends the tour).
    size_t mask_end = 0, last = 0;
    double cost = inf;
    int most = 0;
    for (size_t mask = 1; mask <= full; ++mask) {
      const int count = __builtin_popcountll(mask);
      for (size_t i = 0; i < n; ++i)
        if (std::isfinite(best[mask][i]) && (count > most || (count == most && best[mask][i] < cost))) {
          most = count;
          cost = best[mask][i];
          mask_end = mask;
          last = i;
        }
    }
    for (size_t mask = mask_end, i = last;;) {
      order.push_back(i);
      const int p = prev[mask][i];
      if (p < 0) break;
      mask &= ~(size_t(1) << i);
      i = size_t(p);
    }
    std::reverse(order.begin(), order.end());
  } else {
    std::vector<char> used(n, 0);
    double here_best = inf;
    size_t cur = 0;
    for (size_t i = 0; i < n; ++i)
      if (from_start[size_t(nodes[i])] < here_best) {
        here_best = from_start[size_t(nodes[i])];
        cur = i;
      }
    order.push_back(cur);
    used[cur] = 1;
    for (size_t k = 1; k < n; ++k) {
      double bd = inf;
      size_t next = n;
      for (size_t j = 0; j < n; ++j)
        if (!used[j] && d(cur, j) < bd) {
          bd = d(cur, j);
          next = j;
        }
      if (next == n) break;
      order.push_back(next);
      used[next] = 1;
      cur = next;
    }
    // 2-opt on the open path: reverse order[a..b] when that shortens it.
    auto at = [&](size_t k) { return order[k]; };
    for (bool better = true; better;) {
      better = false;
      for (size_t a = 0; a + 1 < order.size(); ++a)
        for (size_t b = a + 1; b < order.size(); ++b) {
          const double before = (a == 0 ? from_start[size_t(nodes[at(a)])] : d(at(a - 1), at(a))) +
                                (b + 1 < order.size() ? d(at(b), at(b + 1)) : 0.0);
          const double after = (a == 0 ? from_start[size_t(nodes[at(b)])] : d(at(a - 1), at(b))) +
                               (b + 1 < order.size() ? d(at(a), at(b + 1)) : 0.0);
          // The reversed inner edges cost the same both ways (path lengths).
          if (after + 1e-9 < before) {
            std::reverse(order.begin() + long(a), order.begin() + long(b) + 1);
            better = true;
          }
        }
    }
  }
  std::vector<int> out;
  for (size_t k : order) out.push_back(nodes[k]);
  return out;
}

}  // namespace toponav::planning

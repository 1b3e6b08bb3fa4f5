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

}  // namespace toponav::planning

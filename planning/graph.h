#pragma once
// Planner status values and shortest paths on weighted graphs (the search the visibility-graph planner
// runs).
#include <vector>

namespace toponav::planning {

// Expected planner outcomes are values, never magic costs.
enum class PlanStatus { kFound, kNoPath, kNothingToExplore };
const char* ToString(PlanStatus status);

// An undirected weighted graph on nodes 0..num_nodes-1.
struct Graph {
  struct Edge {
    int to;
    double cost;
  };
  std::vector<std::vector<Edge>> adjacency;
  explicit Graph(int num_nodes = 0) : adjacency(static_cast<size_t>(num_nodes)) {}
  int num_nodes() const { return static_cast<int>(adjacency.size()); }
  // Throws core::InternalError for an unknown node or a negative or non-finite cost.
  void AddEdge(int a, int b, double cost);
};

struct GraphPath {
  PlanStatus status = PlanStatus::kNoPath;
  std::vector<int> nodes;  // source ... target when found
  double cost = 0.0;
  explicit operator bool() const { return status == PlanStatus::kFound; }
};

// Dijkstra from 'source' to 'target'.  Ties are broken by node index, so results are deterministic.
GraphPath ShortestPath(const Graph& graph, int source, int target);
// Costs from 'source' to every node (infinity where unreachable).
std::vector<double> ShortestCosts(const Graph& graph, int source);

}  // namespace toponav::planning

#pragma once
// Planning on the map view: a visibility graph over inflated map vertices, frontier targets, single-agent
// nearest-frontier search, a multi-agent assignment of distinct frontiers, and H-signatures (homology
// classes of paths).  Planners read mapping::MapView only.
#include <limits>
#include <optional>
#include <vector>

#include "core/geometry.h"
#include "core/option_fields.h"
#include "mapping/mapping.h"
#include "planning/graph.h"

namespace toponav::planning {

struct PlannerOptions {
  double inflation_radius = 4.8;   // graph nodes sit this far from map vertices (0.8 * the reference's rho = 6)
  double clearance = 1.5;          // graph edges keep at least this distance from map walls
  double frontier_min_length = 8.0;  // shorter frontiers (slivers along walls) are ignored
  // A frontier target lies this far inside known space from the frontier's midpoint, on a line square to it
  // (or half, a quarter, ... as far where known space is thinner or a map wall stands between; never less
  // than min(2, this)): from farther back an agent sees a frontier that lies along an unaccepted wall head on,
  // not edge on.
  double frontier_setback = 2.0;
  // A straight frontier (within frontier_row_tolerance of its chord) with no stretch longer than
  // frontier_row_gap between detected vertices along it (map vertices and seen candidates; its two ends
  // count as such) is taken for a wall the map has not accepted yet and gets no target (so a straight
  // frontier shorter than the gap never gets one).  Keep it below the narrowest opening agents must pass.
  // 0: off.
  double frontier_row_gap = 14.0;
  double frontier_row_tolerance = 1.0;
  // A way may cross a map wall the map is not certain of (mapping::MapWall::certain) at this price times the
  // wall's odds p / (1 - p), p its probability taken at most 0.99 (world units of path): a wall the map is
  // unsure of is a long detour, not an end.  0: map walls are never crossed.
  double wall_crossing_cost = 0.0;
  static const core::OptionFields<PlannerOptions>& Fields();  // YAML keys (under planning:) and their ranges
  void Validate() const;           // throws core::ConfigError ("planning.inflation_radius", ...)
};

struct Path {
  PlanStatus status = PlanStatus::kNoPath;
  std::vector<core::Vec2> points;  // start ... goal when found
  double cost = 0.0;
  explicit operator bool() const { return status == PlanStatus::kFound; }
};

// A visibility graph over one map view.  Build once per map change, query many times.
class VisibilityGraph {
 public:
  // 'require_known': edges must stay inside the view's known space (exploration); otherwise unknown space
  // counts as free (optimistic planning).
  VisibilityGraph(const mapping::MapView& view, const PlannerOptions& options, bool require_known);

  // Shortest path from 'start' to 'goal' (both added to the graph for this query).
  Path Plan(const core::Vec2& start, const core::Vec2& goal) const;
  // Shortest costs from 'start' to each of 'goals' (infinity where unreachable), and the paths.
  std::vector<Path> PlanToMany(const core::Vec2& start, const std::vector<core::Vec2>& goals) const;

  int num_nodes() const { return int(nodes_.size()); }
  int num_edges() const;
  const std::vector<core::Vec2>& nodes() const { return nodes_; }
  // True if the straight segment is traversable under this graph's rules without crossing a wall; a relaxed
  // end may lie closer than the clearance to a wall (agents and targets do), the rest of the segment may not.
  bool Clear(const core::Vec2& a, const core::Vec2& b) const;
  bool Clear(const core::Vec2& a, const core::Vec2& b, bool relax_a, bool relax_b) const;
  // The price of the walls the segment crosses (PlannerOptions::wall_crossing_cost; 0: it crosses none), or
  // infinity where it may not pass (too close to a wall, or across one that is certain).
  double Crossing(const core::Vec2& a, const core::Vec2& b, bool relax_a, bool relax_b) const;
  // Crosses no wall (no clearance asked) and, if known space is required, stays in it.
  bool ClearLoose(const core::Vec2& a, const core::Vec2& b) const;
  bool StaysKnown(const core::Vec2& a, const core::Vec2& b) const;

 private:
  // Adds the edge i-j to 'g' at its length plus its crossing price, if it may pass (and, unless 'crossing', crosses
  // no wall); true if it did.
  bool LinkIfPassable(Graph* g, const std::vector<core::Vec2>& pts, int i, int j, bool relax_i, bool relax_j,
                      bool crossing) const;
  // Shortest paths on 'base' with the start and goals linked in (across walls if 'crossing').
  std::vector<Path> Query(const Graph& base, const core::Vec2& start, const std::vector<core::Vec2>& goals,
                          bool crossing) const;

  const mapping::MapView* view_;
  PlannerOptions options_;
  bool require_known_;
  std::vector<core::Segment2> walls_;
  std::vector<double> prices_;  // per wall: its crossing price (infinity: never crossed)
  double min_price_ = std::numeric_limits<double>::infinity();  // the least of them
  std::vector<core::Vec2> nodes_;
  Graph graph_;                                  // edges that cross no wall
  // ... and those that do, built when a query first needs them: a const query may write it, so one graph is not
  // for several threads at once (num_edges() counts graph_ only).
  mutable std::optional<Graph> crossing_graph_;
};

// True if p lies in the view's known space (its double-precision polygons, as the graph's rules use them).
bool InKnown(const mapping::MapView& view, const core::Vec2& p);

// Where an agent goes to explore a frontier: a point up to 'frontier_setback' inside known space from its
// midpoint, with no map wall between (the midpoint itself where known space is thinner than min(2, setback)).
struct FrontierTarget {
  int frontier_id = 0;
  core::Vec2 point;
  double length = 0.0;
  core::Vec2 outward{1, 0};  // unit normal of the frontier at its midpoint, pointing into unknown space
  double depth = 0.0;        // how far 'point' lies back from the frontier, against 'outward'
};
std::vector<FrontierTarget> FrontierTargets(const mapping::MapView& view, const PlannerOptions& options);
// True if 'frontier' is straight with no stretch longer than PlannerOptions::frontier_row_gap between detected
// vertices along it (a wall the map has not accepted yet).
bool AlongVertexRow(const mapping::Frontier& frontier, const mapping::MapView& view, const PlannerOptions& options);
// True if 'frontier' is straight (within frontier_row_tolerance of its chord) from one map vertex to another
// that map walls already join the long way round, and every wall at its two ends meets it square (within 15
// degrees): in an open world of rectilinear buildings, a building's last side.
bool ClosesWallChain(const mapping::Frontier& frontier, const mapping::MapView& view, const PlannerOptions& options);

// Adds the polyline's segments to 'view' as walls (no map vertices at their ends): what planners must not
// cross beyond the map -- a region's edge, frontiers masked.  'closed': also last -> first.
void AddWalls(mapping::MapView* view, const std::vector<core::Vec2>& polyline, bool closed = false);
// Adds 'wall' to 'view' with map vertices of its own at its ends (ids above the view's), so the visibility
// graph has nodes to go round it: an obstacle standing free of the map's walls (a motion block, a given-up
// frontier piece).
void AddFreeStandingWall(mapping::MapView* view, const core::Segment2& wall);
// The same for each of 'walls', in order (the free vertex id found once for them all).
void AddFreeStandingWalls(mapping::MapView* view, const std::vector<core::Segment2>& walls);

// The frontiers of 'view' the targets name, in the targets' order.
std::vector<const mapping::Frontier*> TargetFrontiers(const mapping::MapView& view,
                                                      const std::vector<FrontierTarget>& targets);

// One agent's choice: the frontier it heads for and the path there.
struct FrontierChoice {
  PlanStatus status = PlanStatus::kNothingToExplore;
  int frontier_id = -1;
  Path path;
};

// Single agent: the reachable frontier with the cheapest path.
FrontierChoice ChooseNearestFrontier(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                                     const core::Vec2& agent);

// A team: agents assigned to distinct frontiers minimizing the summed path cost (Hungarian); when
// there are fewer reachable frontiers than agents, the extra agents take their own cheapest frontier.
std::vector<FrontierChoice> AssignFrontiers(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                                            const std::vector<core::Vec2>& agents);

// H-signature of a polyline with respect to obstacle representative points: for each point, the signed angle
// the path winds around it.  Two paths with the same ends are homologous iff their signatures agree
// (to within 2 pi multiples of nothing: compare with a tolerance well below 2 pi).
std::vector<double> HSignature(const std::vector<core::Vec2>& path, const std::vector<core::Vec2>& obstacle_points);

}  // namespace toponav::planning

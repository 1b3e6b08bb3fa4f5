#include "planning/navigation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/assignment.h"
#include "core/error.h"

namespace toponav::planning {

using core::Vec2;

const core::OptionFields<PlannerOptions>& PlannerOptions::Fields() {
  using O = PlannerOptions;
  static const core::OptionFields<O> fields{
      {"inflation_radius", &O::inflation_radius, 0.01, 100.0},
      {"clearance", &O::clearance, 0.0, 100.0},
      {"frontier_min_length", &O::frontier_min_length, 0.0, 1000.0},
      {"frontier_setback", &O::frontier_setback, 0.01, 100.0},
      {"frontier_row_gap", &O::frontier_row_gap, 0.0, 1000.0},
      {"frontier_row_tolerance", &O::frontier_row_tolerance, 0.01, 100.0},
      {"wall_crossing_cost", &O::wall_crossing_cost, 0.0, 100000.0},
  };
  return fields;
}

void PlannerOptions::Validate() const {
  core::CheckRanges(*this, Fields(), "planning.");
  if (!(clearance < inflation_radius))
    throw core::ConfigError("<options>", "planning.clearance", std::to_string(clearance), "must be < inflation_radius");
}

bool InKnown(const mapping::MapView& view, const Vec2& p) {
  for (const auto& poly : view.known_space)
    if (core::Contains(poly, p)) return true;
  return false;
}

namespace {

// A way may cross a map wall the map is not certain of at 'cost' times its odds, the wall's probability
// taken at most kMaxWallProbability (only what is certain is never crossed); 'cost' 0: never.
constexpr double kMinWallProbability = 0.01, kMaxWallProbability = 0.99;
double CrossingPrice(const mapping::MapWall& w, double cost) {
  if (w.certain || cost <= 0) return std::numeric_limits<double>::infinity();
  const double p = std::clamp(w.probability, kMinWallProbability, kMaxWallProbability);
  return cost * p / (1.0 - p);
}

// Exploration also needs to turn at corners of known space that are not map vertices (where it meets unknown
// space): a node inside each such corner, on the inward bisector, 'r' in, at least 0.9 r from every wall.
void AddKnownSpaceCorners(const mapping::MapView& view, const std::vector<core::Segment2>& walls, double r,
                          std::vector<Vec2>* nodes) {
  auto add_corners = [&](const core::Ring& ring, bool outer) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 prev = ring[(i + n - 1) % n], cur = ring[i], next = ring[(i + 1) % n];
      const double la = core::Distance(prev, cur), lb = core::Distance(cur, next);
      if (la < 1e-9 || lb < 1e-9) continue;
      const Vec2 a = (prev - cur) / la, b = (next - cur) / lb;
      Vec2 bis = a + b;
      if (core::Norm(bis) < 1e-9) continue;  // straight: no corner
      bis = bis / core::Norm(bis);
      // Outer rings are counter-clockwise, so the interior is left of cur->next; flip if the bisector is not.
      const bool left = core::Cross(b, bis) > 0;
      if (left != outer) bis = bis * -1.0;
      const Vec2 p = cur + bis * r;
      bool ok = InKnown(view, p);
      for (const auto& w : walls) ok = ok && core::DistanceToSegment(p, w) >= 0.9 * r - 1e-9;
      if (ok) nodes->push_back(p);
    }
  };
  for (const auto& poly : view.known_space) {
    add_corners(poly.outer, true);
    for (const auto& h : poly.holes) add_corners(h, false);
  }
}

}  // namespace

VisibilityGraph::VisibilityGraph(const mapping::MapView& view, const PlannerOptions& options, bool require_known)
    : view_(&view), options_(options), require_known_(require_known) {
  options.Validate();
  for (const auto& w : view.walls) {
    walls_.push_back({w.pa, w.pb});
    prices_.push_back(CrossingPrice(w, options.wall_crossing_cost));
    min_price_ = std::min(min_price_, prices_.back());
  }
  // Nodes around each map vertex, inflation_radius away: one per free angular sector between its walls (on
  // the bisector; wide sectors get one node per 60 degrees), six around a vertex without walls.
  std::map<int, std::vector<double>> wall_dirs;
  std::map<int, Vec2> pos;
  for (const auto& v : view.vertices) pos[v.id] = v.position;
  for (const auto& w : view.walls) {
    wall_dirs[w.a].push_back(std::atan2(w.pb.y - w.pa.y, w.pb.x - w.pa.x));
    wall_dirs[w.b].push_back(std::atan2(w.pa.y - w.pb.y, w.pa.x - w.pb.x));
  }
  const double r = options.inflation_radius;
  for (const auto& v : view.vertices) {
    std::vector<double> dirs = wall_dirs[v.id];
    std::sort(dirs.begin(), dirs.end());
    std::vector<double> angles;
    if (dirs.empty()) {
      for (int k = 0; k < 6; ++k) angles.push_back(2 * core::kPi * k / 6);
    } else {
      for (size_t k = 0; k < dirs.size(); ++k) {
        const double from = dirs[k];
        double span = (k + 1 < dirs.size() ? dirs[k + 1] : dirs[0] + 2 * core::kPi) - from;
        if (span <= 1e-9) continue;
        const int count = std::max(1, int(std::ceil(span / (core::kPi / 3) - 1e-9)) - 1);
        for (int j = 0; j < count; ++j) angles.push_back(from + span * (j + 1) / (count + 1));
      }
    }
    for (double a : angles) {
      const Vec2 p = v.position + Vec2{r * std::cos(a), r * std::sin(a)};
      bool ok = true;
      for (const auto& w : walls_) ok = ok && core::DistanceToSegment(p, w) >= 0.9 * r - 1e-9;
      if (ok && require_known_) ok = InKnown(view, p);
      if (ok) nodes_.push_back(p);
    }
  }
  if (require_known_) AddKnownSpaceCorners(view, walls_, r, &nodes_);
  graph_ = Graph(int(nodes_.size()));
  for (size_t i = 0; i < nodes_.size(); ++i)
    for (size_t j = i + 1; j < nodes_.size(); ++j) LinkIfPassable(&graph_, nodes_, int(i), int(j), false, false, false);
}

bool VisibilityGraph::LinkIfPassable(Graph* g, const std::vector<Vec2>& pts, int i, int j, bool relax_i,
                                     bool relax_j, bool crossing) const {
  const double price = Crossing(pts[size_t(i)], pts[size_t(j)], relax_i, relax_j);
  if (price == std::numeric_limits<double>::infinity() || (price > 0 && !crossing)) return false;
  g->AddEdge(i, j, core::Distance(pts[size_t(i)], pts[size_t(j)]) + price);
  return true;
}

int VisibilityGraph::num_edges() const {
  size_t n = 0;
  for (const auto& a : graph_.adjacency) n += a.size();
  return int(n / 2);
}

bool VisibilityGraph::Clear(const Vec2& a, const Vec2& b) const { return Clear(a, b, false, false); }

bool VisibilityGraph::Clear(const Vec2& a, const Vec2& b, bool relax_a, bool relax_b) const {
  return Crossing(a, b, relax_a, relax_b) == 0.0;
}

double VisibilityGraph::Crossing(const Vec2& a, const Vec2& b, bool relax_a, bool relax_b) const {
  constexpr double kBlocked = std::numeric_limits<double>::infinity();
  const core::Segment2 s{a, b};
  // A relaxed end (an agent or a target that may stand close to a wall) only needs the clearance from
  // 'clearance' along the segment on; the segment may still not touch a wall anywhere.
  const double len = core::Distance(a, b);
  core::Segment2 inner = s;
  if ((relax_a || relax_b) && len > 1e-12) {
    const Vec2 d = (b - a) / len;
    const double ca = relax_a ? std::min(options_.clearance, len / 2) : 0.0;
    const double cb = relax_b ? std::min(options_.clearance, len / 2) : 0.0;
    inner = {a + d * ca, b - d * cb};
  }
  // Walls whose boxes stay clear of the inner segment's box grown by the clearance can neither come too close
  // nor cross the whole segment (it reaches at most 'clearance' beyond the inner one).
  const double c = options_.clearance;
  const core::Aabb2 box = core::SegmentBox(inner.a, inner.b);
  double price = 0.0;
  for (size_t i = 0; i < walls_.size(); ++i) {
    const core::Segment2& w = walls_[i];
    if (!core::BoxHitsSegment(box, w.a, w.b, c)) continue;
    // A wall the segment crosses and may cross costs its price; any other keeps the clearance.
    if (prices_[i] < kBlocked && core::SegmentsIntersect(s, w)) {
      price += prices_[i];
      continue;
    }
    if (core::SegmentDistance(inner, w) < c) return kBlocked;
    if ((relax_a || relax_b) && core::SegmentsIntersect(s, w)) return kBlocked;
  }
  return StaysKnown(a, b) ? price : kBlocked;
}

bool VisibilityGraph::ClearLoose(const Vec2& a, const Vec2& b) const {
  for (const auto& w : walls_)
    if (core::SegmentsIntersect({a, b}, w)) return false;
  return StaysKnown(a, b);
}

bool VisibilityGraph::StaysKnown(const Vec2& a, const Vec2& b) const {
  const core::Segment2 s{a, b};
  if (require_known_) {
    // Inside known space: the midpoint is inside and the segment crosses no known-space boundary edge.
    if (!InKnown(*view_, (a + b) * 0.5)) return false;
    const double minx = std::min(a.x, b.x), maxx = std::max(a.x, b.x), miny = std::min(a.y, b.y),
                 maxy = std::max(a.y, b.y);
    auto crosses = [&](const core::Ring& ring) {
      for (size_t i = 0, n = ring.size(); i < n; ++i) {
        const Vec2 p = ring[i], q = ring[(i + 1) % n];
        if (std::max(p.x, q.x) < minx || std::min(p.x, q.x) > maxx || std::max(p.y, q.y) < miny ||
            std::min(p.y, q.y) > maxy)
          continue;
        if (core::SegmentsIntersect(s, {p, q})) return true;
      }
      return false;
    };
    for (const auto& poly : view_->known_space) {
      if (crosses(poly.outer)) return false;
      for (const auto& h : poly.holes)
        if (crosses(h)) return false;
    }
  }
  return true;
}

std::vector<Path> VisibilityGraph::PlanToMany(const Vec2& start, const std::vector<Vec2>& goals) const {
  std::vector<Path> out = Query(graph_, start, goals, false);
  // A way that crosses a wall costs at least the least price: a wall-free way no dearer is the best.
  std::vector<size_t> dear;
  for (size_t k = 0; k < goals.size(); ++k)
    if (!out[k] || out[k].cost > min_price_) dear.push_back(k);
  if (dear.empty() || min_price_ == std::numeric_limits<double>::infinity()) return out;
  if (!crossing_graph_) {
    crossing_graph_ = graph_;
    for (size_t i = 0; i < nodes_.size(); ++i)
      for (size_t j = i + 1; j < nodes_.size(); ++j)
        if (!Clear(nodes_[i], nodes_[j])) LinkIfPassable(&*crossing_graph_, nodes_, int(i), int(j), false, false, true);
  }
  std::vector<Vec2> dear_goals;
  for (size_t k : dear) dear_goals.push_back(goals[k]);
  // The crossing query links the ends by crossing edges where the wall-free one fell back to edges that cross no
  // wall at all (an end within the clearance of a wall), so it is not always the cheaper: keep the better.
  const std::vector<Path> crossing = Query(*crossing_graph_, start, dear_goals, true);
  for (size_t i = 0; i < dear.size(); ++i) {
    Path& best = out[dear[i]];
    if (crossing[i] && (!best || crossing[i].cost < best.cost)) best = crossing[i];
  }
  return out;
}

std::vector<Path> VisibilityGraph::Query(const Graph& base, const Vec2& start, const std::vector<Vec2>& goals,
                                         bool crossing) const {
  // Query graph: the built graph plus the start and the goals.
  Graph g = base;
  const int n = int(nodes_.size());
  const int s = n;
  g.adjacency.resize(size_t(n + 1 + int(goals.size())));
  std::vector<Vec2> pts = nodes_;
  pts.push_back(start);
  pts.insert(pts.end(), goals.begin(), goals.end());
  // An end that a map wall has come too close to (a wall estimate that moved, an agent pushed against a
  // wall) still connects by segments that cross no wall, so an agent can always get away from a wall.
  bool start_linked = false;
  for (int i = 0; i < n; ++i) start_linked = LinkIfPassable(&g, pts, s, i, true, false, crossing) || start_linked;
  if (!start_linked)
    for (int i = 0; i < n; ++i)
      if (ClearLoose(start, pts[size_t(i)])) g.AddEdge(s, i, core::Distance(start, pts[size_t(i)]));
  for (size_t k = 0; k < goals.size(); ++k) {
    const int gi = n + 1 + int(k);
    bool linked = false;
    for (int i = 0; i <= n; ++i) linked = LinkIfPassable(&g, pts, gi, i, true, i == n, crossing) || linked;
    if (!linked)
      for (int i = 0; i <= n; ++i)
        if (ClearLoose(goals[k], pts[size_t(i)])) g.AddEdge(gi, i, core::Distance(goals[k], pts[size_t(i)]));
  }
  std::vector<Path> out(goals.size());
  for (size_t k = 0; k < goals.size(); ++k) {
    const GraphPath gp = ShortestPath(g, s, n + 1 + int(k));
    if (!gp) continue;
    out[k].status = PlanStatus::kFound;
    out[k].cost = gp.cost;
    for (int id : gp.nodes) out[k].points.push_back(pts[size_t(id)]);
  }
  return out;
}

Path VisibilityGraph::Plan(const Vec2& start, const Vec2& goal) const { return PlanToMany(start, {goal})[0]; }

void AddWalls(mapping::MapView* view, const std::vector<Vec2>& polyline, bool closed) {
  for (size_t i = 1; i < polyline.size(); ++i)
    view->walls.push_back({-1, -1, polyline[i - 1], polyline[i], 1.0, /*certain=*/true});
  if (closed && polyline.size() > 2)
    view->walls.push_back({-1, -1, polyline.back(), polyline.front(), 1.0, /*certain=*/true});
}

void AddFreeStandingWall(mapping::MapView* view, const core::Segment2& wall) { AddFreeStandingWalls(view, {wall}); }

void AddFreeStandingWalls(mapping::MapView* view, const std::vector<core::Segment2>& walls) {
  int id = 0;
  for (const auto& v : view->vertices) id = std::max(id, v.id + 1);
  for (const auto& w : view->walls) id = std::max({id, w.a + 1, w.b + 1});
  for (const auto& wall : walls) {
    view->vertices.push_back({id, wall.a, {}, 0});
    view->vertices.push_back({id + 1, wall.b, {}, 0});
    view->walls.push_back({id, id + 1, wall.a, wall.b, 1.0, /*certain=*/true});
    id += 2;
  }
}

FrontierChoice ChooseNearestFrontier(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                                     const Vec2& agent) {
  FrontierChoice choice;
  if (targets.empty()) return choice;
  std::vector<Vec2> goals;
  for (const auto& t : targets) goals.push_back(t.point);
  const std::vector<Path> paths = graph.PlanToMany(agent, goals);
  choice.status = PlanStatus::kNoPath;
  double best = 0;
  for (size_t k = 0; k < paths.size(); ++k)
    if (paths[k] && (choice.status != PlanStatus::kFound || paths[k].cost < best)) {
      best = paths[k].cost;
      choice.status = PlanStatus::kFound;
      choice.frontier_id = targets[k].frontier_id;
      choice.path = paths[k];
    }
  return choice;
}

std::vector<FrontierChoice> AssignFrontiers(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                                            const std::vector<Vec2>& agents) {
  std::vector<FrontierChoice> out(agents.size());
  if (targets.empty() || agents.empty()) return out;
  std::vector<Vec2> goals;
  for (const auto& t : targets) goals.push_back(t.point);
  std::vector<std::vector<Path>> paths;
  for (const auto& a : agents) paths.push_back(graph.PlanToMany(a, goals));
  const double kUnreachable = 1e9;
  auto cost = [&](size_t a, size_t t) { return paths[a][t] ? paths[a][t].cost : kUnreachable; };
  auto take = [&](size_t a, size_t t) {
    if (!paths[a][t]) {
      out[a].status = PlanStatus::kNoPath;
      return;
    }
    out[a].status = PlanStatus::kFound;
    out[a].frontier_id = targets[t].frontier_id;
    out[a].path = paths[a][t];
  };
  if (targets.size() >= agents.size()) {
    std::vector<std::vector<double>> c(agents.size(), std::vector<double>(targets.size()));
    for (size_t a = 0; a < agents.size(); ++a)
      for (size_t t = 0; t < targets.size(); ++t) c[a][t] = cost(a, t);
    const std::vector<int> col = core::SolveAssignment(c);
    for (size_t a = 0; a < agents.size(); ++a) take(a, size_t(col[a]));
  } else {
    // Fewer frontiers than agents: each frontier gets its cheapest distinct agent, the rest their nearest.
    std::vector<std::vector<double>> c(targets.size(), std::vector<double>(agents.size()));
    for (size_t t = 0; t < targets.size(); ++t)
      for (size_t a = 0; a < agents.size(); ++a) c[t][a] = cost(a, t);
    const std::vector<int> agent_of = core::SolveAssignment(c);
    std::vector<char> assigned(agents.size(), 0);
    for (size_t t = 0; t < targets.size(); ++t) {
      take(size_t(agent_of[t]), t);
      assigned[size_t(agent_of[t])] = 1;
    }
    for (size_t a = 0; a < agents.size(); ++a) {
      if (assigned[a]) continue;
      size_t best = 0;
      for (size_t t = 1; t < targets.size(); ++t)
        if (cost(a, t) < cost(a, best)) best = t;
      take(a, best);
    }
  }
  // An agent left with an unreachable frontier (fewer reachable frontiers than agents) takes its own cheapest
  // reachable one, shared or not, rather than standing still.
  for (size_t a = 0; a < agents.size(); ++a) {
    if (out[a].status == PlanStatus::kFound) continue;
    size_t best = targets.size();
    for (size_t t = 0; t < targets.size(); ++t)
      if (paths[a][t] && (best == targets.size() || cost(a, t) < cost(a, best))) best = t;
    if (best < targets.size()) take(a, best);
  }
  return out;
}

std::vector<double> HSignature(const std::vector<Vec2>& path, const std::vector<Vec2>& obstacle_points) {
  std::vector<double> h(obstacle_points.size(), 0.0);
  for (size_t k = 0; k < obstacle_points.size(); ++k)
    for (size_t i = 1; i < path.size(); ++i) {
      const Vec2 a = path[i - 1] - obstacle_points[k], b = path[i] - obstacle_points[k];
      h[k] += std::atan2(core::Cross(a, b), core::Dot(a, b));
    }
  return h;
}

}  // namespace toponav::planning

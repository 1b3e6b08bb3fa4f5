#include "planning/goal_navigator.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "planning/cell_estimator.h"
#include "planning/internal/given_up_frontiers.h"
#include "planning/internal/doorway_recovery.h"
#include "planning/internal/motion_blocks.h"
#include "planning/internal/scan_walls.h"
#include "planning/internal/progress.h"

namespace toponav::planning {

using core::Vec2;

namespace {

// A step counts as repeated (RepeatedStep) where it repeats the steps one and two laps of a loop before it, both
// ends of each within this many steps' length: it belongs to the third lap, or a later one, of a loop that the
// same map and plan make the agent walk within about a hundredth of a unit of the lap before.
constexpr double kRepeatTolerance = 0.05;
constexpr int kRepeatLaps = 2;

// Scan walls (planning/internal/scan_walls.h): hit points this far apart or closer lie on one wall (a maze's walls
// stand 14 apart, its openings are wider), walls straight to within this.
constexpr double kScanLink = 2.0;
constexpr double kScanTolerance = 0.3;

// The learned estimator, each estimate also handed to a hook (GoalNavigator::set_on_estimate).
class ReportingEstimator : public SubgoalEstimator {
 public:
  explicit ReportingEstimator(std::shared_ptr<CellAveragingEstimator> learned) : learned_(std::move(learned)) {}
  std::vector<SubgoalProperties> Estimate(const SubgoalGrid& grid, const OrderingProblem& distances) override {
    std::vector<SubgoalProperties> estimates = learned_->Estimate(grid, distances);
    if (hook) hook(grid, distances, estimates, learned_->seen());
    return estimates;
  }
  EstimateHook hook;

 private:
  std::shared_ptr<CellAveragingEstimator> learned_;
};

// The true world's walls as a map (every ring's corners its vertices, no frontiers; clutter, which no map holds,
// left out): planner "known" plans on it.
mapping::MapView TrueMap(const core::World& world) {
  mapping::MapView view;
  int id = 0;
  for (const core::Ring* ring : core::MapRings(world)) {
    const int first = id;
    for (const Vec2& p : *ring) view.vertices.push_back({id++, p, {}, 0});
    for (int i = first; i < id; ++i) {
      const int j = i + 1 < id ? i + 1 : first;
      view.walls.push_back({i, j, view.vertices[i].position, view.vertices[j].position, 1.0, /*certain=*/true});
    }
  }
  return view;
}

// The view with the region's edges as walls: the region (the maze's extent) is known, and a long outer wall
// whose far end lies beyond the sensor's range never becomes a map wall, so the optimistic graph would lead
// around its near end out of the world.
mapping::MapView WithRegionWalls(const mapping::MapView& view, const core::Aabb2& region) {
  mapping::MapView v = view;
  AddWalls(&v, {region.min, {region.max.x, region.min.y}, region.max, {region.min.x, region.max.y}}, true);
  return v;
}

// The nearest frontier within 'reach' of p (-1: none).
int NearestFrontier(const std::vector<mapping::Frontier>& frontiers, const Vec2& p, double reach) {
  int best = -1;
  double best_d = reach;
  for (const auto& f : frontiers)
    for (size_t i = 0; i + 1 < f.points.size(); ++i) {
      const double d = core::DistanceToSegment(p, {f.points[i], f.points[i + 1]});
      if (d < best_d) best_d = d, best = f.id;
    }
  return best;
}

void CheckTruth(const GoalNavigatorSetup& s) {
  if (NeedsTrueWorld(s.planner) && !s.truth)
    throw core::ConfigError("<navigator>", "planner", ToString(s.planner),
                            "needs the true world as its privileged input, and none was given");
  if (!NeedsTrueWorld(s.planner) && s.truth)
    throw core::ConfigError("<navigator>", "planner", ToString(s.planner),
                            "plans from the sensors only: it takes no privileged input");
}

}  // namespace

const char* ToString(GoalPlanner planner) {
  switch (planner) {
    case GoalPlanner::kOptimistic: return "optimistic";
    case GoalPlanner::kOracle: return "oracle";
    case GoalPlanner::kLsp: return "lsp";
    case GoalPlanner::kKnown: return "known";
  }
  return "?";
}

std::optional<GoalPlanner> ParseGoalPlanner(const std::string& name) {
  for (const auto p : {GoalPlanner::kOptimistic, GoalPlanner::kOracle, GoalPlanner::kLsp, GoalPlanner::kKnown})
    if (name == ToString(p)) return p;
  return std::nullopt;
}

bool NeedsTrueWorld(GoalPlanner planner) { return planner == GoalPlanner::kOracle || planner == GoalPlanner::kKnown; }

int LongestHold(const std::vector<core::Vec2>& trail, double span) {
  TOPONAV_CHECK(span >= 0, "bad hold span " << span);
  int best = 0;
  size_t first = 0;  // window [first, j] holds; an entry too far from some in it moves 'first' past the last such
  for (size_t j = 0; j < trail.size(); ++j) {
    for (size_t i = j; i-- > first;)
      if (core::Distance(trail[i], trail[j]) > span) {
        first = i + 1;
        break;
      }
    best = std::max(best, int(j - first + 1));
  }
  return best;
}

// What the navigator keeps: its planner (LSP or the optimistic one), the learned estimator it feeds, the true
// map of planner "known", and the units of its rules.
struct GoalNavigator::Parts {
  explicit Parts(const GoalNavigatorSetup& s)
      : stuck(1, s.navigation.stuck_steps, s.step_length),
        blocked(s.navigation.give_up_reach, s.navigation.give_up_probe_radius),
        recovery(s.navigation, s.planning, s.goal) {
    if (s.planner == GoalPlanner::kKnown) {
      true_map = WithRegionWalls(TrueMap(*s.truth), s.region);
      true_graph.emplace(*true_map, s.planning, false);
    } else if (s.navigation.block_when_stuck) {
      blocks.emplace(1, s.navigation.stuck_steps, s.step_length, 2 * s.step_length, s.planning.clearance + 0.5);
    }
    if (s.planner == GoalPlanner::kOptimistic || s.planner == GoalPlanner::kKnown) {
      optimistic = CreatePlanner(PlannerKind::kOptimistic);
      return;
    }
    std::shared_ptr<SubgoalEstimator> estimator;
    if (s.planner == GoalPlanner::kOracle) {
      estimator = CreateOracleEstimator(*s.truth, s.lsp.cell, s.lsp.clearance);
    } else {
      cells = std::make_shared<CellAveragingEstimator>(10, s.lsp.calibration);
      reporting = std::make_shared<ReportingEstimator>(cells);
      estimator = reporting;
    }
    lsp = CreateLspPlanner(std::move(estimator), s.lsp, s.planning, s.region, ToString(s.planner));
  }
  Planner& planner() { return lsp ? static_cast<Planner&>(*lsp) : *optimistic; }

  std::unique_ptr<LspPlanner> lsp;            // oracle, lsp
  std::unique_ptr<Planner> optimistic;        // optimistic, known
  std::shared_ptr<CellAveragingEstimator> cells;   // lsp: fed this step's observations
  std::shared_ptr<ReportingEstimator> reporting;   // lsp: 'cells' with the estimate hook
  std::optional<mapping::MapView> true_map;        // known: the true walls and the region's
  std::optional<VisibilityGraph> true_graph;
  StuckMonitor stuck;
  GivenUpFrontiers blocked;                  // frontiers the agent was stuck at, blocked where it stood
  std::optional<MotionBlocks> blocks;        // navigation.block_when_stuck, not for known
  internal::DoorwayRecovery recovery;
  ScanWallSet scan_walls{kScanLink, kScanTolerance};  // every scan's walls, merged
};

GoalNavigator::GoalNavigator(const GoalNavigatorSetup& setup) : setup_(setup) {
  CheckTruth(setup);
  parts_ = std::make_unique<Parts>(setup_);
}

GoalNavigator::~GoalNavigator() = default;

void GoalNavigator::set_on_estimate(EstimateHook hook) {
  if (parts_->reporting) parts_->reporting->hook = std::move(hook);
}

const std::vector<core::Segment2>& GoalNavigator::scan_walls() const { return parts_->scan_walls.walls(); }

std::vector<core::Segment2> GoalNavigator::added_blocks() const {
  return parts_->blocks ? parts_->blocks->added() : std::vector<core::Segment2>{};
}

bool GoalNavigator::End(const char* reason) {
  end_reason_ = reason;
  return false;
}

bool GoalNavigator::Plan(const NavigatorInput& in, std::vector<std::vector<Vec2>>* ways) {
  const NavigationOptions& nav = setup_.navigation;
  const Vec2 at = in.poses[0].position();
  if (core::Distance(at, setup_.goal) <= nav.goal_radius) return End("goal");
  if (parts_->cells && in.observations)
    for (const auto& z : *in.observations) parts_->cells->Observe(z);
  // The reference's stuck test: the last stuck_window positions (this one among them) within stuck_span.
  if (HeldInPlace((*in.trails)[0], at, nav.stuck_window, nav.stuck_span)) return End("stuck");
  parts_->blocked.Update(in.view->frontiers);
  const bool known = parts_->true_map.has_value();
  if (!known && nav.scan_when_held > 0) Scan(in, at);
  std::optional<mapping::MapView> own_view;
  std::optional<VisibilityGraph> own_graph;
  if (!known) {
    own_view = PlannerView(*in.view);
    own_graph.emplace(*own_view, setup_.planning, false);
  }
  const std::vector<FrontierTarget> targets = known ? std::vector<FrontierTarget>{} : UnprobedTargets(*in.view);
  if (on_plan) on_plan(in, targets);
  Decide(in, known ? *parts_->true_map : *own_view, known ? *parts_->true_graph : *own_graph, targets, at);
  cut_off_ = choice_.status == PlanStatus::kFound ? 0 : cut_off_ + 1;
  if (cut_off_ >= nav.cut_off_steps) return End("cut_off");
  const bool found = choice_.status == PlanStatus::kFound;
  if (found) (*ways)[0].assign(choice_.path.points.begin() + 1, choice_.path.points.end());
  if (on_decision) on_decision({estimates_, found ? choice_.path.points : std::vector<Vec2>{}});
  return true;
}

// The planner's way on 'view'; where it finds none (not for planner "known"), the recovery's.
void GoalNavigator::Decide(const NavigatorInput& in, const mapping::MapView& view, const VisibilityGraph& graph,
                           const std::vector<FrontierTarget>& targets, const Vec2& at) {
  const PlanningProblem problem{&view, &graph, &targets, {at}, setup_.goal};
  choice_ = parts_->planner().Plan(problem).at(0);
  estimates_ = parts_->lsp ? Estimates(parts_->lsp->decision()) : std::vector<FrontierEstimate>{};
  // Commitment: the map walls this way crosses cost half their odds next step (PlannerView), so a way does not
  // flip between crossings of different walls as the map is sampled again.
  crossed_.clear();
  if (choice_.status == PlanStatus::kFound)
    for (size_t i = 1; i < choice_.path.points.size(); ++i)
      for (const auto& w : in.view->walls)
        if (!w.certain && core::SegmentsIntersect({choice_.path.points[i - 1], choice_.path.points[i]}, {w.pa, w.pb}))
          crossed_.push_back({w.a, w.b});
  parts_->recovery.Reset();
  if (choice_.status == PlanStatus::kFound || parts_->true_map) return;
  ++counts_.recovery_steps;
  choice_ = parts_->recovery.Recover(*in.view, view, parts_->scan_walls.walls().size(), graph, targets, at,
                                     in.step_length, parts_->blocked, parts_->blocks ? &*parts_->blocks : nullptr);
}

// The map with the region's edges as walls, and the blocked frontier parts, motion blocks and scan walls as
// free-standing walls (in that order: the scan walls last).
mapping::MapView GoalNavigator::PlannerView(const mapping::MapView& map) const {
  mapping::MapView view = WithRegionWalls(map, setup_.region);
  for (auto& w : view.walls)
    for (const auto& [a, b] : crossed_)
      if (!w.certain && w.a == a && w.b == b) {
        const double odds = 0.5 * w.probability / std::max(1e-9, 1.0 - w.probability);
        w.probability = odds / (1.0 + odds);
      }
  AddFreeStandingWalls(&view, parts_->blocked.probed());
  if (parts_->blocks && !parts_->blocks->blocks().empty()) view = parts_->blocks->With(view);
  AddFreeStandingWalls(&view, parts_->scan_walls.walls());
  return view;
}

// The frontiers' targets on their parts the agent was not stuck at (GivenUpFrontiers::Unprobed); the planners
// see the frontiers whole, their blocked parts as walls.
std::vector<FrontierTarget> GoalNavigator::UnprobedTargets(const mapping::MapView& map) const {
  if (parts_->blocked.probed().empty()) return FrontierTargets(map, setup_.planning);
  mapping::MapView cut = map;
  cut.frontiers = parts_->blocked.Unprobed(map.frontiers);
  return FrontierTargets(cut, setup_.planning);
}

// Once the agent is held navigation.scan_when_held steps, this step's range ring scan's walls join the set.
void GoalNavigator::Scan(const NavigatorInput& in, const Vec2& at) {
  const NavigationOptions& nav = setup_.navigation;
  scanning_ = scanning_ || HeldInPlace((*in.trails)[0], at, nav.scan_when_held, nav.stuck_span);
  if (!scanning_) return;
  TOPONAV_CHECK(in.observations && !in.observations->empty(), "a held agent's step without observations");
  const std::optional<core::RangeScan>& scan = in.observations->front().scan;
  if (!scan)
    throw core::ConfigError("<options>", "navigation.scan_when_held", std::to_string(nav.scan_when_held),
                            "needs a range ring's scans, and the sensor gives none (declare sensor.range_ring)");
  std::vector<ScanRay> rays(scan->ranges.size());
  for (size_t j = 0; j < rays.size(); ++j) rays[j] = {scan->Angle(j), scan->ranges[j]};
  parts_->scan_walls.Add(ScanWalls(at, rays, scan->max_range, kScanLink, kScanTolerance));
  ++counts_.scan_steps;
}

StepResponse GoalNavigator::AfterStep(const NavigatorInput& in, int agent, const MotionOutcome& step,
                                      core::Rng& rng) {
  const bool has_path = choice_.status == PlanStatus::kFound && choice_.path.points.size() > 1;
  const std::vector<Vec2>& trail = (*in.trails)[0];
  const Vec2 at = step.pose.position();
  StuckMonitor& monitor = parts_->stuck;
  const bool repeated = has_path && RepeatedStep(trail, at, 2 * monitor.pacing_steps(), kRepeatLaps,
                                                 kRepeatTolerance * in.step_length);
  if (repeated) ++counts_.repeated_steps;
  const bool held = PacedForthAndBack(trail, at, in.step_length) ||
                    HeldInPlace(trail, at, monitor.pacing_steps(), 2 * in.step_length) || repeated;
  const bool stuck = (has_path && held) || monitor.NoHeadway(trail, has_path, !has_path, at, step.distance);
  std::optional<MotionBlocks>& blocks = parts_->blocks;
  StepResponse response;
  // Contact: pressed toward the way's next point without getting on (reach: two steps ahead).
  if (has_path && !trail.empty())
    response.contact = core::Contact{trail.back(), choice_.path.points[1], 2 * in.step_length};
  const bool blocked_here = blocks && has_path && !trail.empty() &&
                            blocks->Record(agent, choice_.path.points, trail.back(), at);
  if (!monitor.Record(agent, stuck)) {
    if (!blocked_here) response.contact.reset();
    return response;
  }
  const int blocked =
      parts_->true_map ? -1 : NearestFrontier(in.view->frontiers, at, setup_.navigation.give_up_distance);
  if (blocked >= 0)
    parts_->blocked.GiveUp(blocked, in.view->frontiers, &at);
  else if (blocks && has_path && !trail.empty())
    blocks->Block(trail.back(), choice_.path.points[1]);
  parts_->recovery.Failed();
  ++counts_.nudges;
  response.nudge = RandomNudge(in.step_length, rng);
  return response;
}

}  // namespace toponav::planning

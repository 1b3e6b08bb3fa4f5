#include "experiments/navigation_trial.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "experiments/agent_loop.h"
#include "experiments/map_drive.h"
#include "planning/cell_estimator.h"
#include "planning/doorways.h"
#include "planning/given_up_frontiers.h"
#include "planning/lsp_planner.h"
#include "planning/map_suspects.h"
#include "planning/motion_blocks.h"
#include "planning/scan_walls.h"
#include "planning/search_policy.h"
#include "sim/paths.h"
#include "sim/raycast.h"

namespace toponav::experiments {

using core::Vec2;

namespace {

using SubgoalTruthHook = std::function<void(const std::vector<planning::SubgoalProperties>&,
                                            const std::vector<planning::SubgoalProperties>&)>;

// The learned estimator, with each estimate handed to 'hook' beside the true properties of the pieces it
// covered (NavigationTrialOptions::on_subgoal_truth).
class TruthRecordingEstimator : public planning::SubgoalEstimator {
 public:
  TruthRecordingEstimator(std::unique_ptr<planning::CellAveragingEstimator> learned, const core::World& world,
                          const Config& config, SubgoalTruthHook hook)
      : learned_(std::move(learned)),
        truth_(planning::CreateOracleEstimator(world, config.lsp.cell, config.lsp.clearance)),
        hook_(std::move(hook)) {}
  std::vector<planning::SubgoalProperties> Estimate(const planning::SubgoalGrid& grid,
                                                    const planning::OrderingProblem& distances) override {
    std::vector<planning::SubgoalProperties> estimates = learned_->Estimate(grid, distances);
    const std::vector<planning::SubgoalProperties> truth = truth_->Estimate(grid, distances);
    std::vector<planning::SubgoalProperties> seen_estimates, seen_truth;
    for (size_t f = 0; f < estimates.size(); ++f)
      if (learned_->seen()[f]) seen_estimates.push_back(estimates[f]), seen_truth.push_back(truth[f]);
    hook_(seen_estimates, seen_truth);
    return estimates;
  }

 private:
  std::unique_ptr<planning::CellAveragingEstimator> learned_;
  std::unique_ptr<planning::SubgoalEstimator> truth_;
  SubgoalTruthHook hook_;
};

// The planner 'kind' names; for "lsp" also its estimator, which the policy feeds the observations (its pieces
// handed to 'on_subgoal_truth' with their true properties, if set).
std::unique_ptr<planning::Planner> CreateGoalPlanner(const core::World& world, const Config& config, GoalPlanner kind,
                                                     const SubgoalTruthHook& on_subgoal_truth,
                                                     planning::CellAveragingEstimator** cells) {
  if (kind == GoalPlanner::kOptimistic || kind == GoalPlanner::kKnown)
    return planning::CreatePlanner(planning::PlannerKind::kOptimistic);
  std::unique_ptr<planning::SubgoalEstimator> estimator;
  if (kind == GoalPlanner::kOracle) {
    estimator = planning::CreateOracleEstimator(world, config.lsp.cell, config.lsp.clearance);
  } else {
    auto averaging = std::make_unique<planning::CellAveragingEstimator>(10, config.lsp.calibration);
    *cells = averaging.get();
    if (on_subgoal_truth)
      estimator = std::make_unique<TruthRecordingEstimator>(std::move(averaging), world, config, on_subgoal_truth);
    else
      estimator = std::move(averaging);
  }
  return planning::CreateLspPlanner(std::move(estimator), config.lsp, config.planning, world.bounds, ToString(kind));
}

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
      view.walls.push_back({i, j, view.vertices[i].position, view.vertices[j].position, 1.0});
    }
  }
  return view;
}

// The view with the region's edges as walls: the region of interest (the maze's extent) is known, and a
// long outer wall whose far end lies beyond the sensor's range never becomes a map wall, so the optimistic
// graph would lead around its near end out of the world.
mapping::MapView WithRegionWalls(const mapping::MapView& view, const core::Aabb2& region) {
  mapping::MapView v = view;
  planning::AddWalls(&v, {region.min, {region.max.x, region.min.y}, region.max, {region.min.x, region.max.y}}, true);
  return v;
}

// A step counts as repeated (planning::RepeatedStep) where it repeats the steps one and two laps of a loop
// before it, both ends of each within this many steps' length: it belongs to the third lap, or a later one, of
// a loop that the same map and plan make the agent walk within about a hundredth of a unit of the lap before.
constexpr double kRepeatTolerance = 0.05;
constexpr int kRepeatLaps = 2;

// A held agent's range scans (navigation.scan_when_held): rays a full turn round, hit points this far apart
// or closer on one wall (a maze's walls stand 14 apart, its openings are wider), walls straight to within this.
constexpr int kScanRays = 360;
constexpr double kScanLink = 2.0;
constexpr double kScanTolerance = 0.3;

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

// The goal-directed policy: the planner's way to the goal every step.  An agent that makes no headway is nudged
// as in a search; pacing forth and back (planning::PacedForthAndBack), a loop of steps that stays within two
// steps across for 2 * search.stuck_steps steps (planning::HeldInPlace) and the third lap of a loop of up to
// 4 * stuck_steps steps, of any width (planning::RepeatedStep) count as no headway too (so an agent that a
// nudge leaves inside the loop is nudged again every stuck_steps steps until it leaves).  The frontier
// it stands at is blocked where it stood: a wall the map has not accepted yet (its vertices seen edge-on or
// from too close, or a blank wall longer than the sensor's range) that the optimistic way runs through.  The
// part of a blocked frontier within search.give_up_probe_radius of the agent is a free-standing wall to the
// planners (graph nodes round its ends; the rest of the frontier may hold the opening the agent was heading
// for), and the frontier's target lies on its longest other piece (a frontier with none is no target).  With
// search.block_when_stuck, steps that make no headway along the path, and a nudge with no frontier near to
// block, put a short wall across the way (planning::MotionBlocks): a true wall the map lacks inside known
// space.
// With navigation.scan_when_held, an agent held that many steps (as the stuck test counts) plans from then on
// with the walls its own range sensing shows round it besides the map's (planning::ScanWalls, every scan's
// merged; exact ray casts, clutter included, as the motion's own obstacle avoidance sees): the true wall the map
// lacks that holds it is then a wall to its planner, and no doorway hypothesis opens one.
// Where the map cuts the goal off (a goal-directed trial's goal is reachable: some wall of the map is false),
// Recover() tries in turn a way through a doorway hypothesis (planning/doorways.h), the blocked frontiers and
// motion blocks taken back, and a frontier or a suspected false wall to look at from close by
// (planning::SuspectInspector); the trial ends "cut_off" only when none is left for cut_off_steps steps.  Where
// the agent stands at the place the inspector leads it to, the map walls within inspect_reach of it become
// openings (planning::OpeningsNear) that later doorway searches try too, each until the agent makes no
// headway through it.  Planner "known" plans on TrueMap(world) in place of the map, and adds no walls: it
// blocks no frontier, puts no motion block, and where it finds no way (the goal cut off in the true world) it
// does not recover.
class NavigationPolicy : public AgentPolicy {
 public:
  NavigationPolicy(const core::World& world, const Config& config, GoalPlanner kind,
                   const SubgoalTruthHook& on_subgoal_truth)
      : world_(world),
        goal_(world.goal),
        region_(world.bounds),
        options_(config.navigation),
        planning_(config.planning),
        planner_(CreateGoalPlanner(world, config, kind, on_subgoal_truth, &cells_)),
        true_map_(kind == GoalPlanner::kKnown
                      ? std::optional<mapping::MapView>(WithRegionWalls(TrueMap(world), region_))
                      : std::nullopt),
        stuck_(1, config.search.stuck_steps, MotionFor(config, world).step_length),
        blocked_(config.search.give_up_reach, config.search.give_up_probe_radius),
        blocks_(kind == GoalPlanner::kKnown ? std::nullopt : MotionBlocksFor(config, world, 1)),
        block_reach_(config.search.give_up_distance),
        inspector_(options_.inspect_reach, planning_.inflation_radius + planning_.clearance, options_.inspect_reach),
        scan_range_(MotionFor(config, world).avoid_window) {
    if (true_map_) true_graph_.emplace(*true_map_, planning_, false);
  }

  bool Plan(const LoopState& state, std::vector<std::vector<Vec2>>* paths) override {
    const Vec2 at = state.poses[0].position();
    if (core::Distance(at, goal_) <= options_.goal_radius) return End("goal");
    if (cells_ && state.observations)
      for (const auto& z : *state.observations) cells_->Observe(z);
    // The reference's stuck test: the last stuck_window positions (this one among them) within stuck_span.
    if (planning::HeldInPlace((*state.trails)[0], at, options_.stuck_window, options_.stuck_span)) return End("stuck");
    blocked_.Update(state.view->frontiers);
    if (!true_map_ && options_.scan_when_held > 0) Scan(state, at);
    mapping::MapView own_view;
    std::optional<planning::VisibilityGraph> own_graph;
    if (!true_map_) {
      own_view = WithRegionWalls(*state.view, region_);
      planning::AddFreeStandingWalls(&own_view, blocked_.probed());
      if (blocks_ && !blocks_->blocks().empty()) own_view = blocks_->With(own_view);
      planning::AddFreeStandingWalls(&own_view, scan_walls_.walls());
      own_graph.emplace(own_view, planning_, false);
    }
    const mapping::MapView& view = true_map_ ? *true_map_ : own_view;
    const planning::VisibilityGraph& graph = true_graph_ ? *true_graph_ : *own_graph;
    const std::vector<planning::FrontierTarget> targets =
        true_map_ ? std::vector<planning::FrontierTarget>{} : UnprobedTargets(*state.view);
    if (on_plan) on_plan(state, targets);
    const planning::PlanningProblem problem{&view, &graph, &targets, {at}, goal_};
    choice_ = planner_->Plan(problem).at(0);
    estimates_.clear();
    if (const planning::LspDecision* d = planning::LastDecision(*planner_)) estimates_ = planning::Estimates(*d);
    doorway_.reset();
    if (choice_.status != planning::PlanStatus::kFound && !true_map_) {
      ++recovery_steps_;
      choice_ = Recover(*state.view, view, graph, targets, at, state.step_length);
    }
    cut_off_ = choice_.status == planning::PlanStatus::kFound ? 0 : cut_off_ + 1;
    if (cut_off_ >= options_.cut_off_steps) return End("cut_off");
    if (choice_.status == planning::PlanStatus::kFound)
      (*paths)[0].assign(choice_.path.points.begin() + 1, choice_.path.points.end());
    if (on_decision)
      on_decision({estimates_, choice_.status == planning::PlanStatus::kFound ? choice_.path.points
                                                                              : std::vector<Vec2>{}});
    return true;
  }

  sim::StepResult AfterStep(const LoopState& state, int agent, const sim::StepResult& step, sim::MotionSim& motion,
                            core::Rng& rng) override {
    const bool has_path = choice_.status == planning::PlanStatus::kFound && choice_.path.points.size() > 1;
    const std::vector<Vec2>& trail = (*state.trails)[0];
    const Vec2 at = step.pose.position();
    const bool repeated = has_path && planning::RepeatedStep(trail, at, 2 * stuck_.pacing_steps(), kRepeatLaps,
                                                             kRepeatTolerance * state.step_length);
    if (repeated) ++repeated_steps_;
    const bool held = planning::PacedForthAndBack(trail, at, state.step_length) ||
                      planning::HeldInPlace(trail, at, stuck_.pacing_steps(), 2 * state.step_length) || repeated;
    const bool stuck = (has_path && held) || stuck_.NoHeadway(trail, has_path, !has_path, at, step.distance);
    if (blocks_ && has_path && !trail.empty()) blocks_->Record(agent, choice_.path.points, trail.back(), at);
    if (!stuck_.Record(agent, stuck)) return step;
    const int blocked = true_map_ ? -1 : NearestFrontier(state.view->frontiers, at, block_reach_);
    if (blocked >= 0)
      blocked_.GiveUp(blocked, state.view->frontiers, &at);
    else if (blocks_ && has_path && !trail.empty())
      blocks_->Block(trail.back(), choice_.path.points[1]);
    if (doorway_) failed_doorways_.push_back(*doorway_);
    ++nudges_;
    return NudgeRandomly(motion, agent, state.step_length, rng);
  }

  std::function<void(const NavigationDecision&)> on_decision;
  std::function<void(const LoopState&, const std::vector<planning::FrontierTarget>&)> on_plan;
  const std::vector<planning::FrontierEstimate>& estimates() const { return estimates_; }
  const std::string& end_reason() const { return end_reason_; }
  int nudges() const { return nudges_; }
  int recovery_steps() const { return recovery_steps_; }
  int repeated_steps() const { return repeated_steps_; }
  int scan_steps() const { return scan_steps_; }
  const std::vector<core::Segment2>& scan_walls() const { return scan_walls_.walls(); }
  // Every motion block added, those Recover took back too (none without search.block_when_stuck).
  std::vector<core::Segment2> added_blocks() const {
    return blocks_ ? blocks_->added() : std::vector<core::Segment2>{};
  }

 private:
  // Once the agent is held navigation.scan_when_held steps, a range scan from where it stands every step.
  void Scan(const LoopState& state, const Vec2& at) {
    const std::vector<Vec2>& trail = (*state.trails)[0];
    scanning_ = scanning_ || planning::HeldInPlace(trail, at, options_.scan_when_held, options_.stuck_span);
    if (!scanning_) return;
    if (!ray_caster_) ray_caster_ = std::make_unique<sim::RayCaster>(world_);
    std::vector<planning::ScanRay> rays(kScanRays);
    for (int j = 0; j < kScanRays; ++j) {
      const double angle = 2.0 * core::kPi * j / kScanRays;
      rays[size_t(j)] = {angle, ray_caster_->CastRay(at, angle, scan_range_, /*include_clutter=*/true)};
    }
    scan_walls_.Add(planning::ScanWalls(at, rays, scan_range_, kScanLink, kScanTolerance));
    ++scan_steps_;
  }

  // Where the planner finds no way to the goal: the cheapest way through a doorway hypothesis; else, if some
  // frontiers were given up or motion blocks added, they are all taken back (no way this step); else a
  // frontier or a suspected false wall to look at; where the agent stands at that already, the map walls
  // beside it become openings (planning::OpeningsNear) for this and later doorway searches.  'map': the
  // map's view; 'view': it with the walls the policy adds, after the map's own.
  planning::FrontierChoice Recover(const mapping::MapView& map, const mapping::MapView& view,
                                   const planning::VisibilityGraph& graph,
                                   const std::vector<planning::FrontierTarget>& targets, const Vec2& at,
                                   double step_length) {
    planning::FrontierChoice c = ThroughDoorway(view, map.walls.size(), at);
    if (c.status == planning::PlanStatus::kFound) return c;
    if (blocked_.given_up() > 0 || (blocks_ && !blocks_->blocks().empty())) {
      blocked_.Clear();
      if (blocks_) blocks_->Clear();
      return c;
    }
    c = inspector_.Choose(map, graph, at, goal_, targets);
    if (c.status != planning::PlanStatus::kFound || c.path.cost >= 0.5 * step_length) return c;
    // An opening overlapping one tried or failed before is not new.
    const double apart = options_.doorway_min_width;
    bool added = false;
    for (const auto& o : planning::OpeningsNear(map, map.walls.size(), at, options_.inspect_reach, apart)) {
      bool known = false;
      for (const auto& k : openings_) known = known || core::Distance(k.middle(), o.middle()) < apart;
      for (const auto& f : failed_doorways_) known = known || core::Distance(f, o.middle()) < apart;
      if (!known) openings_.push_back(o), added = true;
    }
    if (!added) return c;
    const planning::FrontierChoice through = ThroughDoorway(view, map.walls.size(), at);
    return through.status == planning::PlanStatus::kFound ? through : c;
  }

  // The frontiers' targets on their parts the agent was not stuck at (GivenUpFrontiers::Unprobed); the
  // planners see the frontiers whole, their blocked parts as walls.
  std::vector<planning::FrontierTarget> UnprobedTargets(const mapping::MapView& map) const {
    if (blocked_.probed().empty()) return planning::FrontierTargets(map, planning_);
    mapping::MapView cut = map;
    cut.frontiers = blocked_.Unprobed(map.frontiers);
    return planning::FrontierTargets(cut, planning_);
  }

  // The way to the goal through the doorway hypothesis or the opening (on one of the view's first 'map_walls'
  // walls; not yet failed) that makes it cheapest.
  planning::FrontierChoice ThroughDoorway(const mapping::MapView& view, size_t map_walls, const Vec2& at) {
    constexpr double kOnWall = 2.0, kSame = 4.0;
    planning::FrontierChoice best;
    const double min_width = options_.doorway_min_width, max_width = options_.doorway_max_width;
    std::vector<planning::Doorway> doorways = planning::DoorwayHypotheses(view, kOnWall, min_width, max_width);
    // The walls the range scans showed come last in the view: they are true walls, with no doorway in them.
    const size_t scanned_from = view.walls.size() - scan_walls_.walls().size();
    doorways.erase(std::remove_if(doorways.begin(), doorways.end(),
                                  [&](const planning::Doorway& d) { return size_t(d.wall) >= scanned_from; }),
                   doorways.end());
    for (const auto& o : openings_)
      if (const auto d = planning::Anchored(view, map_walls, o, kOnWall / 2)) doorways.push_back(*d);
    for (const auto& d : doorways) {
      bool failed = false;
      for (const auto& f : failed_doorways_) failed = failed || core::Distance(f, d.middle()) < kSame;
      if (failed) continue;
      const planning::Path p =
          planning::VisibilityGraph(planning::WithDoorway(view, d), planning_, false).Plan(at, goal_);
      if (!p || (best.status == planning::PlanStatus::kFound && p.cost >= best.path.cost)) continue;
      best = {planning::PlanStatus::kFound, -1, p};
      doorway_ = d.middle();
    }
    return best;
  }

  bool End(const char* reason) {
    end_reason_ = reason;
    return false;
  }

  const core::World& world_;
  Vec2 goal_;
  core::Aabb2 region_;
  NavigationOptions options_;
  planning::PlannerOptions planning_;
  // Declared before planner_, whose initializer sets it: a member declared after would be reset to nullptr by
  // its own initializer once planner_ was built (and the network's estimates never reached the planner).
  planning::CellAveragingEstimator* cells_ = nullptr;  // the "lsp" planner's estimator (owned by planner_)
  std::unique_ptr<planning::Planner> planner_;
  // Planner "known" only: TrueMap(world) with the region's walls, and its graph (built once: the walls never move).
  std::optional<mapping::MapView> true_map_;
  std::optional<planning::VisibilityGraph> true_graph_;
  planning::StuckMonitor stuck_;
  planning::GivenUpFrontiers blocked_;
  std::optional<planning::MotionBlocks> blocks_;  // search.block_when_stuck only
  double block_reach_;
  planning::SuspectInspector inspector_;
  std::optional<Vec2> doorway_;        // the middle of the doorway hypothesis the agent heads through now
  std::vector<Vec2> failed_doorways_;  // middles of those it made no headway through
  std::vector<planning::Doorway> openings_;  // walls beside a place recovery led to, opened (OpeningsNear)
  planning::FrontierChoice choice_;
  std::vector<planning::FrontierEstimate> estimates_;
  double scan_range_;
  bool scanning_ = false;
  std::unique_ptr<sim::RayCaster> ray_caster_;      // built at the first scan
  planning::ScanWallSet scan_walls_{kScanLink, kScanTolerance};  // every scan's walls, merged
  int cut_off_ = 0, nudges_ = 0, recovery_steps_ = 0, repeated_steps_ = 0, scan_steps_ = 0;
  std::string end_reason_ = "step_cap";
};

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

NavigationResult RunNavigationTrial(const core::World& world, const Config& config, const NavigationTrialOptions& o,
                                    uint64_t seed, mapping::MapView* final_view) {
  const auto t0 = std::chrono::steady_clock::now();
  NavigationPolicy policy(world, config, o.planner, o.on_subgoal_truth);
  policy.on_decision = o.on_decision;
  policy.on_plan = o.on_plan;
  LoopOptions lo;
  lo.max_steps = o.max_steps;
  lo.mcmc_every = o.mcmc_every;
  lo.goal = world.goal;
  lo.on_step = o.on_step;
  const LoopResult loop = RunAgentLoop(world, config, lo, policy, seed);
  NavigationResult r;
  r.seed = seed;
  r.planner = ToString(o.planner);
  r.end_reason = policy.end_reason();
  r.reached = r.end_reason == "goal";
  r.steps = loop.steps;
  r.distance = loop.distance.at(0);
  r.shortest = core::PolylineLength(
      sim::FreePath(world, world.start.position(), world.goal, config.lsp.clearance, config.lsp.cell));
  r.nudges = policy.nudges();
  r.recovery_steps = policy.recovery_steps();
  r.repeated_steps = policy.repeated_steps();
  r.scan_steps = policy.scan_steps();
  r.scan_walls = policy.scan_walls();
  r.longest_hold = planning::LongestHold(loop.paths.at(0), config.navigation.stuck_span);
  r.blocks = policy.added_blocks();
  r.path = loop.paths.at(0);
  r.frontier_ps = policy.estimates();
  r.iou = KnownSpaceIoU(world, loop.final_view);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (final_view) *final_view = loop.final_view;
  return r;
}

}  // namespace toponav::experiments

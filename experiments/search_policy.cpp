#include "experiments/search_policy.h"

#include <cmath>

#include "core/error.h"
#include "planning/frontier_exploration.h"
#include "planning/sealed_region.h"

namespace toponav::experiments {

using core::Vec2;

namespace {

const SearchOptions& Validated(const SearchOptions& o) {
  o.Validate();  // before the units check their own arguments: a bad value is a ConfigError naming its key
  return o;
}

}  // namespace

SearchPolicy::SearchPolicy(const core::World& world, const Config& config, int num_agents)
    : search_(Validated(config.search)),
      planning_(config.planning),
      planner_(planning::CreateSearchPlanner(num_agents, config.search.tour)),
      given_up_(config.search.give_up_reach, config.search.give_up_probe_radius),
      dwell_(config.search.give_up_steps, config.search.give_up_distance),
      commitment_(num_agents, config.search.switch_ratio, config.search.switch_margin),
      stuck_(num_agents, config.search.stuck_steps, MotionFor(config, world).step_length),
      blocks_(MotionBlocksFor(config, world, num_agents)),
      cell_(config.lsp.cell),
      bounds_(world.bounds) {
  if (!world.has_boundary()) region_ = world.bounds;
  if (num_agents == 1 && config.search.exploration_estimate == "oracle")
    exploration_ = planning::CreateOracleEstimator(world, config.lsp.cell, config.lsp.clearance);
  if (num_agents == 1 && config.search.exploration_estimate == "learned") {
    auto averaging = std::make_unique<planning::CellAveragingEstimator>();
    cells_ = averaging.get();
    exploration_ = std::move(averaging);
    model_ = config.sensor.learned.model;
  }
  planning::VertexInspectionOptions inspection;
  inspection.max_bend = config.search.inspect_bend;
  inspection.standoff = config.search.inspect_standoff;
  inspection.unwalled_detections = world.has_boundary() ? 0 : config.search.inspect_unwalled;
  inspection.unwalled_standoff = config.planning.frontier_setback;
  inspection.reach = config.search.give_up_distance;
  inspection.looks = config.search.give_up_steps;
  if (inspection.max_bend > 0 || inspection.unwalled_detections > 0) inspector_.emplace(inspection);
  if (search_.sealed_reach > 0 && world.has_boundary())
    sealed_.emplace(config.navigation.inspect_reach, planning_.inflation_radius + planning_.clearance,
                    config.navigation.inspect_reach);
}

bool SearchPolicy::ChooseSealedSuspects(const mapping::MapView& view, const planning::VisibilityGraph& graph,
                                        const std::vector<Vec2>& agents) {
  const std::optional<Vec2> side =
      planning::UnreachedSide(view.known_space, bounds_, search_.sealed_reach, agents[0]);
  if (!side) return false;
  std::vector<planning::FrontierChoice> choices;
  bool any = false;
  for (const Vec2& agent : agents) {
    choices.push_back(sealed_->Choose(view, graph, agent, *side, {}));
    any = any || choices.back().status == planning::PlanStatus::kFound;
  }
  if (!any) return false;
  for (auto& c : choices) c.frontier_id = kSealedSuspect;
  choices_ = std::move(choices);
  sealed_choices_ += int(agents.size());
  return true;
}

void SearchPolicy::ObserveCells(const LoopState& state) {
  const size_t before = cells_->observations();
  for (const auto& z : *state.observations) cells_->Observe(z);
  if (cells_->observations() == before && !state.observations->empty())
    throw core::DataError(model_, "search.exploration_estimate learned: the model gives no subgoal outputs "
                                  "(not trained with train.subgoal)");
}

std::vector<planning::FrontierTarget> SearchPolicy::Targets(const mapping::MapView& view) {
  // The same place under a new id is given up again; grown ones come back, counted afresh.
  for (int id : given_up_.Update(view.frontiers)) dwell_.Reset(id);
  std::vector<planning::FrontierTarget> targets;
  for (const auto& t : planning::FrontierTargets(view, planning_))
    if (!given_up_.Contains(t.frontier_id) && (!region_ || region_->Contains(t.point))) targets.push_back(t);
  const bool dropped = search_.dropped_wall_steps > 0, close = search_.close_buildings && region_;
  if (dropped) dropped_walls_.Update(view.walls);
  if (!dropped && !close) return targets;
  // A frontier along a wall the map dropped, and in open worlds a building's last side, is no target.
  const std::vector<const mapping::Frontier*> frontiers = planning::TargetFrontiers(view, targets);
  std::vector<planning::FrontierTarget> kept, along_dropped;
  for (size_t i = 0; i < targets.size(); ++i) {
    if (close && planning::ClosesWallChain(*frontiers[i], view, planning_)) continue;
    if (dropped && dropped_walls_.TakenForWall(*frontiers[i], view.walls, search_.dropped_wall_steps)) {
      along_dropped.push_back(targets[i]);
      continue;
    }
    kept.push_back(targets[i]);
  }
  // With nothing else left while known space misses a side of a closed world's bounds, a frontier along a
  // dropped wall may be the way on (the wall was a false one across it).
  if (kept.empty() && sealed_ &&
      planning::UnreachedSide(view.known_space, bounds_, search_.sealed_reach, bounds_.min))
    return along_dropped;
  return kept;
}

bool SearchPolicy::Ended(const std::vector<planning::FrontierTarget>& targets, const mapping::MapView& view) {
  if (targets.empty() && !view.known_space.empty()) {
    end_reason_ = "explored";
    explored_ = true;
    return true;
  }
  // Frontiers none of the agents can reach for a while: no reachable frontier is left, which is the paper's
  // definition of explored (a map error that walls one off shows in the IoU instead).
  bool any = false;
  for (const auto& c : choices_) any = any || c.status == planning::PlanStatus::kFound;
  unreachable_ = any || targets.empty() ? 0 : unreachable_ + 1;
  if (unreachable_ >= search_.unreachable_steps) {
    end_reason_ = "unreachable";
    explored_ = true;
    return true;
  }
  return false;
}

// Frontiers standing agents are next to count a step toward being given up (only agents that stand: one
// walking along or through a frontier toward its pushed-through target is still finding out what is behind).
void SearchPolicy::CountDwelling(const LoopState& state, const std::vector<Vec2>& agents) {
  std::vector<char> standing;
  for (const auto& trail : *state.trails)
    standing.push_back(planning::FrontierDwell::Standing(trail, state.step_length));
  // Inspection targets are the inspector's to retire.
  std::vector<planning::FrontierTarget> frontiers, before;
  for (size_t i = 0; i < targets_.size(); ++i)
    if (!planning::VertexInspector::IsInspection(targets_[i].frontier_id))
      frontiers.push_back(targets_[i]), before.push_back(original_[i]);
  for (size_t i : dwell_.CountStanding(frontiers, before, agents, standing))
    given_up_.GiveUp(frontiers[i].frontier_id, state.view->frontiers, &before[i].point);
}

bool SearchPolicy::Plan(const LoopState& state, std::vector<std::vector<Vec2>>* paths) {
  const mapping::MapView& view = *state.view;
  original_ = Targets(view);
  targets_ = original_;
  dwell_.PushThrough(&targets_, search_.push_distance, region_);
  // Optimistic: unknown space counts as free (the reference plans on map walls only); the agent finds out on
  // the way and the plan is redone every step.
  std::optional<mapping::MapView> blocked;  // the view with the motion blocks, when there are any
  if (blocks_ && !blocks_->blocks().empty()) blocked = blocks_->With(view);
  const mapping::MapView& planned = blocked ? *blocked : view;
  const planning::VisibilityGraph graph(planned, planning_, false);
  planning::PlanningProblem problem{&planned, &graph, &targets_, {}, std::nullopt};
  for (const auto& p : state.poses) problem.agents.push_back(p.position());
  if (cells_) ObserveCells(state);
  if (exploration_) planning::EstimateExploration(view, problem.agents[0], cell_, bounds_, *exploration_, &targets_);
  if (targets_.empty() && inspector_) {
    // A lookout the agents cannot reach and look from within the steps left is not worth starting for.
    targets_ = inspector_->Targets(view, graph, problem.agents, PathBudget(state, search_.give_up_steps));
    original_ = targets_;
  }
  const bool sealed = targets_.empty() && sealed_ && ChooseSealedSuspects(view, graph, problem.agents);
  if (!sealed) {
    choices_ = planner_->Plan(problem);
    commitment_.Apply(graph, targets_, problem.agents, &choices_);
  }
  if (on_plan) on_plan(state, targets_, choices_);
  if (!sealed && Ended(targets_, view)) return false;
  if (!sealed) CountDwelling(state, problem.agents);
  for (size_t a = 0; a < choices_.size(); ++a)
    if (choices_[a].status == planning::PlanStatus::kFound)
      (*paths)[a].assign(choices_[a].path.points.begin() + 1, choices_[a].path.points.end());
  return true;
}

sim::StepResult SearchPolicy::AfterStep(const LoopState& state, int agent, const sim::StepResult& step,
                                        sim::MotionSim& motion, core::Rng& rng) {
  const planning::FrontierChoice& c = choices_[size_t(agent)];
  const bool found = c.status == planning::PlanStatus::kFound;
  const bool has_path = found && c.path.points.size() > 1;
  // No path at all while there are frontiers: the agent may stand where the map leaves it no way out.
  const bool no_way = c.status == planning::PlanStatus::kNoPath && !targets_.empty();
  const std::vector<Vec2>& trail = (*state.trails)[size_t(agent)];
  const bool stuck = stuck_.NoHeadway(trail, has_path, no_way, step.pose.position(), step.distance);
  if (blocks_ && has_path && !trail.empty()) blocks_->Record(agent, c.path.points, trail.back(), step.pose.position());
  // An agent that cannot get to its frontier (its path runs into a wall the map lacks) counts toward giving
  // it up as if it stood next to it; all of it counts as probed.  A suspect wall (search.sealed_reach) is the
  // suspect inspector's to retire, once an agent came near it.
  const bool target = found && c.frontier_id != kSealedSuspect;
  if (stuck && target && planning::VertexInspector::IsInspection(c.frontier_id))
    inspector_->GiveUp(c.frontier_id);
  else if (stuck && target && dwell_.Count(c.frontier_id))
    given_up_.GiveUp(c.frontier_id, state.view->frontiers);
  if (!stuck_.Record(agent, stuck)) return step;
  // The paper's failures were agents stuck in place feeding identical images: perturb and re-observe.
  ++nudges_;
  return NudgeRandomly(motion, agent, state.step_length, rng);
}

}  // namespace toponav::experiments

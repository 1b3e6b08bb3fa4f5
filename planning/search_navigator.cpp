#include "planning/search_navigator.h"

#include <cmath>

#include "core/error.h"
#include "planning/internal/sealed_region.h"

namespace toponav::planning {

using core::Vec2;

namespace {

const SearchOptions& Validated(const SearchOptions& o) {
  o.Validate();  // before the units check their own arguments: a bad value is a ConfigError naming its key
  return o;
}

}  // namespace

SearchNavigator::SearchNavigator(const SearchNavigatorSetup& s)
    : search_(Validated(s.search)),
      planning_(s.planning),
      planner_(CreateSearchPlanner(s.num_agents, s.search.tour)),
      given_up_(s.search.give_up_reach, s.search.give_up_probe_radius),
      dwell_(s.search.give_up_steps, s.search.give_up_distance),
      commitment_(s.num_agents, s.search.switch_ratio, s.search.switch_margin),
      stuck_(s.num_agents, s.search.stuck_steps, s.step_length),
      bounds_(s.bounds) {
  if (s.search.block_when_stuck)
    blocks_.emplace(s.num_agents, s.search.stuck_steps, s.step_length, 2 * s.step_length, s.planning.clearance + 0.5);
  if (!s.closed) region_ = s.bounds;
  VertexInspectionOptions inspection;
  inspection.max_bend = s.search.inspect_bend;
  inspection.standoff = s.search.inspect_standoff;
  inspection.unwalled_detections = s.closed ? 0 : s.search.inspect_unwalled;
  inspection.unwalled_standoff = s.planning.frontier_setback;
  inspection.reach = s.search.give_up_distance;
  inspection.looks = s.search.give_up_steps;
  if (inspection.max_bend > 0 || inspection.unwalled_detections > 0) inspector_.emplace(inspection);
  if (search_.sealed_reach > 0 && s.closed)
    sealed_.emplace(s.search.inspect_reach, planning_.inflation_radius + planning_.clearance,
                    s.search.inspect_reach);
}

bool SearchNavigator::ChooseSealedSuspects(const mapping::MapView& view, const VisibilityGraph& graph,
                                        const std::vector<Vec2>& agents) {
  const std::optional<Vec2> side =
      UnreachedSide(view.known_space, bounds_, search_.sealed_reach, agents[0]);
  if (!side) return false;
  std::vector<FrontierChoice> choices;
  bool any = false;
  for (const Vec2& agent : agents) {
    choices.push_back(sealed_->Choose(view, graph, agent, *side, {}));
    any = any || choices.back().status == PlanStatus::kFound;
  }
  if (!any) return false;
  for (auto& c : choices) c.frontier_id = kSealedSuspect;
  choices_ = std::move(choices);
  sealed_choices_ += int(agents.size());
  return true;
}

std::vector<FrontierTarget> SearchNavigator::Targets(const mapping::MapView& view) {
  // The same place under a new id is given up again; grown ones come back, counted afresh.
  for (int id : given_up_.Update(view.frontiers)) dwell_.Reset(id);
  std::vector<FrontierTarget> targets;
  for (const auto& t : FrontierTargets(view, planning_))
    if (!given_up_.Contains(t.frontier_id) && (!region_ || region_->Contains(t.point))) targets.push_back(t);
  const bool dropped = search_.dropped_wall_steps > 0, close = search_.close_buildings && region_;
  if (dropped) dropped_walls_.Update(view.walls);
  if (!dropped && !close) return targets;
  // A frontier along a wall the map dropped, and in open worlds a building's last side, is no target.
  const std::vector<const mapping::Frontier*> frontiers = TargetFrontiers(view, targets);
  std::vector<FrontierTarget> kept, along_dropped;
  for (size_t i = 0; i < targets.size(); ++i) {
    if (close && ClosesWallChain(*frontiers[i], view, planning_)) continue;
    if (dropped && dropped_walls_.TakenForWall(*frontiers[i], view.walls, search_.dropped_wall_steps)) {
      along_dropped.push_back(targets[i]);
      continue;
    }
    kept.push_back(targets[i]);
  }
  // With nothing else left while known space misses a side of a closed world's bounds, a frontier along a
  // dropped wall may be the way on (the wall was a false one across it).
  if (kept.empty() && sealed_ &&
      UnreachedSide(view.known_space, bounds_, search_.sealed_reach, bounds_.min))
    return along_dropped;
  return kept;
}

bool SearchNavigator::Ended(const std::vector<FrontierTarget>& targets, const mapping::MapView& view) {
  if (targets.empty() && !view.known_space.empty()) {
    end_reason_ = "explored";
    explored_ = true;
    return true;
  }
  // Frontiers none of the agents can reach for a while: no reachable frontier is left, which is the paper's
  // definition of explored (a map error that walls one off shows in the IoU instead).
  bool any = false;
  for (const auto& c : choices_) any = any || c.status == PlanStatus::kFound;
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
void SearchNavigator::CountDwelling(const NavigatorInput& input, const std::vector<Vec2>& agents) {
  std::vector<char> standing;
  for (const auto& trail : *input.trails)
    standing.push_back(FrontierDwell::Standing(trail, input.step_length));
  // Inspection targets are the inspector's to retire.
  std::vector<FrontierTarget> frontiers, before;
  for (size_t i = 0; i < targets_.size(); ++i)
    if (!VertexInspector::IsInspection(targets_[i].frontier_id))
      frontiers.push_back(targets_[i]), before.push_back(original_[i]);
  for (size_t i : dwell_.CountStanding(frontiers, before, agents, standing))
    given_up_.GiveUp(frontiers[i].frontier_id, input.view->frontiers, &before[i].point);
}

bool SearchNavigator::Plan(const NavigatorInput& input, std::vector<std::vector<Vec2>>* paths) {
  const mapping::MapView& view = *input.view;
  original_ = Targets(view);
  targets_ = original_;
  dwell_.PushThrough(&targets_, search_.push_distance, region_);
  // Optimistic: unknown space counts as free (the reference plans on map walls only); the agent finds out on
  // the way and the plan is redone every step.
  std::optional<mapping::MapView> blocked;  // the view with the motion blocks, when there are any
  if (blocks_ && !blocks_->blocks().empty()) blocked = blocks_->With(view);
  const mapping::MapView& planned = blocked ? *blocked : view;
  const VisibilityGraph graph(planned, planning_, false);
  PlanningProblem problem{&planned, &graph, &targets_, {}, std::nullopt};
  for (const auto& p : input.poses) problem.agents.push_back(p.position());
  if (targets_.empty() && inspector_) {
    // A lookout the agents cannot reach and look from within the steps left is not worth starting for.
    targets_ = inspector_->Targets(view, graph, problem.agents, PathBudget(input, search_.give_up_steps));
    original_ = targets_;
  }
  const bool sealed = targets_.empty() && sealed_ && ChooseSealedSuspects(view, graph, problem.agents);
  if (!sealed) {
    choices_ = planner_->Plan(problem);
    commitment_.Apply(graph, targets_, problem.agents, &choices_);
  }
  if (on_plan) on_plan(input, targets_, choices_);
  if (!sealed && Ended(targets_, view)) return false;
  if (!sealed) CountDwelling(input, problem.agents);
  for (size_t a = 0; a < choices_.size(); ++a)
    if (choices_[a].status == PlanStatus::kFound)
      (*paths)[a].assign(choices_[a].path.points.begin() + 1, choices_[a].path.points.end());
  return true;
}

StepResponse SearchNavigator::AfterStep(const NavigatorInput& input, int agent, const MotionOutcome& step,
                                        core::Rng& rng) {
  const FrontierChoice& c = choices_[size_t(agent)];
  const bool found = c.status == PlanStatus::kFound;
  const bool has_path = found && c.path.points.size() > 1;
  // No path at all while there are frontiers: the agent may stand where the map leaves it no way out.
  const bool no_way = c.status == PlanStatus::kNoPath && !targets_.empty();
  const std::vector<Vec2>& trail = (*input.trails)[size_t(agent)];
  const bool stuck = stuck_.NoHeadway(trail, has_path, no_way, step.pose.position(), step.distance);
  if (blocks_ && has_path && !trail.empty()) blocks_->Record(agent, c.path.points, trail.back(), step.pose.position());
  // An agent that cannot get to its frontier (its path runs into a wall the map lacks) counts toward giving
  // it up as if it stood next to it; all of it counts as probed.  A suspect wall (search.sealed_reach) is the
  // suspect inspector's to retire, once an agent came near it.
  const bool target = found && c.frontier_id != kSealedSuspect;
  if (stuck && target && VertexInspector::IsInspection(c.frontier_id))
    inspector_->GiveUp(c.frontier_id);
  else if (stuck && target && dwell_.Count(c.frontier_id))
    given_up_.GiveUp(c.frontier_id, input.view->frontiers);
  if (!stuck_.Record(agent, stuck)) return {};
  // The paper's failures were agents stuck in place feeding identical images: perturb and re-observe.
  ++nudges_;
  return {RandomNudge(input.step_length, rng), std::nullopt};
}

}  // namespace toponav::planning

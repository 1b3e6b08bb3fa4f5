#include "experiments/trial.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>

#include "core/error.h"
#include "core/rng.h"
#include "experiments/map_drive.h"
#include "mapping/polygon_set.h"
#include "sim/motion.h"
#include "sim/noisy_sensor.h"

namespace toponav::experiments {

using core::Vec2;

double BuildingPlacementIoU(const core::World& world, const mapping::MapView& map) {
  const mapping::PolygonSet found = KnownSet(map).Holes();
  std::vector<mapping::PolygonSet> buildings;
  for (const auto& o : world.obstacles) buildings.push_back(mapping::PolygonSet::FromRing(o));
  return mapping::IoU(found, mapping::PolygonSet::JoinAll(buildings));
}

namespace {

bool Near(const std::vector<core::Segment2>& edges, const Vec2& p, double reach) {
  for (const auto& e : edges)
    if (core::DistanceToSegment(p, e) < reach) return true;
  return false;
}

// Middle and both ends near: a longer frontier reaching past (an opening beside the unmapped wall piece) is not.
bool LiesOn(const std::vector<core::Segment2>& edges, const mapping::Frontier& f, double reach) {
  return !f.points.empty() && Near(edges, f.midpoint, reach) && Near(edges, f.points.front(), reach) &&
         Near(edges, f.points.back(), reach);
}

std::vector<core::Segment2> Edges(const std::vector<Vec2>& polyline) {
  std::vector<core::Segment2> out;
  for (size_t i = 1; i < polyline.size(); ++i) out.push_back({polyline[i - 1], polyline[i]});
  return out;
}

// The part of segment ab within 'radius' of c (false if none).
bool ClipToDisc(const Vec2& a, const Vec2& b, const Vec2& c, double radius, core::Segment2* out) {
  const Vec2 d = b - a;
  const double dd = core::Dot(d, d);
  if (dd < 1e-18) {
    *out = {a, b};
    return core::Distance(a, c) <= radius;
  }
  // |a + t d - c|^2 = radius^2
  const Vec2 f = a - c;
  const double bq = 2 * core::Dot(f, d), cq = core::Dot(f, f) - radius * radius;
  const double disc = bq * bq - 4 * dd * cq;
  if (disc < 0) return false;
  const double t0 = std::max(0.0, (-bq - std::sqrt(disc)) / (2 * dd)), t1 = std::min(1.0, (-bq + std::sqrt(disc)) / (2 * dd));
  if (t0 > t1) return false;
  *out = {a + d * t0, a + d * t1};
  return true;
}

// How far a ray from 'p' along unit 'dir' runs inside 'box' (0 from outside it).
double DepthInBox(const Vec2& p, const Vec2& dir, const core::Aabb2& box) {
  if (!box.Contains(p)) return 0.0;
  double t = std::numeric_limits<double>::infinity();
  if (dir.x > 1e-12) t = std::min(t, (box.max.x - p.x) / dir.x);
  if (dir.x < -1e-12) t = std::min(t, (box.min.x - p.x) / dir.x);
  if (dir.y > 1e-12) t = std::min(t, (box.max.y - p.y) / dir.y);
  if (dir.y < -1e-12) t = std::min(t, (box.min.y - p.y) / dir.y);
  return std::isfinite(t) ? t : 0.0;
}

}  // namespace

void GivenUpFrontiers::AddPieces(const mapping::Frontier& f, const Vec2* probed_at) {
  for (const auto& e : Edges(f.points)) {
    core::Segment2 piece = e;
    if (!probed_at || probe_radius_ <= 0 || ClipToDisc(e.a, e.b, *probed_at, probe_radius_, &piece)) edges_.push_back(piece);
  }
}

void GivenUpFrontiers::GiveUp(int id, const std::vector<mapping::Frontier>& frontiers, const Vec2* probed_at) {
  if (!ids_.insert(id).second) return;
  ++given_up_;
  for (const auto& f : frontiers) {
    if (f.id != id) continue;
    extent_[id] = Edges(f.points);
    AddPieces(f, probed_at);
  }
}

void GivenUpFrontiers::Probe(int id, const std::vector<mapping::Frontier>& frontiers, const Vec2& probed_at) {
  for (const auto& f : frontiers)
    if (f.id == id) AddPieces(f, &probed_at);
}

std::vector<int> GivenUpFrontiers::Update(const std::vector<mapping::Frontier>& frontiers) {
  std::vector<int> back;
  if (reach_ <= 0) return back;
  for (const auto& f : frontiers) {
    if (Contains(f.id)) {
      const auto it = extent_.find(f.id);
      // Well past (the boundary of known space wobbles by a few units as the map changes), and once.
      if (it != extent_.end() && !it->second.empty() && !LiesOn(it->second, f, kRegrowth * reach_) &&
          taken_back_.insert(f.id).second) {
        ids_.erase(f.id);
        extent_.erase(it);
        back.push_back(f.id);
      }
    } else if (LiesOn(edges_, f, reach_)) {
      ids_.insert(f.id);
      extent_[f.id] = Edges(f.points);
    }
  }
  return back;
}

TrialResult RunSearchTrial(const core::World& world, const Config& config, const TrialOptions& o, uint64_t seed,
                           mapping::MapView* final_view) {
  const auto t0 = std::chrono::steady_clock::now();
  const SearchOptions& so = config.search;
  TOPONAV_CHECK(o.num_agents >= 1, "num_agents " << o.num_agents);
  so.Validate();
  mapping::MapperOptions mo = config.mapping;
  mo.world_bounds = world.bounds;
  // Split frontiers no shorter than the planner keeps (a split must not make an opening vanish).
  mo.frontier_split_min_length = std::max(mo.frontier_split_min_length, config.planning.frontier_min_length);
  if (!world.has_boundary()) mo.open_region = world.bounds;  // open world: its bounds are the search region
  mapping::Mapper mapper(mo);
  auto sensor = sim::CreateNoisyGroundTruthSensor(world, config.sensor, core::DeriveSeed(seed, 1));
  core::Rng rng(core::DeriveSeed(seed, 2));
  sim::MotionSim motion(world, config.motion);
  const bool open_world = !world.has_boundary();
  const double step_length = sim::StepLength(config.motion, world);
  const FrontierOrder order = open_world ? so.open_world_order : so.order;  // one agent's
  // MCMC cadence; open worlds spread the same proposals per step over more frequent calls.
  const int mcmc_every = o.mcmc_every > 0 && open_world ? o.open_world_mcmc_every : o.mcmc_every;
  const int mcmc_samples =
      o.mcmc_every > 0 ? std::max(1, int(std::lround(double(mo.mcmc_samples) * mcmc_every / o.mcmc_every))) : 0;
  TrialResult r;
  r.seed = seed;
  r.num_agents = o.num_agents;
  r.distance.assign(size_t(o.num_agents), 0.0);
  r.paths.resize(size_t(o.num_agents));
  std::vector<int> still(size_t(o.num_agents), 0);
  for (int a = 0; a < o.num_agents; ++a) {
    motion.AddAgent(world.start);
    r.paths[size_t(a)].push_back(world.start.position());
  }
  r.end_reason = "step_cap";
  mapping::MapView view;
  int unreachable = 0;
  // Frontiers an agent reached without them going away (a wall the map has not accepted yet, a sliver) are
  // given up after a while, so they cannot hold a trial forever.  (Frontiers recede as an agent approaches,
  // so "no progress" alone is not a reason: dwelling next to the target is, and so is being stuck on the way.)
  GivenUpFrontiers given_up(so.give_up_reach, so.give_up_probe_radius);
  std::map<int, int> near_steps;
  std::vector<int> committed(size_t(o.num_agents), -1);
  for (int step = 0; step < o.max_steps; ++step) {
    using Clock = std::chrono::steady_clock;
    auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
    const auto tk0 = Clock::now();
    for (int a = 0; a < o.num_agents; ++a) mapper.AddObservation(sensor->Observe(motion.Pose(a), a));
    const auto tk1 = Clock::now();
    if (mcmc_every > 0 && (step % mcmc_every == 0)) mapper.SampleMostLikelyMap(rng, mcmc_samples);
    const auto tk2 = Clock::now();
    view = mapper.View();
    const auto tk3 = Clock::now();
    r.time_map_s += seconds(tk0, tk1);
    r.time_mcmc_s += seconds(tk1, tk2);
    r.time_known_s += seconds(tk2, tk3);
    // Frontiers outside the search region (the office park's bounds) do not count.
    planning::PlannerOptions po = config.planning;
    po.clearance = std::min(std::max(po.clearance, config.motion.agent_radius + 0.25), 0.9 * po.inflation_radius);
    std::vector<planning::FrontierTarget> targets, original;
    for (int id : given_up.Update(view.frontiers)) near_steps[id] = 0;  // the same place under a new id; grown ones back
    auto frontier = [&](int id) -> const mapping::Frontier* {
      for (const auto& f : view.frontiers)
        if (f.id == id) return &f;
      return nullptr;
    };
    for (auto t : planning::FrontierTargets(view, po)) {
      if (given_up.Contains(t.frontier_id)) continue;
      // Where part of a frontier was given up, the rest of it is the target (none left: given up by place).
      const mapping::Frontier* f = frontier(t.frontier_id);
      if (so.give_up_in_part && f && !given_up.probed().empty() &&
          !planning::FrontierTargetAwayFrom(view, *f, given_up.probed(), so.give_up_reach, po, &t))
        continue;
      if (!open_world || world.bounds.Contains(t.point)) targets.push_back(t);
    }
    original = targets;
    // Gives up frontier 'id', probed at 'at'.  'stuck': agents could not get to it; then, with give_up_in_part,
    // a long one keeps the rest as a target (counted afresh), else all of it is recorded as probed.
    auto give_up = [&](int id, const Vec2& at, bool stuck) {
      const mapping::Frontier* f = frontier(id);
      if (stuck && so.give_up_in_part && f) {
        given_up.Probe(id, view.frontiers, at);
        planning::FrontierTarget rest;
        if (planning::FrontierTargetAwayFrom(view, *f, given_up.probed(), so.give_up_reach, po, &rest)) {
          near_steps[id] = 0;
          return;
        }
      }
      given_up.GiveUp(id, view.frontiers, stuck ? nullptr : &at);
    };
    // A frontier agents have stood next to for a while without it receding (the map does not take in what
    // lies beyond yet) is pushed through: its target moves into the unknown space behind it, so an agent
    // walks in and looks from there (the optimistic planner counts unknown space as free).
    for (auto& t : targets) {
      if (near_steps[t.frontier_id] <= so.give_up_steps / 2) continue;
      const Vec2 pushed = t.point + t.outward * (po.frontier_setback + so.push_distance);
      if (!open_world || world.bounds.Contains(pushed)) t.point = pushed;  // never out of the search region
    }
    // Shallow frontiers first: one with little of the search region behind it costs less (a pocket the agent
    // would otherwise leave behind and walk back to at the end).
    if (so.depth_weight > 0)
      for (auto& t : targets) t.bias = so.depth_weight * DepthInBox(t.point, t.outward, world.bounds);
    // Optimistic: unknown space counts as free (the reference plans on map walls only); the agent finds out
    // on the way and the plan is redone every step.
    const planning::VisibilityGraph graph(view, po, false);
    std::vector<Vec2> agents;
    for (int a = 0; a < o.num_agents; ++a) agents.push_back(motion.Pose(a).position());
    std::vector<planning::FrontierChoice> choices;
    if (o.num_agents > 1)
      choices = planning::AssignFrontiers(graph, targets, agents);
    else if (order == FrontierOrder::kTour)
      choices = {planning::ChooseFrontierByTour(graph, targets, agents[0])};
    else
      choices = {planning::ChooseNearestFrontier(graph, targets, agents[0])};
    // Commitment: an agent keeps heading for its previous frontier while it exists and costs at most a little
    // more than the new choice (switching back and forth between two frontiers wastes the whole trial).
    for (int a = 0; a < o.num_agents; ++a) {
      auto& c = choices[size_t(a)];
      const int prev = committed[size_t(a)];
      if (prev < 0 || c.status != planning::PlanStatus::kFound || c.frontier_id == prev) continue;
      double bias = 0;  // the new choice's
      for (const auto& t : targets)
        if (t.frontier_id == c.frontier_id) bias = t.bias;
      for (const auto& t : targets) {
        if (t.frontier_id != prev) continue;
        const planning::Path keep = graph.Plan(agents[size_t(a)], t.point);
        if (keep && keep.cost + t.bias <= so.switch_ratio * (c.path.cost + bias) + so.switch_margin) {
          bool taken = false;  // a team member may have been given it meanwhile
          for (int b = 0; b < o.num_agents; ++b) taken = taken || (b != a && choices[size_t(b)].frontier_id == prev);
          if (!taken) {
            c.frontier_id = prev;
            c.path = keep;
          }
        }
      }
    }
    for (int a = 0; a < o.num_agents; ++a)
      committed[size_t(a)] = choices[size_t(a)].status == planning::PlanStatus::kFound ? choices[size_t(a)].frontier_id : -1;
    if (o.on_plan) o.on_plan(targets, choices);
    bool any = false;
    for (const auto& c : choices) any = any || c.status == planning::PlanStatus::kFound;
    r.steps = step + 1;
    if (targets.empty() && !view.known_space.empty()) {
      r.end_reason = "explored";
      r.explored = true;
      break;
    }
    // Frontiers none of the agents can reach for a while: no reachable frontier is left, which is the
    // paper's definition of explored (a map error that walls one off shows in the IoU instead).
    unreachable = any || targets.empty() ? 0 : unreachable + 1;
    if (unreachable >= so.unreachable_steps) {
      r.end_reason = "unreachable";
      r.explored = true;
      break;
    }
    // A frontier that agents have stood next to for give_up_steps steps in all (not necessarily in a row)
    // without it going away is given up (counted per frontier, so it holds however the team shuffles).
    // Only agents that stand (moved less than half a step last step) count: one walking along or through
    // the frontier towards its pushed-through target is still finding out what lies behind it.
    std::vector<char> standing(size_t(o.num_agents), 1);
    for (int a = 0; a < o.num_agents; ++a) {
      const auto& trail = r.paths[size_t(a)];
      if (so.count_standing_only && trail.size() >= 2)
        standing[size_t(a)] = core::Distance(trail[trail.size() - 2], trail.back()) < 0.5 * step_length;
    }
    for (size_t i = 0; i < targets.size(); ++i) {
      bool near = false;
      for (int a = 0; a < o.num_agents; ++a) {
        const Vec2& p = agents[size_t(a)];
        near = near || (standing[size_t(a)] && (core::Distance(p, targets[i].point) < so.give_up_distance ||
                                                core::Distance(p, original[i].point) < so.give_up_distance));
      }
      if (near && ++near_steps[targets[i].frontier_id] > so.give_up_steps)
        give_up(targets[i].frontier_id, original[i].point, false);
    }
    int stuck = 0;
    for (int a = 0; a < o.num_agents; ++a) {
      const auto& c = choices[size_t(a)];
      std::vector<Vec2> path;
      if (c.status == planning::PlanStatus::kFound) path.assign(c.path.points.begin() + 1, c.path.points.end());
      sim::StepResult s = motion.Step(a, path);
      // Stuck: a path but no motion, or no path at all while there are frontiers (the agent may stand
      // where the map leaves it no way out; moving shows it more).
      const bool no_way = c.status == planning::PlanStatus::kNoPath && !targets.empty();
      // ... or a path but no headway over the last few steps (pacing back and forth in front of something).
      const auto& trail = r.paths[size_t(a)];
      const size_t window = size_t(2 * so.stuck_steps);
      const bool pacing = !path.empty() && trail.size() > window &&
                          core::Distance(trail[trail.size() - window], s.pose.position()) < step_length;
      if ((!path.empty() && s.distance < 0.1 * step_length) || no_way || pacing) {
        // An agent that cannot get to its frontier (its path runs into a wall the map lacks) counts toward
        // giving it up as if it stood next to it (both, if it is stuck next to it).
        if (c.status == planning::PlanStatus::kFound && ++near_steps[c.frontier_id] > so.give_up_steps) {
          // Probed where its target is: a long frontier may be reachable elsewhere along it.
          Vec2 at = c.path.points.back();
          for (size_t i = 0; i < targets.size(); ++i)
            if (targets[i].frontier_id == c.frontier_id) at = original[i].point;
          give_up(c.frontier_id, at, true);
        }
        if (++still[size_t(a)] >= so.stuck_steps) {
          // The paper's failures were agents stuck in place feeding identical images: perturb and re-observe.
          const double ang = rng.Uniform(-core::kPi, core::kPi);
          s = motion.Nudge(a, Vec2{std::cos(ang), std::sin(ang)} * step_length);
          still[size_t(a)] = 0;
          ++r.nudges;
          ++stuck;
        }
      } else {
        still[size_t(a)] = 0;
      }
      r.distance[size_t(a)] += s.distance;
      r.paths[size_t(a)].push_back(s.pose.position());
    }
    r.time_plan_s += seconds(tk3, Clock::now());
    if (o.on_step) o.on_step(view, r.paths);
  }
  if (o.mcmc_every > 0) mapper.SampleMostLikelyMap(rng);
  view = mapper.ExactView();  // (the planners' views let vertices drift a little before known space follows)
  if (o.on_step) o.on_step(view, r.paths);  // the final map, the one the metrics score
  r.iou = open_world ? BuildingPlacementIoU(world, view) : KnownSpaceIoU(world, view);
  r.success = r.explored && r.iou > so.success_iou;
  r.give_ups = given_up.given_up();
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (final_view) *final_view = view;
  return r;
}

}  // namespace toponav::experiments

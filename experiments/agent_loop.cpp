#include "experiments/agent_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "experiments/sensor_factory.h"

namespace toponav::experiments {

namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

mapping::MapperOptions MapperOptionsFor(const core::World& world, const Config& config, const LoopOptions& o) {
  mapping::MapperOptions mo = config.mapping;
  mo.world_bounds = world.bounds;
  if (!world.has_boundary()) mo.open_region = world.bounds;  // open world: its bounds are the search region
  if (o.mcmc_every <= 0) mo.defer_to_mcmc = false;           // without MCMC every vertex with enough detections is kept
  return mo;
}

// Moves every agent one step along its path, letting the policy correct each step; records paths.
void MoveAgents(const LoopState& state, const std::vector<std::vector<core::Vec2>>& paths, AgentPolicy& policy,
                sim::MotionSim& motion, core::Rng& rng, LoopResult* r) {
  TOPONAV_CHECK(paths.size() == r->paths.size(),
                "the policy planned " << paths.size() << " paths for " << r->paths.size() << " agents");
  for (size_t a = 0; a < paths.size(); ++a) {
    sim::StepResult s = motion.Step(int(a), paths[a]);
    s = policy.AfterStep(state, int(a), s, motion, rng);
    r->distance[a] += s.distance;
    r->paths[a].push_back(s.pose.position());
  }
}

// True if two observations are the same view: the same pose and the same detections (agents standing
// together, with a sensor that sees the same image the same way).
bool SameView(const core::Observation& x, const core::Observation& y) {
  auto same_detection = [](const core::Detection& a, const core::Detection& b) {
    return a.range == b.range && a.bearing == b.bearing && a.polar.xx == b.polar.xx && a.polar.xy == b.polar.xy &&
           a.polar.yy == b.polar.yy && a.labels == b.labels;
  };
  return x.pose.x == y.pose.x && x.pose.y == y.pose.y && x.pose.yaw == y.pose.yaw &&
         std::equal(x.detections.begin(), x.detections.end(), y.detections.begin(), y.detections.end(), same_detection);
}

// Adds this step's observations to the map.  An agent's view that another agent had this step (a team
// starting together) is one look, not several: counted again, its errors would pass the map's detection
// count and posterior as if seen from independent views.
void AddToMap(const std::vector<core::Observation>& observations, mapping::Mapper& mapper) {
  for (size_t a = 0; a < observations.size(); ++a) {
    bool seen = false;
    for (size_t b = 0; b < a && !seen; ++b) seen = SameView(observations[a], observations[b]);
    if (!seen) mapper.AddObservation(observations[a]);
  }
}

}  // namespace

double PathBudget(const LoopState& state, int reserve_steps) {
  TOPONAV_CHECK(state.step_length > 0, "step length " << state.step_length);
  if (state.max_steps <= 0) return std::numeric_limits<double>::infinity();
  return std::max(0, state.max_steps - state.step - reserve_steps) * state.step_length;
}

sim::StepResult NudgeRandomly(sim::MotionSim& motion, int agent, double distance, core::Rng& rng) {
  const double angle = rng.Uniform(-core::kPi, core::kPi);
  return motion.Nudge(agent, core::Vec2{std::cos(angle), std::sin(angle)} * distance);
}

LoopResult RunAgentLoop(const core::World& world, const Config& config, const LoopOptions& o, AgentPolicy& policy,
                        uint64_t seed) {
  TOPONAV_CHECK(o.num_agents >= 1 && o.max_steps >= 0, "num_agents " << o.num_agents << ", max_steps " << o.max_steps);
  Validate(config);  // a config built in code meets the same rules as a loaded one
  LoopResult r;
  r.mapper = std::make_unique<mapping::Mapper>(MapperOptionsFor(world, config, o));
  mapping::Mapper& mapper = *r.mapper;
  auto sensor = CreateSensor(SensorFor(config, world),
                             {&world, config.render, o.goal, core::DeriveSeed(seed, 1), o.goal_at_agent});
  core::Rng rng(core::DeriveSeed(seed, 2));
  const sim::MotionOptions motion_options = MotionFor(config, world);
  sim::MotionSim motion(world, motion_options);
  r.distance.assign(size_t(o.num_agents), 0.0);
  r.paths.resize(size_t(o.num_agents));
  for (int a = 0; a < o.num_agents; ++a) {
    motion.AddAgent(world.start);
    r.paths[size_t(a)].push_back(world.start.position());
  }
  LoopState state;
  state.world = &world;
  state.trails = &r.paths;
  state.step_length = motion_options.step_length;
  state.max_steps = o.max_steps;
  std::vector<core::Observation> observations;
  state.observations = &observations;
  mapping::MapView view;
  state.view = &view;
  std::vector<std::vector<core::Vec2>> paths(size_t(o.num_agents));
  for (int step = 0; step < o.max_steps; ++step) {
    const auto t0 = Clock::now();
    state.step = step;
    state.poses.clear();
    for (int a = 0; a < o.num_agents; ++a) state.poses.push_back(motion.Pose(a));
    observations.clear();
    for (int a = 0; a < o.num_agents; ++a) observations.push_back(sensor->Observe(state.poses[size_t(a)], a));
    AddToMap(observations, mapper);
    const auto t1 = Clock::now();
    if (o.mcmc_every > 0 && step % o.mcmc_every == 0) {
      mapper.SampleMostLikelyMap(rng, o.mcmc_samples);
      ++r.mcmc_calls;
    }
    const auto t2 = Clock::now();
    view = mapper.View();
    const auto t3 = Clock::now();
    r.observe_s += Seconds(t0, t1);
    r.mcmc_s += Seconds(t1, t2);
    r.view_s += Seconds(t2, t3);
    for (auto& p : paths) p.clear();
    r.steps = step + 1;
    if (!policy.Plan(state, &paths)) {
      r.ended_by_policy = true;
      r.plan_s += Seconds(t3, Clock::now());
      break;
    }
    MoveAgents(state, paths, policy, motion, rng, &r);
    r.plan_s += Seconds(t3, Clock::now());
    if (o.on_step) o.on_step(view, r.paths);
  }
  if (o.mcmc_every > 0) mapper.SampleMostLikelyMap(rng);
  r.final_view = mapper.ExactView();  // (the per-step views let vertices drift a little before known space follows)
  if (o.on_step) o.on_step(r.final_view, r.paths);
  return r;
}

}  // namespace toponav::experiments

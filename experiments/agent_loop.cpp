#include "experiments/agent_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "experiments/sensor_factory.h"
#include "sim/motion.h"

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

// Moves every agent one step along its path, nudged where the navigator asks; records paths.
void MoveAgents(const planning::NavigatorInput& state, const std::vector<std::vector<core::Vec2>>& paths,
                planning::Navigator& navigator, sim::MotionSim& motion, core::Rng& rng, LoopResult* r) {
  TOPONAV_CHECK(paths.size() == r->paths.size(),
                "the navigator planned " << paths.size() << " paths for " << r->paths.size() << " agents");
  for (size_t a = 0; a < paths.size(); ++a) {
    sim::StepResult s = motion.Step(int(a), paths[a]);
    const planning::StepResponse response = navigator.AfterStep(state, int(a), {s.pose, s.distance, s.blocked}, rng);
    if (response.contact) r->mapper->AddContact(*response.contact);
    if (response.nudge) s = motion.Nudge(int(a), *response.nudge);
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

// This step's observations from 'poses', added to the map, MCMC on its cadence: the map's view (timed in 'r').
mapping::MapView Sense(const std::vector<core::Pose2>& poses, core::VertexSensorInterface& sensor,
                       const LoopOptions& o, int step, core::Rng& rng, std::vector<core::Observation>* observations,
                       LoopResult* r) {
  const auto t0 = Clock::now();
  observations->clear();
  for (size_t a = 0; a < poses.size(); ++a) observations->push_back(sensor.Observe(poses[a], int(a)));
  AddToMap(*observations, *r->mapper);
  const auto t1 = Clock::now();
  if (o.mcmc_every > 0 && step % o.mcmc_every == 0) {
    r->mapper->SampleMostLikelyMap(rng, o.mcmc_samples);
    ++r->mcmc_calls;
  }
  const auto t2 = Clock::now();
  mapping::MapView view = r->mapper->View();
  r->observe_s += Seconds(t0, t1);
  r->mcmc_s += Seconds(t1, t2);
  r->view_s += Seconds(t2, Clock::now());
  return view;
}

}  // namespace

LoopResult RunAgentLoop(const core::World& world, const Config& config, const LoopOptions& o,
                        planning::Navigator& navigator, uint64_t seed) {
  TOPONAV_CHECK(o.num_agents >= 1 && o.max_steps >= 0, "num_agents " << o.num_agents << ", max_steps " << o.max_steps);
  Validate(config);  // a config built in code meets the same rules as a loaded one
  LoopResult r;
  r.mapper = std::make_unique<mapping::Mapper>(MapperOptionsFor(world, config, o));
  mapping::Mapper& mapper = *r.mapper;
  auto sensor = CreateSensor(SensorFor(config, world),
                             {&world, config.render, o.goal, core::DeriveSeed(seed, 1)});
  core::Rng rng(core::DeriveSeed(seed, 2));
  const sim::MotionOptions motion_options = MotionFor(config, world);
  sim::MotionSim motion(world, motion_options);
  r.distance.assign(size_t(o.num_agents), 0.0);
  r.paths.resize(size_t(o.num_agents));
  for (int a = 0; a < o.num_agents; ++a) {
    motion.AddAgent(world.start);
    r.paths[size_t(a)].push_back(world.start.position());
  }
  planning::NavigatorInput state;
  state.trails = &r.paths;
  state.step_length = motion_options.step_length;
  state.max_steps = o.max_steps;
  std::vector<core::Observation> observations;
  state.observations = &observations;
  mapping::MapView view;
  state.view = &view;
  std::vector<std::vector<core::Vec2>> paths(size_t(o.num_agents));
  for (int step = 0; step < o.max_steps; ++step) {
    state.step = step;
    state.poses.clear();
    for (int a = 0; a < o.num_agents; ++a) state.poses.push_back(motion.Pose(a));
    view = Sense(state.poses, *sensor, o, step, rng, &observations, &r);
    const auto t3 = Clock::now();
    for (auto& p : paths) p.clear();
    r.steps = step + 1;
    if (!navigator.Plan(state, &paths)) {
      r.ended_by_navigator = true;
      r.plan_s += Seconds(t3, Clock::now());
      break;
    }
    MoveAgents(state, paths, navigator, motion, rng, &r);
    r.plan_s += Seconds(t3, Clock::now());
    if (o.on_step) o.on_step(view, r.paths);
  }
  if (o.mcmc_every > 0) mapper.SampleMostLikelyMap(rng);
  r.final_view = mapper.ExactView();  // (the per-step views let vertices drift a little before known space follows)
  if (o.on_step) o.on_step(r.final_view, r.paths);
  return r;
}

}  // namespace toponav::experiments

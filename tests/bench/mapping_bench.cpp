// Map-building speed along one long drive (labyrinth seed 1, whole-free-space tour, noisy sensor), as a
// trial uses it: every step adds an observation and asks for the map view (known space, frontiers); MCMC
// runs every 5 steps.  Run: build/bench_mapping
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "core/rng.h"
#include "mapping/mapping.h"
#include "sim/sim.h"

namespace toponav {
namespace {

struct Drive {
  core::World world;
  std::vector<core::Observation> observations;
};

const Drive& LongDrive() {
  static const Drive drive = [] {
    Drive d;
    d.world = sim::GenerateLabyrinth({}, 1);
    auto path = sim::CoverageTour(d.world, d.world.start.position(), 30.0, 3.0);
    auto sensor = sim::CreateNoisyGroundTruthSensor(d.world, {}, 7);
    sim::MotionSim motion(d.world, {});
    const int a = motion.AddAgent(d.world.start);
    size_t wp = 1;
    while (d.observations.size() < 420) {
      d.observations.push_back(sensor->Observe(motion.Pose(a), 0));
      if (wp >= path.size()) wp = 1;  // loop the tour
      const auto s = motion.Step(a, std::vector<core::Vec2>(path.begin() + long(wp), path.end()));
      while (wp < path.size() && core::Distance(s.pose.position(), path[wp]) < 0.9) ++wp;
      if (s.blocked) ++wp;
    }
    return d;
  }();
  return drive;
}

// The mapper after 'steps' steps of the drive, MCMC every 5 steps (wall_front_vertex_tolerance 'front').
std::unique_ptr<mapping::Mapper> MapperAt(int steps, core::Rng& rng, double front = 0.0) {
  mapping::MapperOptions o;
  o.world_bounds = LongDrive().world.bounds;
  o.wall_front_vertex_tolerance = front;
  auto m = std::make_unique<mapping::Mapper>(o);
  for (int s = 0; s < steps; ++s) {
    m->AddObservation(LongDrive().observations[size_t(s)]);
    if ((s + 1) % 5 == 0) m->SampleMostLikelyMap(rng);
  }
  m->View();
  return m;
}

// Per-step update (AddObservation + View) over the 20 steps starting at step range(0), with
// wall_front_vertex_tolerance range(1) (the maze configs' 1: every pair checks the map vertices in front).
void BM_MapStep(benchmark::State& state) {
  const int start = int(state.range(0));
  core::Rng rng(3);
  auto m = MapperAt(start, rng, double(state.range(1)));
  int s = start;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    m->AddObservation(LongDrive().observations[size_t(s)]);
    benchmark::DoNotOptimize(m->View());
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(dt);
    if (getenv("TOPONAV_STEPS")) fprintf(stderr, "step %d: %.2f ms\n", s, dt * 1e3);
    ++s;
    state.PauseTiming();
    if (s % 5 == 0) m->SampleMostLikelyMap(rng);
    state.ResumeTiming();
  }
}
BENCHMARK(BM_MapStep)
    ->ArgsProduct({{50, 200, 400}, {0, 1}})
    ->Iterations(20)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

// One MCMC call (50 samples) on the map of step range(0).
void BM_Mcmc50(benchmark::State& state) {
  core::Rng rng(3);
  auto m = MapperAt(int(state.range(0)), rng);
  for (auto _ : state) benchmark::DoNotOptimize(m->SampleMostLikelyMap(rng));
}
BENCHMARK(BM_Mcmc50)->Arg(50)->Arg(200)->Arg(400)->Iterations(10)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace toponav



namespace toponav {
namespace {
void BM_LogPosterior(benchmark::State& state) {
  core::Rng rng(3);
  auto m = MapperAt(int(state.range(0)), rng);
  for (auto _ : state) benchmark::DoNotOptimize(m->LogPosterior());
}
BENCHMARK(BM_LogPosterior)->Arg(200)->Iterations(10)->Unit(benchmark::kMillisecond);
void BM_View(benchmark::State& state) {
  core::Rng rng(3);
  auto m = MapperAt(int(state.range(0)), rng);
  for (auto _ : state) benchmark::DoNotOptimize(m->View());
}
BENCHMARK(BM_View)->Arg(200)->Iterations(10)->Unit(benchmark::kMillisecond);
}  // namespace
}  // namespace toponav
BENCHMARK_MAIN();

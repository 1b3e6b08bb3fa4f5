// Speed of world generation and ray-cast ground truth.  Run: build/bench_sim [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include "core/rng.h"
#include "sim/sim.h"

namespace toponav::sim {
namespace {

void BM_GenerateWorld(benchmark::State& state) {
  const auto kind = static_cast<core::WorldKind>(state.range(0));
  const WorldOptions options;
  uint64_t seed = 0;
  for (auto _ : state) benchmark::DoNotOptimize(GenerateWorld(kind, options, seed++));
  state.SetLabel(core::ToString(kind));
}
BENCHMARK(BM_GenerateWorld)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Visible vertices (with labels) from random free poses.
void BM_VisibleVertices(benchmark::State& state) {
  const auto kind = static_cast<core::WorldKind>(state.range(0));
  const core::World w = GenerateWorld(kind, {}, 1);
  const RayCaster rc(w);
  core::Rng rng(2);
  std::vector<core::Pose2> poses;
  while (poses.size() < 256) {
    const core::Vec2 p{rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
    if (core::IsFree(w, p)) poses.push_back({p.x, p.y, rng.Uniform(-3, 3)});
  }
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(rc.VisibleVertices(poses[i++ % poses.size()], 100.0));
  state.SetLabel(core::ToString(kind));
}
BENCHMARK(BM_VisibleVertices)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

void BM_VisibilityPolygon(benchmark::State& state) {
  const core::World w = GenerateLabyrinth({}, 1);
  const RayCaster rc(w);
  for (auto _ : state) benchmark::DoNotOptimize(rc.VisibilityPolygon(w.start.position()));
}
BENCHMARK(BM_VisibilityPolygon)->Unit(benchmark::kMicrosecond);

void BM_DepthScan512(benchmark::State& state) {
  const core::World w = GenerateLabyrinth({}, 1);
  const RayCaster rc(w);
  for (auto _ : state) benchmark::DoNotOptimize(rc.DepthScan(w.start, 512, 100.0));
}
BENCHMARK(BM_DepthScan512)->Unit(benchmark::kMicrosecond);

void BM_MotionStep(benchmark::State& state) {
  const core::World w = GenerateLabyrinth({}, 1);
  MotionSim sim(w, {});
  const int a = sim.AddAgent(w.start);
  core::Rng rng(3);
  core::Vec2 target = w.start.position();
  int k = 0;
  for (auto _ : state) {
    if (k++ % 20 == 0)
      target = {rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
    benchmark::DoNotOptimize(sim.Step(a, {target}));
  }
}
BENCHMARK(BM_MotionStep)->Unit(benchmark::kMicrosecond);

// One 128x512 RGB panorama (4 cube faces + resampling) from poses along a path through the world.
void BM_RenderPanorama(benchmark::State& state) {
  const auto kind = static_cast<core::WorldKind>(state.range(0));
  const core::World w = GenerateWorld(kind, {}, 1);
  const Renderer renderer(w, {});
  std::vector<core::Vec2> path = w.guide_path;
  if (path.size() < 2) path = FreePath(w, w.start.position(), w.goal, 3.0);
  const auto poses = PosesAlong(path, 64);
  renderer.Render(poses[0]);  // context creation and scene upload happen once, outside the timing
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(renderer.Render(poses[i++ % poses.size()]));
  state.SetLabel(std::string(core::ToString(kind)) + ", " + std::to_string(renderer.num_triangles()) + " triangles");
}
BENCHMARK(BM_RenderPanorama)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RenderPanoramaWithDepthAndIds(benchmark::State& state) {
  const core::World w = GenerateLabyrinth({}, 1);
  const Renderer renderer(w, {});
  renderer.Render(w.start);
  for (auto _ : state) benchmark::DoNotOptimize(renderer.Render(w.start, kRenderRgb | kRenderDepth | kRenderIds));
}
BENCHMARK(BM_RenderPanoramaWithDepthAndIds)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace toponav::sim

BENCHMARK_MAIN();

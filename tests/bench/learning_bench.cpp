// The learned vertex sensor's speed on this machine: inference per panorama (the vertex network and its LSP
// extension) and training steps, for a quarter-width (CPU) net and the paper-size net.
#include <benchmark/benchmark.h>

#include "learning/learning.h"
#include "learning/vertex_model.h"
#include "sim/raycast.h"
#include "sim/render.h"
#include "sim/worlds.h"

namespace toponav {
namespace {

struct Data {
  core::Panorama image;
  sim::VertexLabelGrid labels;
};

const Data& OnePanorama() {
  static const Data d = [] {
    const core::World w = sim::GenerateLabyrinth({}, 4);
    Data x;
    x.image = sim::Renderer(w, {}).Render(w.start);
    x.labels = sim::RasterizeVertexLabels(sim::RayCaster(w).VisibleVertices(w.start, 100.0), core::RangeBearingGrid{});
    return x;
  }();
  return d;
}

// Arg: width in percent.
void BM_PredictPanorama(benchmark::State& state) {
  learning::SelectBackend(false, 2);
  learning::VertexNetOptions o;
  o.width = state.range(0) / 100.0;
  const learning::VertexModel m(o, 1);
  const Data& d = OnePanorama();
  for (auto _ : state) benchmark::DoNotOptimize(m.Predict(d.image));
  state.counters["parameters"] = double(m.num_parameters());
}
BENCHMARK(BM_PredictPanorama)->Arg(25)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

// The LSP network's inference (the vertex grid and the 64x256 subgoal grid for a goal).  Arg: width in percent.
void BM_PredictWithGoal(benchmark::State& state) {
  learning::SelectBackend(false, 2);
  learning::VertexNetOptions o;
  o.width = state.range(0) / 100.0;
  o.subgoal = true;
  const learning::VertexModel m(o, 1);
  const Data& d = OnePanorama();
  for (auto _ : state) benchmark::DoNotOptimize(m.PredictWithGoal(d.image, {80.0, 1.0}));
  state.counters["parameters"] = double(m.num_parameters());
}
BENCHMARK(BM_PredictWithGoal)->Arg(25)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

// Args: width in percent, batch size.
void BM_TrainStep(benchmark::State& state) {
  learning::SelectBackend(false, 2);
  learning::VertexNetOptions o;
  o.width = state.range(0) / 100.0;
  learning::VertexModel m(o, 1);
  const Data& d = OnePanorama();
  const std::vector<learning::LabelledImage> batch(size_t(state.range(1)), {&d.image, &d.labels, {}, nullptr});
  for (auto _ : state) benchmark::DoNotOptimize(m.TrainStep(batch, 1e-3));
}
BENCHMARK(BM_TrainStep)->Args({25, 8})->Args({100, 8})->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace toponav

BENCHMARK_MAIN();

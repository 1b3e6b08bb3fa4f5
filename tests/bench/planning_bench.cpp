// Learned Subgoal Planning's ordering solve: the exact dynamic program over (tried set, last frontier) for
// n frontiers (the target: 12 under 1 ms on 2 cores; 14 and 16 for the documented limit).
#include <benchmark/benchmark.h>

#include "core/geometry.h"
#include "core/rng.h"
#include "planning/subgoal_ordering.h"

namespace toponav {
namespace {

planning::OrderingProblem Problem(int n) {
  core::Rng rng(static_cast<uint64_t>(n));
  planning::OrderingProblem p;
  std::vector<core::Vec2> at;
  for (int i = 0; i < n; ++i) at.push_back({rng.Uniform(0, 150), rng.Uniform(0, 190)});
  for (int i = 0; i < n; ++i) {
    p.properties.push_back({rng.Uniform(0.05, 0.95), rng.Uniform(0, 80), rng.Uniform(0, 300)});
    p.robot_cost.push_back(core::Distance(at[size_t(i)], {75, 95}));
    p.goal_cost.push_back(core::Distance(at[size_t(i)], {10, 10}));
    std::vector<double> row;
    for (int j = 0; j < n; ++j) row.push_back(core::Distance(at[size_t(i)], at[size_t(j)]));
    p.between.push_back(row);
  }
  return p;
}

void BM_BestOrdering(benchmark::State& state) {
  const planning::OrderingProblem p = Problem(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(planning::BestOrdering(p));
}
BENCHMARK(BM_BestOrdering)->Arg(8)->Arg(12)->Arg(14)->Arg(16)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace toponav

BENCHMARK_MAIN();

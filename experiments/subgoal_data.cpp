#include "experiments/subgoal_data.h"

#include <utility>

#include "core/error.h"
#include "experiments/navigation_trial.h"
#include "experiments/trial.h"
#include "sim/raycast.h"
#include "sim/render.h"
#include "sim/worlds.h"

namespace toponav::experiments {

namespace {

constexpr double kSeenMargin = 1.8;  // a frontier cell this close to what the pose sees counts as seen

}  // namespace

std::vector<SubgoalSample> CollectSubgoalSamples(const core::World& world, const Config& config, uint64_t seed,
                                                 int every, const core::RangeBearingGrid& grid) {
  TOPONAV_CHECK(every >= 1, "every " << every);
  const sim::RayCaster rays(world);
  const planning::TrueFreeSpace truth(world, config.lsp.cell, config.lsp.clearance);
  const bool maze = world.kind == core::WorldKind::kGuidedMaze;
  std::vector<SubgoalSample> out;
  const auto sample = [&](const planning::NavigatorInput& state, const std::vector<planning::FrontierTarget>& targets) {
    if (state.step % every != 0 || targets.empty()) return;
    const std::vector<const mapping::Frontier*> frontiers = planning::TargetFrontiers(*state.view, targets);
    const core::Pose2 pose = state.poses[0];
    const core::Vec2 goal = maze ? world.goal : pose.position();  // a search's goal: where the agent stands
    const planning::SubgoalGrid sg(*state.view, frontiers, pose.position(), goal, config.lsp.cell, world.bounds);
    if (maze && sg.goal_known()) return;
    const std::vector<planning::SubgoalProperties> p = planning::TrueSubgoalProperties(
        sg, truth, maze ? sg.Distances() : planning::ProblemWithoutDistances(frontiers.size()));
    const core::Ring seen = rays.VisibilityPolygon(pose.position());
    const auto visible = [&](const core::Vec2& q) {
      return core::Contains(seen, q) || core::NearRing(q, seen, kSeenMargin);
    };
    planning::SubgoalLabelGrid labels = planning::RasterizeSubgoalLabels(sg, p, pose, grid, visible);
    SubgoalSample s{world.seed, state.step, pose, goal, 0, std::move(labels)};
    for (size_t f = 0; f < frontiers.size(); ++f)
      for (int c : sg.cells(f))
        if (visible(sg.raster().Center(c))) {
          ++s.frontiers;
          break;
        }
    if (s.frontiers > 0) out.push_back(std::move(s));
  };
  if (maze) {
    NavigationTrialOptions o;
    o.max_steps = config.bench.max_steps;
    o.mcmc_every = config.bench.mcmc_every;
    o.on_plan = sample;
    RunNavigationTrial(world, config, o, seed);
  } else {
    TrialOptions o;
    o.max_steps = config.bench.max_steps;
    o.mcmc_every = config.bench.mcmc_every;
    o.open_world_mcmc_every = config.open_world.mcmc_every;
    o.on_plan = [&](const planning::NavigatorInput& state, const std::vector<planning::FrontierTarget>& targets,
                    const std::vector<planning::FrontierChoice>&) { sample(state, targets); };
    RunSearchTrial(world, config, o, seed);
  }
  return out;
}

std::string SubgoalRunsText(const SubgoalDataOptions& o) {
  return o.kind == core::WorldKind::kGuidedMaze ? "optimistic runs" : "one-agent searches (the goal at the agent)";
}

std::vector<SubgoalExample> MakeSubgoalExamples(const Config& config, sim::Split split,
                                                const std::function<void(int, int, size_t)>& progress) {
  const SubgoalDataOptions& o = config.subgoal_data;
  o.Validate();
  const int first = split == sim::Split::kTrain ? o.train_first_seed : o.val_first_seed;
  const int count = split == sim::Split::kTrain ? o.train_num_seeds : o.val_num_seeds;
  const core::RangeBearingGrid vertex_grid, subgoal_grid = core::kSubgoalGrid;
  std::vector<SubgoalExample> out;
  for (int k = 0; k < count; ++k) {
    const uint64_t seed = uint64_t(first + k);
    const core::World world = sim::GenerateWorld(o.kind, config.worlds, seed);
    const sim::Renderer renderer(world, config.render);
    const sim::RayCaster rays(world);
    for (SubgoalSample& s : CollectSubgoalSamples(world, config, seed, o.every, subgoal_grid)) {
      SubgoalExample e{seed,
                       s.step,
                       s.pose,
                       renderer.Render(s.pose),
                       sim::RasterizeVertexLabels(rays.VisibleVertices(s.pose, vertex_grid.max_range), vertex_grid),
                       core::GoalInAgentFrame(s.pose, s.goal),
                       std::move(s.labels)};
      out.push_back(std::move(e));
    }
    if (progress) progress(k + 1, count, out.size());
  }
  return out;
}

}  // namespace toponav::experiments

#include "experiments/cli/trial_command.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "experiments/cli/common.h"
#include "experiments/cli_parse.h"
#include "experiments/experiments.h"
#include "experiments/navigation_report.h"

namespace toponav::cli {

namespace fs = std::filesystem;

namespace {

struct TrialArgs : WorldSource {
  std::string out = "results/trial";
  std::string video;
  std::string trace;
  std::string planner;  // a goal-directed planner: a navigation trial from the world's start to its goal
  int frames_every = 0;
  experiments::TrialOptions trial;
  std::optional<int> max_steps, mcmc_every, open_world_mcmc_every;  // unset: the config's
};

// The --trace CSV at 'path' with the header's first columns written (not open when 'path' is empty).
std::ofstream OpenTrace(const std::string& path, const std::string& header) {
  std::ofstream f;
  if (path.empty()) return f;
  f.open(path);
  if (!f) throw core::DataError(path, "cannot write the trace file");
  f << header;
  return f;
}

// One row of the navigation trace (columns as its header in RunNavigationCommand).
std::string NavigationTraceRow(int step, const core::Vec2& at, const core::Vec2& goal, const mapping::MapView& v,
                               const std::vector<planning::FrontierEstimate>& ps) {
  double min_ps = ps.empty() ? std::nan("") : 1.0;
  core::Vec2 subgoal{std::nan(""), std::nan("")};
  double subgoal_ps = std::nan("");
  for (const auto& e : ps) {
    min_ps = std::min(min_ps, e.ps);
    if (!e.subgoal) continue;
    subgoal = core::PointAlong(e.points, 0.5 * core::PolylineLength(e.points));
    subgoal_ps = e.ps;
  }
  return fmt::format("{},{:.2f},{:.2f},{:.2f},{},{},{:.3f},{:.2f},{:.2f},{:.3f},{},{},{:.1f}\n", step, at.x, at.y,
                     core::Distance(at, goal), v.frontiers.size(), ps.size(), min_ps, subgoal.x, subgoal.y,
                     subgoal_ps, v.vertices.size(), v.walls.size(), v.known_area());
}

// A goal-directed navigation trial with the named planner (trial.png; a frame every --frames-every steps and
// with --video a video, each with the way the agent followed; with --trace a CSV row a step).
int RunNavigationCommand(const TrialArgs& a) {
  const experiments::Config cfg = LoadOrDefault(a.config);
  const auto planner = experiments::ParseGoalPlanner(a.planner);
  if (!planner)
    throw core::ConfigError("<command line>", "--planner", a.planner,
                            "not a goal-directed planner (optimistic, oracle, lsp, known)");
  const uint64_t seed = experiments::ParseSeed(a.seed);
  const core::World w = StartAtPose(WorldFromSource(a, cfg), a.pose);
  EnsureDir(a.out);
  experiments::NavigationTrialOptions n;
  n.planner = *planner;
  n.max_steps = a.max_steps.value_or(cfg.bench.max_steps);
  n.mcmc_every = a.mcmc_every.value_or(cfg.bench.mcmc_every);
  int step = 0;
  experiments::MapPictureExtras extras{w.goal, {}, {}, {}, {}};
  n.on_decision = [&](const experiments::NavigationDecision& d) {
    extras.frontier_ps = d.estimates;
    extras.way = d.way;
  };
  std::ofstream trace = OpenTrace(
      a.trace,
      "step,x,y,distance_to_goal,frontiers,estimated_pieces,min_ps,subgoal_x,subgoal_y,subgoal_ps,map_vertices,"
      "map_walls,known_area");
  if (trace.is_open()) trace << "\n";
  std::unique_ptr<experiments::TrialVideo> video;
  if (!a.video.empty()) video = std::make_unique<experiments::TrialVideo>(w, cfg.picture, a.video);
  if (a.frames_every > 0 || trace.is_open() || video)
    n.on_step = [&](const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) {
      if (a.frames_every > 0 && step % a.frames_every == 0)
        experiments::DrawMapPicture(w, v, paths, cfg.picture,
                                    (fs::path(a.out) / fmt::format("frame_{:04d}.png", step)).string(), extras);
      if (video) video->AddFrame(v, paths, extras);
      if (trace.is_open())  // labelled like the search trace: moves made (the final map repeats the last)
        trace << NavigationTraceRow(int(paths.front().size()) - 1, paths.front().back(), w.goal, v,
                                    extras.frontier_ps);
      ++step;
    };
  mapping::MapView view;
  const auto r = experiments::RunNavigationTrial(w, cfg, n, seed, &view);
  if (trace.is_open()) fmt::print("wrote {} ({} rows)\n", a.trace, step);
  if (video) fmt::print("wrote {} ({} frames)\n", a.video, video->frames());
  const std::string picture = (fs::path(a.out) / "trial.png").string();
  experiments::DrawMapPicture(w, view, {r.path}, cfg.picture, picture,
                              {w.goal, r.frontier_ps, r.blocks, r.scan_walls, {}});
  fmt::print("seed {} planner {}: {} after {} steps, distance {:.1f}, IoU {:.4f}, nudges {}, motion blocks {}, "
             "longest hold {}, scan steps {}, {:.1f} s -> {}\n",
             seed, r.planner, r.end_reason, r.steps, r.distance, r.iou, r.nudges, r.blocks.size(), r.longest_hold,
             r.scan_steps, r.wall_time_s, picture);
  return 0;
}

// The search trial's --trace CSV: one row a step (the map the planners used; the last row is the final map the
// metrics score) with what the planners chose that step (targets on offer; each agent's frontier and the end
// of its path; the final row has none).
class SearchTrace {
 public:
  SearchTrace(const std::string& path, int num_agents)
      : file_(OpenTrace(path, "step,iou,frontiers,targets,map_vertices,map_walls")) {
    if (!file_.is_open()) return;
    for (int i = 0; i < num_agents; ++i) file_ << fmt::format(",x{0},y{0},frontier{0},goal_x{0},goal_y{0}", i);
    file_ << "\n";
  }
  bool is_open() const { return file_.is_open(); }

  void Plan(const std::vector<planning::FrontierTarget>& targets,
            const std::vector<planning::FrontierChoice>& choices) {
    plan_targets_ = std::to_string(targets.size());
    plan_goals_.clear();
    for (const auto& c : choices) {
      const bool found = c.status == planning::PlanStatus::kFound && !c.path.points.empty();
      plan_goals_.push_back(
          found ? fmt::format("{},{:.2f},{:.2f}", c.frontier_id, c.path.points.back().x, c.path.points.back().y)
                : std::string(",,"));
    }
  }

  void Row(const core::World& w, const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) {
    file_ << fmt::format("{},{:.5f},{},{},{},{}", paths.front().size() - 1, experiments::SearchIoU(w, v),
                         v.frontiers.size(), plan_targets_, v.vertices.size(), v.walls.size());
    for (size_t i = 0; i < paths.size(); ++i)
      file_ << fmt::format(",{:.2f},{:.2f},{}", paths[i].back().x, paths[i].back().y,
                           i < plan_goals_.size() ? plan_goals_[i] : ",,");
    file_ << "\n";
    plan_targets_.clear();
    plan_goals_.clear();
  }

 private:
  std::ofstream file_;
  std::string plan_targets_;
  std::vector<std::string> plan_goals_;
};

// Open worlds: where the building-placement IoU is lost (each building's IoU, spurious enclosed ground).
void PrintBuildingPlacement(const core::World& w, const mapping::MapView& view) {
  const auto b = experiments::BreakDownBuildingPlacement(w, view);
  std::string per;
  for (double x : b.building_iou) per += fmt::format(" {:.3f}", x);
  fmt::print("buildings' IoU with the holes that overlap them:{}; holes overlapping no building: {:.1f} units^2\n",
             per, b.spurious_area);
}

void PrintSearchResult(const experiments::TrialResult& r, uint64_t seed, const std::string& picture) {
  double total = 0;
  for (double d : r.distance) total += d;
  fmt::print("seed {} agents {}: {} after {} steps, IoU {:.4f}, success {}, distance {:.1f}, nudges {}, "
             "frontiers given up {}, motion blocks {}, vertex inspections {}, {:.1f} s -> {}\n",
             seed, r.num_agents, r.end_reason, r.steps, r.iou, r.success ? "yes" : "no", total, r.nudges,
             r.give_ups, r.blocks.size(), r.inspections, r.wall_time_s, picture);
}

int RunSearchCommand(const TrialArgs& a) {
  const experiments::Config cfg = LoadOrDefault(a.config);
  const uint64_t seed = experiments::ParseSeed(a.seed);
  const core::World w = StartAtPose(WorldFromSource(a, cfg), a.pose);
  EnsureDir(a.out);
  experiments::TrialOptions t = a.trial;
  t.max_steps = a.max_steps.value_or(cfg.bench.max_steps);
  t.mcmc_every = a.mcmc_every.value_or(cfg.bench.mcmc_every);
  t.open_world_mcmc_every = a.open_world_mcmc_every.value_or(cfg.open_world.mcmc_every);
  std::unique_ptr<experiments::TrialVideo> video;
  if (!a.video.empty()) video = std::make_unique<experiments::TrialVideo>(w, cfg.picture, a.video);
  SearchTrace trace(a.trace, t.num_agents);
  if (trace.is_open())
    t.on_plan = [&](const planning::NavigatorInput&, const std::vector<planning::FrontierTarget>& targets,
                    const std::vector<planning::FrontierChoice>& choices) { trace.Plan(targets, choices); };
  if (video || trace.is_open())
    t.on_step = [&](const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) {
      if (video) video->AddFrame(v, paths);
      if (trace.is_open()) trace.Row(w, v, paths);
    };
  mapping::MapView view;
  const auto r = experiments::RunSearchTrial(w, cfg, t, seed, &view);
  if (video) fmt::print("wrote {} ({} frames)\n", a.video, video->frames());
  if (trace.is_open()) fmt::print("wrote {} ({} steps)\n", a.trace, r.steps);
  experiments::MapPictureExtras extras;
  extras.blocks = r.blocks;
  const std::string picture = (fs::path(a.out) / "trial.png").string();
  experiments::DrawMapPicture(w, view, r.paths, cfg.picture, picture, extras);
  PrintSearchResult(r, seed, picture);
  if (!w.has_boundary()) PrintBuildingPlacement(w, view);
  return 0;
}

CLI::App* AddTrialCommand(CLI::App& app, TrialArgs* a) {
  CLI::App* trial = app.add_subcommand("trial", "Run one search trial (1 agent, or a team over distinct frontiers), "
                                                "or with --planner one goal-directed navigation trial");
  AddWorldSourceOptions(trial, a, "YAML config (sensor:, mapping:, motion:)");
  trial->add_option("--agents", a->trial.num_agents, "Number of agents")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  trial->add_option("--max-steps", a->max_steps, "Step cap (default: the config's bench.max_steps)")
      ->check(CLI::Range(1, 100000));
  trial->add_option("--mcmc-every", a->mcmc_every,
                    "MCMC every this many steps, 0: never (default: the config's bench.mcmc_every)")
      ->check(CLI::Range(0, 100000));
  trial->add_option("--open-world-mcmc-every", a->open_world_mcmc_every,
                    "MCMC every this many steps in open worlds, at the same proposals per step (default: the config's "
                    "open_world.mcmc_every)")
      ->check(CLI::Range(1, 100000));
  trial->add_option("--out", a->out, "Output directory: trial.png")->capture_default_str();
  trial->add_option("--video", a->video, "Also write a video of the trial, one frame a step (.mp4 or .avi)");
  trial->add_option("--trace", a->trace,
                    "Also write a CSV with one row a step: IoU, frontiers and targets, map size, agent positions and "
                    "goals (navigation: position, distance to the goal, frontiers, estimates, map size)");
  trial->add_option("--planner", a->planner,
                    "Run goal-directed navigation (start to goal, one agent) with this planner instead: optimistic, "
                    "oracle, lsp, known (the optimistic planner on the true walls: the floor)");
  trial->add_option("--frames-every", a->frames_every,
                    "Navigation: also draw the map every this many steps (frame_NNNN.png)")
      ->check(CLI::Range(1, 100000));
  return trial;
}

}  // namespace

struct TrialCommand::Impl {
  TrialArgs args;
  CLI::App* cmd = nullptr;
};

TrialCommand::TrialCommand(CLI::App& app) : impl_(std::make_unique<Impl>()) {
  impl_->cmd = AddTrialCommand(app, &impl_->args);
}
TrialCommand::~TrialCommand() = default;

std::optional<int> TrialCommand::Run() {
  if (!*impl_->cmd) return std::nullopt;
  return impl_->args.planner.empty() ? RunSearchCommand(impl_->args) : RunNavigationCommand(impl_->args);
}

}  // namespace toponav::cli

// toponav: the command-line front end.  Subcommands: world, observe, render, map, trial, bench, report, demo,
// info here; datagen, train and eval-sensor in experiments/cli/learning_commands.cpp.
#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/error.h"
#include "experiments/batch.h"
#include "experiments/cli/common.h"
#include "experiments/cli/learning_commands.h"
#include "experiments/cli/sensing_commands.h"
#include "experiments/cli_parse.h"
#include "experiments/navigation_report.h"
#include "experiments/experiments.h"
#include "learning/learning.h"
#include "mapping/polygon_set.h"
#include "sim/sim.h"

namespace fs = std::filesystem;
using namespace toponav;

namespace {

using namespace cli;

// ---------------------------------------------------------------- world

struct WorldArgs {
  std::string kind, seeds = "0", out = "results/world", config, world_file;
  bool no_png = false, check = false;
};

int RunWorld(const WorldArgs& a) {
  const experiments::Config cfg = LoadOrDefault(a.config);
  EnsureDir(a.out);
  if (!a.world_file.empty()) {
    const core::World w = sim::LoadWorld(a.world_file);  // (validated: a file that loads can be run)
    fmt::print("read {} ({} vertices, {} clutter items)\n", a.world_file, core::MapVertices(w).size(), w.clutter.size());
    if (!a.no_png) {
      const std::string png = (fs::path(a.out) / "world.png").string();
      experiments::DrawWorldPicture(w, cfg.picture, png);
      fmt::print("wrote {}\n", png);
    }
    if (!a.check) return 0;
    const auto problems = experiments::CheckWorld(w, cfg.worlds);
    for (const auto& p : problems) fmt::print("  PROBLEM: {}\n", p);
    return problems.empty() ? 0 : 3;
  }
  if (a.kind.empty()) throw core::ConfigError("<command line>", "--kind", "", "give --kind or --world");
  const core::WorldKind kind = ParseKind(a.kind);
  const std::vector<uint64_t> seeds = experiments::ParseSeeds(a.seeds);
  int failures = 0;
  double total_ms = 0;
  for (uint64_t seed : seeds) {
    const auto t0 = Clock::now();
    const core::World w = sim::GenerateWorld(kind, cfg.worlds, seed);
    const double ms = MsSince(t0);
    total_ms += ms;
    const std::string stem = seeds.size() == 1 ? "world" : fmt::format("{}_s{}", a.kind, seed);
    const std::string json_path = (fs::path(a.out) / (stem + ".json")).string();
    sim::SaveWorld(w, json_path);
    std::string line = fmt::format("{} seed {}: {} vertices, {} obstacles, {} clutter, generated in {:.1f} ms -> {}",
                                   a.kind, seed, core::MapVertices(w).size(), w.obstacles.size(), w.clutter.size(),
                                   ms, json_path);
    if (!a.no_png) {
      const std::string png = (fs::path(a.out) / (stem + ".png")).string();
      experiments::DrawWorldPicture(w, cfg.picture, png);
      line += ", " + png;
    }
    if (a.check) {
      const auto problems = experiments::CheckWorld(w, cfg.worlds);
      for (const auto& p : problems) line += "\n  PROBLEM: " + p;
      failures += problems.empty() ? 0 : 1;
    }
    fmt::print("{}\n", line);
  }
  if (seeds.size() > 1)
    fmt::print("{} worlds, mean generation time {:.1f} ms{}\n", seeds.size(), total_ms / double(seeds.size()),
               a.check ? fmt::format(", {} with problems", failures) : "");
  return failures == 0 ? 0 : 3;
}

// ---------------------------------------------------------------- trial

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
                               const std::map<int, double>& ps) {
  double min_ps = ps.empty() ? std::nan("") : 1.0;
  for (const auto& [id, p] : ps) min_ps = std::min(min_ps, p);
  return fmt::format("{},{:.2f},{:.2f},{:.2f},{},{},{:.3f},{},{},{:.1f}\n", step, at.x, at.y, core::Distance(at, goal),
                     v.frontiers.size(), ps.size(), min_ps, v.vertices.size(), v.walls.size(), v.known_area());
}

// A goal-directed navigation trial with the named planner (trial.png, a frame every --frames-every steps, and
// with --trace a CSV row a step).
int RunNavigationCommand(const TrialArgs& a) {
  const experiments::Config cfg = LoadOrDefault(a.config);
  const auto planner = experiments::ParseGoalPlanner(a.planner);
  if (!planner) throw core::ConfigError("<command line>", "--planner", a.planner, "not a goal-directed planner (optimistic, oracle, lsp)");
  const uint64_t seed = experiments::ParseSeed(a.seed);
  const core::World w = StartAtPose(WorldFromSource(a, cfg), a.pose);
  EnsureDir(a.out);
  experiments::NavigationTrialOptions n;
  n.planner = *planner;
  n.max_steps = a.max_steps.value_or(cfg.bench.max_steps);
  n.mcmc_every = a.mcmc_every.value_or(cfg.bench.mcmc_every);
  int step = 0;
  experiments::MapPictureExtras extras{w.goal, {}, {}};
  n.on_estimates = [&](const std::map<int, double>& ps) { extras.frontier_ps = ps; };
  std::ofstream trace =
      OpenTrace(a.trace, "step,x,y,distance_to_goal,frontiers,estimated_frontiers,min_ps,map_vertices,map_walls,known_area");
  if (trace.is_open()) trace << "\n";
  if (a.frames_every > 0 || trace.is_open())
    n.on_step = [&](const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) {
      if (a.frames_every > 0 && step % a.frames_every == 0)
        experiments::DrawMapPicture(w, v, paths, cfg.picture,
                                    (fs::path(a.out) / fmt::format("frame_{:04d}.png", step)).string(), extras);
      if (trace.is_open())  // labelled like the search trace: moves made (the final map repeats the last)
        trace << NavigationTraceRow(int(paths.front().size()) - 1, paths.front().back(), w.goal, v, extras.frontier_ps);
      ++step;
    };
  mapping::MapView view;
  const auto r = experiments::RunNavigationTrial(w, cfg, n, seed, &view);
  if (trace.is_open()) fmt::print("wrote {} ({} rows)\n", a.trace, step);
  experiments::DrawMapPicture(w, view, {r.path}, cfg.picture, (fs::path(a.out) / "trial.png").string(), {w.goal, r.frontier_ps, {}});
  fmt::print("seed {} planner {}: {} after {} steps, distance {:.1f}, IoU {:.4f}, nudges {}, {:.1f} s -> {}\n", seed,
             r.planner, r.end_reason, r.steps, r.distance, r.iou, r.nudges, r.wall_time_s, (fs::path(a.out) / "trial.png").string());
  return 0;
}

// Open worlds: where the building-placement IoU is lost (each building's IoU, spurious enclosed ground).
void PrintBuildingPlacement(const core::World& w, const mapping::MapView& view) {
  const auto b = experiments::BreakDownBuildingPlacement(w, view);
  std::string per;
  for (double x : b.building_iou) per += fmt::format(" {:.3f}", x);
  fmt::print("buildings' IoU with the holes that overlap them:{}; holes overlapping no building: {:.1f} units^2\n", per,
             b.spurious_area);
}

int RunTrialCommand(const TrialArgs& a) {
  if (!a.planner.empty()) return RunNavigationCommand(a);
  const experiments::Config cfg = LoadOrDefault(a.config);
  const uint64_t seed = experiments::ParseSeed(a.seed);
  const core::World w = StartAtPose(WorldFromSource(a, cfg), a.pose);
  EnsureDir(a.out);
  mapping::MapView view;
  experiments::TrialOptions t = a.trial;
  t.max_steps = a.max_steps.value_or(cfg.bench.max_steps);
  t.mcmc_every = a.mcmc_every.value_or(cfg.bench.mcmc_every);
  t.open_world_mcmc_every = a.open_world_mcmc_every.value_or(cfg.open_world.mcmc_every);
  std::unique_ptr<experiments::TrialVideo> video;
  if (!a.video.empty()) video = std::make_unique<experiments::TrialVideo>(w, cfg.picture, a.video);
  // Trace: one CSV row a step (the map the planners used; the last row is the final map the metrics score).
  std::ofstream trace = OpenTrace(a.trace, "step,iou,frontiers,targets,map_vertices,map_walls");
  if (trace.is_open()) {
    for (int i = 0; i < t.num_agents; ++i) trace << fmt::format(",x{0},y{0},frontier{0},goal_x{0},goal_y{0}", i);
    trace << "\n";
  }
  // What the planners chose this step (targets on offer; each agent's frontier and the end of its path),
  // written with the step's row; the final row has none.
  std::string plan_targets;
  std::vector<std::string> plan_goals;
  if (trace.is_open())
    t.on_plan = [&](const experiments::LoopState&, const std::vector<planning::FrontierTarget>& targets,
                    const std::vector<planning::FrontierChoice>& choices) {
      plan_targets = std::to_string(targets.size());
      plan_goals.clear();
      for (const auto& c : choices)
        plan_goals.push_back(c.status == planning::PlanStatus::kFound && !c.path.points.empty()
                                 ? fmt::format("{},{:.2f},{:.2f}", c.frontier_id, c.path.points.back().x, c.path.points.back().y)
                                 : std::string(",,"));
    };
  if (video || trace.is_open())
    t.on_step = [&](const mapping::MapView& v, const std::vector<std::vector<core::Vec2>>& paths) {
      if (video) video->AddFrame(v, paths);
      if (!trace.is_open()) return;
      const double iou = w.has_boundary() ? experiments::KnownSpaceIoU(w, v) : experiments::BuildingPlacementIoU(w, v);
      trace << fmt::format("{},{:.5f},{},{},{},{}", paths.front().size() - 1, iou, v.frontiers.size(), plan_targets,
                           v.vertices.size(), v.walls.size());
      for (size_t i = 0; i < paths.size(); ++i)
        trace << fmt::format(",{:.2f},{:.2f},{}", paths[i].back().x, paths[i].back().y, i < plan_goals.size() ? plan_goals[i] : ",,");
      trace << "\n";
      plan_targets.clear();
      plan_goals.clear();
    };
  const auto r = experiments::RunSearchTrial(w, cfg, t, seed, &view);
  if (video) fmt::print("wrote {} ({} frames)\n", a.video, video->frames());
  if (trace.is_open()) fmt::print("wrote {} ({} steps)\n", a.trace, r.steps);
  experiments::MapPictureExtras extras;
  extras.blocks = r.blocks;
  experiments::DrawMapPicture(w, view, r.paths, cfg.picture, (fs::path(a.out) / "trial.png").string(), extras);
  double total = 0;
  for (double d : r.distance) total += d;
  fmt::print("seed {} agents {}: {} after {} steps, IoU {:.4f}, success {}, distance {:.1f}, nudges {}, "
             "frontiers given up {}, motion blocks {}, vertex inspections {}, {:.1f} s -> {}\n",
             seed, r.num_agents, r.end_reason, r.steps, r.iou, r.success ? "yes" : "no", total, r.nudges,
             r.give_ups, r.blocks.size(), r.inspections, r.wall_time_s, (fs::path(a.out) / "trial.png").string());
  if (!w.has_boundary()) PrintBuildingPlacement(w, view);
  return 0;
}

// ---------------------------------------------------------------- bench and report

int RunReport(const std::vector<std::string>& dirs, std::string out) {
  experiments::CheckOneBatch(dirs);
  std::vector<std::string> skipped;
  const auto records = experiments::ReadResults(dirs, &skipped);
  for (const auto& s : skipped) std::cerr << "warning: " << s << "\n";
  if (records.empty()) throw core::DataError(dirs.front(), "no trial results (*.jsonl) found");
  if (out.empty()) out = dirs.front();
  EnsureDir(out);
  std::string md;
  std::vector<std::string> wrote{"report.md"};
  if (const auto rows = experiments::Summarize(records); !rows.empty()) {
    md += experiments::MarkdownTable(rows);
    WriteTextFile((fs::path(out) / "report.csv").string(), experiments::CsvTable(rows));
    experiments::WriteStepsPlot(records, (fs::path(out) / "steps.png").string());
    wrote.insert(wrote.end(), {"report.csv", "steps.png"});
  }
  if (const auto rows = experiments::SummarizeNavigation(records); !rows.empty()) {
    md += (md.empty() ? "" : "\n") + experiments::NavigationMarkdown(rows, records);
    WriteTextFile((fs::path(out) / "navigation.csv").string(), experiments::NavigationCsv(rows));
    experiments::WriteCostScatter(records, (fs::path(out) / "costs.png").string());
    wrote.insert(wrote.end(), {"navigation.csv", "costs.png"});
  }
  WriteTextFile((fs::path(out) / "report.md").string(), md);
  fmt::print("{}\n{} trials from {} director{}; wrote {}/{}\n", md, records.size(), dirs.size(),
             dirs.size() == 1 ? "y" : "ies", out, fmt::join(wrote, ", "));
  return 0;
}

struct BenchArgs {
  std::string config = "configs/search/quick.yaml", out, shard, seeds;
  experiments::BatchOptions batch;
  bool quiet = false;
};

int RunBench(BenchArgs a) {
  experiments::Config cfg = experiments::LoadConfig(a.config);
  if (cfg.bench.rows.empty()) throw core::ConfigError(a.config, "bench.rows", "[]", "list at least one row");
  const std::vector<uint64_t> seed_override = a.seeds.empty() ? std::vector<uint64_t>{} : experiments::ParseSeeds(a.seeds);
  // (pictures: failures also draws each row's first seed)
  if (!seed_override.empty()) cfg.bench.first_seed = *std::min_element(seed_override.begin(), seed_override.end());
  a.batch.out_dir = a.out.empty() ? "results/" + cfg.bench.name : a.out;
  a.batch.progress = !a.quiet;
  if (!a.shard.empty()) experiments::ParseShard(a.shard, &a.batch.shard_index, &a.batch.shard_count);
  const auto trials = experiments::ListTrials(cfg.bench, seed_override);
  a.batch.stamp = experiments::BatchStamp(a.config, trials);
  fmt::print("toponav bench {}: {} trials ({} rows), results in {}\n", cfg.bench.name, trials.size(), cfg.bench.rows.size(),
             a.batch.out_dir);
  const auto s = experiments::RunBatch(cfg, a.batch, trials);
  fmt::print("{} of {} trials were already done; ran {} ({} failed) in {:.1f} s\n", s.already_done, s.total, s.ran,
             s.failed, s.wall_s);
  return RunReport({a.batch.out_dir}, a.batch.out_dir);
}

// ---------------------------------------------------------------- demo

int RunDemo(const std::string& config_path, const std::string& out_override) {
  const experiments::Config cfg = LoadOrDefault(config_path);
  const std::string out = out_override.empty() ? cfg.demo.out_dir : out_override;
  fmt::print("toponav demo: one world of each kind, seed {} (config {})\n", cfg.demo.seed, cfg.source);
  for (const core::WorldKind kind : cfg.demo.kinds) {
    const std::string dir = (fs::path(out) / core::ToString(kind)).string();
    EnsureDir(dir);
    const auto t0 = Clock::now();
    const core::World w = sim::GenerateWorld(kind, cfg.worlds, cfg.demo.seed);
    const double gen_ms = MsSince(t0);
    sim::SaveWorld(w, dir + "/world.json");
    experiments::DrawWorldPicture(w, cfg.picture, dir + "/world.png");
    const sim::RayCaster caster(w);
    const auto visible = caster.VisibleVertices(w.start);
    const auto poly = caster.VisibilityPolygon(w.start.position());
    experiments::DrawObservationPicture(w, w.start, visible, poly, cfg.picture, dir + "/observation.png");
    const sim::Renderer renderer(w, cfg.render);
    experiments::WritePanoramaPng(renderer.Render(w.start), dir + "/panorama.png");
    const auto problems = experiments::CheckWorld(w, cfg.worlds);
    fmt::print("  {:<12} {:>4} vertices {:>3} clutter  generated in {:6.1f} ms  {} visible from start  {}\n",
               core::ToString(kind), core::MapVertices(w).size(), w.clutter.size(), gen_ms, visible.size(),
               problems.empty() ? "ok" : "PROBLEMS: " + problems.front());
    fmt::print("  {:<12} {}/world.json  {}/world.png  {}/observation.png  {}/panorama.png\n", "", dir, dir, dir, dir);
  }
  return 0;
}

// ---------------------------------------------------------------- info

int RunInfo(bool prefer_cuda) {
  fmt::print("toponav {}\n", "0.1.0");
  fmt::print("  ray casting : {}\n", sim::RayCasterLibraryInfo());
  fmt::print("  motion      : {}\n", sim::MotionLibraryInfo());
  fmt::print("  polygons    : {}\n", mapping::PolygonLibraryInfo());
  fmt::print("  off-screen GL: {}\n", sim::OffscreenGlInfo());
  const auto b = learning::SelectBackend(prefer_cuda);
  fmt::print("  LibTorch    : {} on {} ({} threads, CUDA {})\n", b.torch_version, b.device, b.num_threads,
             b.cuda_available ? "available" : "not available");
  fmt::print("  torch check : 3x3 conv of a 4x5 image sums to {}\n", learning::ConvolutionCheck(4, 5));
  return 0;
}

CLI::App* AddWorldCommand(CLI::App& app, WorldArgs* a) {
  CLI::App* world = app.add_subcommand("world", "Generate procedural worlds: writes world.json and a top-down world.png");
  world->add_option("--kind", a->kind, "World kind: labyrinth, office_park or guided_maze");
  world->add_option("--seed,--seeds", a->seeds, "Seed N, or an inclusive range A-B (files then named KIND_sSEED)")
      ->capture_default_str();
  world->add_option("--out", a->out, "Output directory")->capture_default_str();
  world->add_option("--config", a->config, "YAML config with generator options (e.g. configs/demo.yaml)");
  world->add_option("--world", a->world_file, "Instead of generating, read this world.json and draw it");
  world->add_flag("--no-png", a->no_png, "Skip the pictures (faster for many seeds)");
  world->add_flag("--check", a->check, "Check every world (one connected free space, building gaps, guide path); exit 3 on problems");
  return world;
}

CLI::App* AddTrialCommand(CLI::App& app, TrialArgs* a) {
  CLI::App* trial = app.add_subcommand("trial", "Run one search trial (1 agent, or a team over distinct frontiers), or with "
                                                 "--planner one goal-directed navigation trial");
  AddWorldSourceOptions(trial, a, "YAML config (sensor:, mapping:, motion:)");
  trial->add_option("--agents", a->trial.num_agents, "Number of agents")->capture_default_str()->check(CLI::Range(1, 16));
  trial->add_option("--max-steps", a->max_steps, "Step cap (default: the config's bench.max_steps)")->check(CLI::Range(1, 100000));
  trial->add_option("--mcmc-every", a->mcmc_every, "MCMC every this many steps, 0: never (default: the config's bench.mcmc_every)")
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
  trial->add_option("--planner", a->planner, "Run goal-directed navigation (start to goal, one agent) with this planner instead: optimistic, oracle, lsp");
  trial->add_option("--frames-every", a->frames_every, "Navigation: also draw the map every this many steps (frame_NNNN.png)")
      ->check(CLI::Range(1, 100000));
  return trial;
}

CLI::App* AddBenchCommand(CLI::App& app, BenchArgs* a) {
  CLI::App* bench = app.add_subcommand("bench", "Run a search benchmark (paper Table I): trials in parallel processes, "
                                             "JSON lines, resumable, shardable; prints the table");
  bench->add_option("--config", a->config, "Benchmark config (bench: rows, seeds, max_steps, ...)")->capture_default_str();
  bench->add_option("--out", a->out, "Results directory (default results/<bench.name>)");
  bench->add_option("--workers", a->batch.workers, "Parallel trial processes (default: all cores)")->check(CLI::Range(0, 256));
  bench->add_option("--shard", a->shard, "Run only shard i of N (i/N, 0-based), e.g. 0/4 for a cluster job array");
  bench->add_option("--seeds", a->seeds, "Override the config's seeds: N or A-B");
  bench->add_option("--max-trials", a->batch.max_new_trials, "Stop after this many new trials (resume later)")->check(CLI::Range(0, 100000000));
  bench->add_flag("--quiet", a->quiet, "No progress lines");
  bench->add_flag("--fresh", a->batch.fresh, "Discard the results directory's trials first (they came from another build or config)");
  bench->add_option("--fail-trial", a->batch.fail_key, "Testing: make this trial (e.g. labyrinth/a1/s10000) throw")->group("");
  bench->add_option("--crash-trial", a->batch.crash_key, "Testing: make this trial's process crash")->group("");
  return bench;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"toponav: topological planning with monocular vision - simulator and experiment harness"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  WorldArgs wa;
  TrialArgs ta;
  BenchArgs ba;
  CLI::App* world = AddWorldCommand(app, &wa);
  cli::SensingCommands sensing_commands(app);
  CLI::App* trial = AddTrialCommand(app, &ta);
  CLI::App* bench = AddBenchCommand(app, &ba);
  cli::LearningCommands learning_commands(app);
  std::vector<std::string> report_dirs;
  std::string report_out;
  auto* report = app.add_subcommand("report", "Merge results directories (shards) into the Table I layout: Markdown, CSV, plot");
  report->add_option("dirs", report_dirs, "Results directories")->required();
  report->add_option("--out", report_out, "Where to write report.md, report.csv, steps.png (default: the first directory)");

  std::string demo_config = "configs/demo.yaml", demo_out;
  auto* demo = app.add_subcommand("demo", "The default job: one world of each kind: its JSON, top-down picture, observation and panorama under results/");
  demo->add_option("--config", demo_config, "Job config")->capture_default_str();
  demo->add_option("--out", demo_out, "Output directory (default: demo.out_dir of the config)");

  bool prefer_cuda = false;
  auto* info = app.add_subcommand("info", "Print the versions of the libraries and check that each one works");
  info->add_flag("--cuda", prefer_cuda, "Ask for the CUDA backend (falls back to the CPU with a warning)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints help, or the error and a hint
    return rc == 0 ? 0 : 2;
  }
  try {
    if (*world) return RunWorld(wa);
    if (const auto rc = sensing_commands.Run()) return *rc;
    if (*trial) return RunTrialCommand(ta);
    if (*bench) return RunBench(ba);
    if (const auto rc = learning_commands.Run()) return *rc;
    if (*report) return RunReport(report_dirs, report_out);
    if (*demo) return RunDemo(demo_config, demo_out);
    if (*info) return RunInfo(prefer_cuda);
  } catch (const core::ConfigError& e) {
    std::cerr << "config error: " << e.what() << "\n";
    return 2;
  } catch (const core::DataError& e) {
    std::cerr << "data error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

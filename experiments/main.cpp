// toponav: the command-line front end.  Subcommands: world, bench, report, demo, info here; observe, render, map
// in experiments/cli/sensing_commands.cpp; trial in experiments/cli/trial_command.cpp; datagen, train and
// eval-sensor in experiments/cli/learning_commands.cpp.
#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/error.h"
#include "experiments/batch.h"
#include "experiments/cli/common.h"
#include "experiments/cli/learning_commands.h"
#include "experiments/cli/sensing_commands.h"
#include "experiments/cli/trial_command.h"
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
    fmt::print("read {} ({} vertices, {} clutter items)\n", a.world_file, core::MapVertices(w).size(),
               w.clutter.size());
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
  const std::vector<uint64_t> seed_override =
      a.seeds.empty() ? std::vector<uint64_t>{} : experiments::ParseSeeds(a.seeds);
  // (pictures: failures also draws each row's first seed)
  if (!seed_override.empty()) cfg.bench.first_seed = *std::min_element(seed_override.begin(), seed_override.end());
  a.batch.out_dir = a.out.empty() ? "results/" + cfg.bench.name : a.out;
  a.batch.progress = !a.quiet;
  if (!a.shard.empty()) experiments::ParseShard(a.shard, &a.batch.shard_index, &a.batch.shard_count);
  const auto trials = experiments::ListTrials(cfg.bench, seed_override);
  a.batch.stamp = experiments::BatchStamp(a.config, trials);
  fmt::print("toponav bench {}: {} trials ({} rows), results in {}\n", cfg.bench.name, trials.size(),
             cfg.bench.rows.size(), a.batch.out_dir);
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
  CLI::App* world =
      app.add_subcommand("world", "Generate procedural worlds: writes world.json and a top-down world.png");
  world->add_option("--kind", a->kind, "World kind: labyrinth, office_park or guided_maze");
  world->add_option("--seed,--seeds", a->seeds, "Seed N, or an inclusive range A-B (files then named KIND_sSEED)")
      ->capture_default_str();
  world->add_option("--out", a->out, "Output directory")->capture_default_str();
  world->add_option("--config", a->config, "YAML config with generator options (e.g. configs/demo.yaml)");
  world->add_option("--world", a->world_file, "Instead of generating, read this world.json and draw it");
  world->add_flag("--no-png", a->no_png, "Skip the pictures (faster for many seeds)");
  world->add_flag("--check", a->check,
                  "Check every world (one connected free space, building gaps, guide path); exit 3 on problems");
  return world;
}

CLI::App* AddBenchCommand(CLI::App& app, BenchArgs* a) {
  CLI::App* bench = app.add_subcommand("bench", "Run a search benchmark (paper Table I): trials in parallel processes, "
                                             "JSON lines, resumable, shardable; prints the table");
  bench->add_option("--config", a->config, "Benchmark config (bench: rows, seeds, max_steps, ...)")
      ->capture_default_str();
  bench->add_option("--out", a->out, "Results directory (default results/<bench.name>)");
  bench->add_option("--workers", a->batch.workers, "Parallel trial processes (default: all cores)")
      ->check(CLI::Range(0, 256));
  bench->add_option("--shard", a->shard, "Run only shard i of N (i/N, 0-based), e.g. 0/4 for a cluster job array");
  bench->add_option("--seeds", a->seeds, "Override the config's seeds: N or A-B");
  bench->add_option("--max-trials", a->batch.max_new_trials, "Stop after this many new trials (resume later)")
      ->check(CLI::Range(0, 100000000));
  bench->add_flag("--quiet", a->quiet, "No progress lines");
  bench->add_flag("--fresh", a->batch.fresh,
                  "Discard the results directory's trials first (they came from another build or config)");
  bench->add_option("--fail-trial", a->batch.fail_key, "Testing: make this trial (e.g. labyrinth/a1/s10000) throw")
      ->group("");
  bench->add_option("--crash-trial", a->batch.crash_key, "Testing: make this trial's process crash")->group("");
  return bench;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"toponav: topological planning with monocular vision - simulator and experiment harness"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  WorldArgs wa;
  BenchArgs ba;
  CLI::App* world = AddWorldCommand(app, &wa);
  cli::SensingCommands sensing_commands(app);
  cli::TrialCommand trial_command(app);
  CLI::App* bench = AddBenchCommand(app, &ba);
  cli::LearningCommands learning_commands(app);
  std::vector<std::string> report_dirs;
  std::string report_out;
  auto* report =
      app.add_subcommand("report", "Merge results directories (shards) into the Table I layout: Markdown, CSV, plot");
  report->add_option("dirs", report_dirs, "Results directories")->required();
  report->add_option("--out", report_out,
                     "Where to write report.md, report.csv, steps.png (default: the first directory)");

  std::string demo_config = "configs/demo.yaml", demo_out;
  auto* demo = app.add_subcommand(
      "demo",
      "The default job: one world of each kind: its JSON, top-down picture, observation and panorama under results/");
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
    if (const auto rc = trial_command.Run()) return *rc;
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

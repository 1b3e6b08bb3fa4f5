#include "experiments/cli/learning_commands.h"

#include <fmt/core.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "experiments/cli/common.h"
#include "experiments/cli_parse.h"
#include "experiments/datagen.h"
#include "experiments/sensor_eval.h"
#include "experiments/subgoal_calibration.h"
#include "experiments/subgoal_data.h"
#include "experiments/subgoal_eval.h"
#include "experiments/subgoal_export.h"
#include "learning/trainer.h"

// jemalloc's control interface when the binary links it (experiments/internal/jemalloc_conf.c), else null.
extern "C" int mallctl(const char* name, void* oldp, size_t* oldlenp, void* newp, size_t newlen) __attribute__((weak));

namespace toponav::cli {

namespace {

// Hands the allocator's freed pages back to the system.  jemalloc runs without page decay (LibTorch's large
// activations are reused instead of refaulted), but training over a large in-memory set grew by ~15 MB a step
// (freed pages not reused; out of memory after ~1000 steps of configs/learning/lsp_cpu.yaml): purging every
// 50 steps keeps it flat (every 10 cost 20 % of the speed in refaulted pages).
void PurgeFreedPages() {
  if (mallctl) mallctl("arena.4096.purge", nullptr, nullptr, nullptr, 0);  // 4096: MALLCTL_ARENAS_ALL
}

// ---------------------------------------------------------------- datagen

struct DatagenArgs {
  std::string config = "configs/learning/ci.yaml", out = "results/dataset";
  int max_samples = 0;
  bool subgoal = false;
};

int RunSubgoalDatagen(const DatagenArgs& a, const experiments::Config& cfg) {
  const auto& d = cfg.subgoal_data;
  fmt::print(
      "toponav datagen --subgoal: {} through {} training and {} validation worlds ({}), a sample every {} "
      "steps{} -> {}\n",
      experiments::SubgoalRunsText(d), d.train_num_seeds, d.val_num_seeds, core::ToString(d.kind), d.every,
      a.max_samples > 0 ? fmt::format(", at most {} per split", a.max_samples) : "", a.out);
  const auto s = experiments::ExportSubgoalDataset(cfg, a.out, a.max_samples);
  fmt::print(
      "wrote {} samples in {:.1f} s ({:.1f} samples/s): {}/subgoal_dataset.json, index.csv, train/, val/, "
      "contact_sheet.png\n",
      s.samples, s.seconds, s.samples_per_second(), a.out);
  return 0;
}

int RunDatagen(const DatagenArgs& a) {
  const experiments::Config cfg = experiments::LoadConfig(a.config);
  if (a.subgoal) return RunSubgoalDatagen(a, cfg);
  const core::RangeBearingGrid grid;
  fmt::print("toponav datagen: {} training and {} validation samples ({} per world){} -> {}\n",
             experiments::ListSamples(cfg.datagen, experiments::Split::kTrain).size(),
             experiments::ListSamples(cfg.datagen, experiments::Split::kVal).size(), cfg.datagen.samples_per_world,
             a.max_samples > 0 ? fmt::format(", at most {} per split", a.max_samples) : "", a.out);
  const auto s = experiments::ExportDataset(cfg.datagen, cfg.worlds, cfg.render, grid, a.out, a.max_samples);
  fmt::print(
      "wrote {} samples in {:.1f} s ({:.1f} samples/s): {}/dataset.json, index.csv, train/, val/, contact_sheet.png\n",
      s.samples, s.seconds, s.samples_per_second(), a.out);
  return 0;
}

CLI::App* AddDatagenCommand(CLI::App& app, DatagenArgs* a) {
  CLI::App* cmd = app.add_subcommand("datagen",
                                     "Export training data for the learned vertex sensor: panoramas and their "
                                     "vertex labels on the range-bearing grid (README: Training data)");
  cmd->add_option("--config", a->config, "Config with a datagen: section")->capture_default_str();
  cmd->add_option("--out", a->out, "Output directory")->capture_default_str();
  cmd->add_option("--max-samples", a->max_samples, "At most this many samples per split (0: all)")
      ->check(CLI::Range(0, 100000000));
  cmd->add_flag("--subgoal", a->subgoal,
                "Export the LSP network's data instead: the config's subgoal_data mazes, "
                "panoramas with vertex and frontier labels");
  return cmd;
}

// ---------------------------------------------------------------- train

struct TrainArgs {
  std::string config = "configs/learning/ci.yaml", out = "results/train";
  bool fresh = false, quiet = false;
};

std::string Duration(double s) { return fmt::format("{}m{:02d}s", int(s) / 60, int(s) % 60); }

// The subgoal network's examples: runs through the subgoal_data worlds, rendered.
learning::TrainingSet SubgoalTrainingSet(const experiments::Config& cfg) {
  learning::TrainingSet set;
  for (const sim::Split split : {sim::Split::kTrain, sim::Split::kVal}) {
    auto& into = split == sim::Split::kTrain ? set.train : set.val;
    const auto progress = [&](int done, int total, size_t n) {
      std::cerr << fmt::format("[data] {} worlds {}/{}: {} examples\n", sim::ToString(split), done, total, n);
    };
    for (auto& e : experiments::MakeSubgoalExamples(cfg, split, progress)) {
      const learning::GoalInView goal = learning::GoalInView::FromAgentFrame(e.goal);
      into.push_back({std::move(e.image), std::move(e.labels), goal, std::move(e.subgoal)});
    }
  }
  const auto& d = cfg.subgoal_data;
  set.identity_json = nlohmann::json{
      {"kinds", {core::ToString(d.kind)}},
      {"train_seeds", {d.train_first_seed, d.train_first_seed + d.train_num_seeds - 1}},
      {"val_seeds", {d.val_first_seed, d.val_first_seed + d.val_num_seeds - 1}},
      {"every", d.every}}.dump();
  return set;
}

int RunTrain(const TrainArgs& a) {
  const experiments::Config cfg = experiments::LoadConfig(a.config);
  const auto& t = cfg.train;
  const auto& sd = cfg.subgoal_data;
  const std::string data =
      t.subgoal ? fmt::format("subgoal examples every {} steps of {} through {} training and {} validation worlds ({})",
                              sd.every, experiments::SubgoalRunsText(sd), sd.train_num_seeds, sd.val_num_seeds,
                              core::ToString(sd.kind))
                : fmt::format("{} training and {} validation worlds of {} kinds, {} samples each",
                              cfg.datagen.train_num_seeds, cfg.datagen.val_num_seeds, cfg.datagen.kinds.size(),
                              cfg.datagen.samples_per_world);
  fmt::print("toponav train: width {}, batch {}, {} steps (lr {}), validation every {}{}{}; data: {} -> {}\n",
             t.width, t.batch_size, t.steps, t.learning_rate, t.validate_every,
             t.init_from.empty() ? "" : ", starting from " + t.init_from,
             t.mirror ? ", each example mirrored at random" : "", data, a.out);
  std::fflush(stdout);
  auto report = [&](const learning::TrainProgress& p) {
    if (p.step % 50 == 0) PurgeFreedPages();
    if (a.quiet && p.val_loss < 0) return;
    std::cerr << fmt::format(
        "[train] step {}/{} loss {:.3f}{} elapsed {} ETA {}\n", p.step, p.steps, p.train_loss,
        p.val_loss >= 0 ? fmt::format(" val {:.3f} (best {:.3f})", p.val_loss, p.best_val_loss) : "",
        Duration(p.seconds), Duration(p.eta_seconds));
  };
  const learning::TrainingSet set =
      t.subgoal ? SubgoalTrainingSet(cfg) : learning::RenderVertexExamples(cfg.datagen, cfg.worlds, cfg.render);
  const auto r = learning::Train(set, t, a.out, a.fresh, report);
  fmt::print(
      "{}{} training / {} validation samples; best validation loss {:.4f} at step {}; {:.1f} s ({:.2f} steps/s) "
      "-> {}\n",
      r.resumed_from > 0 ? fmt::format("resumed at step {}; ", r.resumed_from) : "", r.train_samples, r.val_samples,
      r.best_val_loss, r.best_step, r.seconds, (r.steps - r.resumed_from) / std::max(r.seconds, 1e-9), r.model_path);
  return 0;
}

CLI::App* AddTrainCommand(CLI::App& app, TrainArgs* a) {
  CLI::App* cmd = app.add_subcommand("train",
                                     "Train the learned vertex sensor on samples rendered from the config's "
                                     "datagen worlds (train.subgoal: the LSP network on subgoal_data mazes); "
                                     "resumable; writes model.pt (the best on validation)");
  cmd->add_option("--config", a->config, "Config with datagen: and train: sections")->capture_default_str();
  cmd->add_option("--out", a->out, "Output directory: model.pt, checkpoint.pt, train_state.json, train_log.csv")
      ->capture_default_str();
  cmd->add_flag("--fresh", a->fresh, "Start over instead of resuming the directory's run");
  cmd->add_flag("--quiet", a->quiet, "Report validations only");
  return cmd;
}

// ---------------------------------------------------------------- eval-sensor

struct EvalSensorArgs {
  std::string config, model, kind, seeds = "10000-10019", out, calibrate;
  int samples = 10;
  bool subgoal = false;
  int every = 6;
};

// --subgoal: the network's frontier estimates against the truth along runs made as its training data is
// (optimistic runs through guided mazes, searches elsewhere; the world kind is --kind or the config's
// subgoal_data.kind; the config's sensor drives the runs; the model is --model or the config's learned sensor's).
int RunEvalSubgoal(const EvalSensorArgs& a) {
  const experiments::Config cfg = LoadOrDefault(a.config);
  experiments::LearnedSensorOptions model = cfg.sensor.learned;
  if (!a.model.empty()) model.model = a.model;
  if (model.model.empty())
    throw core::ConfigError(a.config.empty() ? "<defaults>" : a.config, "sensor.model", "",
                            "--subgoal needs a subgoal model: --model, or a config whose sensor is learned");
  experiments::SubgoalEvalOptions o;
  o.kind = a.kind.empty() ? cfg.subgoal_data.kind : ParseKind(a.kind);
  o.seeds = experiments::ParseSeeds(a.seeds);
  o.every = a.every;
  const auto e = experiments::EvaluateSubgoalEstimates(
      cfg, model, o, [](int done, int total) { std::cerr << fmt::format("[eval] {}/{} worlds\n", done, total); });
  fmt::print(
      "{} {} worlds (seeds {}), {} samples, {} frontier cells ({:.1f} % with Ps = 1), model {}:\n"
      "  Ps: AUC {:.3f}, cross-entropy {:.3f}, mean {:.3f} on Ps = 1 cells and {:.3f} on Ps = 0 cells\n"
      "  success cost: mean |error| {:.1f} (Ps = 1 cells); exploration cost: mean |error| {:.1f} (Ps = 0 cells) "
      "({:.1f} s)\n"
      "  Ps AUC by range: {:.3f} nearer than {} ({} cells), {:.3f} up to {} ({}), {:.3f} farther ({})\n"
      "  exploration cost on Ps = 0 cells: mean {:.1f} true, {:.1f} estimated; frontier order by it: {:.3f} of {} "
      "pairs (true costs {}x or more apart) right\n",
      core::ToString(o.kind), e.worlds, a.seeds, e.examples, e.cells, 100.0 * e.positive_rate(), model.model, e.auc,
      e.cross_entropy, e.mean_ps_positive, e.mean_ps_negative, e.success_mae, e.exploration_mae, e.seconds,
      e.band_auc[0], experiments::SubgoalEval::kBandEdges[0], e.band_cells[0], e.band_auc[1],
      experiments::SubgoalEval::kBandEdges[1], e.band_cells[1], e.band_auc[2], e.band_cells[2], e.exploration_truth,
      e.exploration_estimate, e.exploration_order, e.frontier_pairs, experiments::SubgoalEval::kOrderRatio);
  return 0;
}

// --subgoal --calibrate FILE: LSP runs through the --seeds mazes with the network's outputs as they are, and the
// map of Ps to the true share of its bin (experiments/subgoal_calibration.h), written to FILE.
int RunCalibrateSubgoal(const EvalSensorArgs& a) {
  const experiments::Config cfg = LoadWithModel(a.config, a.model);
  if (cfg.sensor.kind != experiments::SensorKind::kLearned || cfg.sensor.learned.model.empty())
    throw core::ConfigError(a.config.empty() ? "<defaults>" : a.config, "sensor.model", "",
                            "--calibrate needs a subgoal model: --model, or a config whose sensor is learned");
  const std::vector<uint64_t> seeds = experiments::ParseSeeds(a.seeds);
  for (uint64_t s : seeds)
    if (s >= 10000)
      throw core::ConfigError("<command line>", "--seeds", a.seeds,
                              "calibrate on tuning mazes (seeds below 10000): benchmark seeds measure, never tune");
  const auto samples = experiments::MeasurePieceEstimates(
      cfg, seeds, [](int done, int total) { std::cerr << fmt::format("[calibrate] {}/{} mazes\n", done, total); });
  if (samples.empty())
    throw core::DataError(cfg.sensor.learned.model, "no frontier piece got an estimate: not a subgoal model?");
  const experiments::CalibrationFit fit = experiments::FitSubgoalCalibration(samples);
  const std::string measured = fmt::format(
      "guided mazes {} ({} frontier piece estimates, {} of them with Ps 1), model {}", a.seeds, fit.samples,
      fit.successes, cfg.sensor.learned.model);
  fmt::print("{}:\n  Ps cross-entropy {:.3f} -> {:.3f}\n", measured, fit.cross_entropy[0], fit.cross_entropy[1]);
  const std::string yaml = experiments::SubgoalCalibrationYaml(
      fit.calibration, {"What the subgoal network's Ps means: [estimate, share of pieces with Ps 1] (lsp.calibration).",
                        "Measured by toponav eval-sensor --subgoal --calibrate on " + measured + "."});
  fmt::print("{}", yaml);
  WriteTextFile(a.calibrate, yaml);
  return 0;
}

int RunEvalSensor(const EvalSensorArgs& a) {
  if (a.subgoal && !a.calibrate.empty()) return RunCalibrateSubgoal(a);
  if (a.subgoal) return RunEvalSubgoal(a);
  const experiments::Config cfg = LoadWithModel(a.config, a.model);
  experiments::SensorEvalOptions o;
  o.kind = ParseKind(a.kind.empty() ? "labyrinth" : a.kind);
  o.seeds = experiments::ParseSeeds(a.seeds);
  o.samples_per_world = a.samples;
  const auto e = experiments::EvaluateSensor(cfg, o);
  const std::string on =
      fmt::format("{} seeds {}, {} poses a world ({} sensor{})", core::ToString(o.kind), a.seeds, a.samples,
                  experiments::ToString(cfg.sensor.kind), a.model.empty() ? "" : " " + a.model);
  fmt::print(
      "{} observations, {} true vertices, {} detections: precision {:.3f}, recall {:.3f}, F1 {:.3f}, label accuracy "
      "{:.3f}, mean range error {:.2f}, mean bearing error {:.4f} rad ({:.1f} s)\n",
      e.observations, e.true_vertices, e.detections, e.precision(), e.recall(), e.f1(), e.label_accuracy(),
      e.mean_range_error(), e.mean_bearing_error(), e.seconds);
  const auto& edges = experiments::SensorEval::kRangeEdges;
  fmt::print(
      "  recall by range: {:.3f} nearer than {} ({} vertices), {:.3f} to {} ({}), {:.3f} to {} ({}), "
      "{:.3f} farther ({})\n",
      e.recall_in_band(0), edges[0], e.true_by_range[0], e.recall_in_band(1), edges[1], e.true_by_range[1],
      e.recall_in_band(2), edges[2], e.true_by_range[2], e.recall_in_band(3), e.true_by_range[3]);
  const auto& sight = experiments::SensorEval::kSightEdges;
  fmt::print(
      "  recall by sight-line angle to the vertex's walls: {:.3f} under {:.0f} deg ({} vertices), {:.3f} to {:.0f} "
      "({}), {:.3f} to {:.0f} ({}), {:.3f} beyond ({})\n",
      e.recall_at_sight(0), sight[0] * 180 / core::kPi, e.true_by_sight[0], e.recall_at_sight(1),
      sight[1] * 180 / core::kPi, e.true_by_sight[1], e.recall_at_sight(2), sight[2] * 180 / core::kPi,
      e.true_by_sight[2], e.recall_at_sight(3), e.true_by_sight[3]);
  fmt::print(
      "  recall by true label: right gap {:.3f} ({}), corner {:.3f} ({}), left gap {:.3f} ({}), "
      "point {:.3f} ({})\n",
      e.recall_of_label(0), e.true_by_label[0], e.recall_of_label(1), e.true_by_label[1], e.recall_of_label(2),
      e.true_by_label[2], e.recall_of_label(3), e.true_by_label[3]);
  fmt::print("  bias by true label (detected - true; bearing toward the gap for gaps, else counter-clockwise): ");
  for (size_t l = 0; l < 4; ++l)
    fmt::print("{}{} range {:+.2f} bearing {:+.4f}", l ? ", " : "", core::ToString(core::VertexLabel(l)),
               e.range_bias_of_label(l), e.bearing_bias_of_label(l));
  fmt::print("\n");
  const std::string yaml = experiments::NoisySensorYaml(e, on);
  fmt::print("{}", yaml);
  if (!a.out.empty()) WriteTextFile(a.out, yaml);
  return 0;
}

CLI::App* AddEvalSensorCommand(CLI::App& app, EvalSensorArgs* a) {
  CLI::App* cmd = app.add_subcommand("eval-sensor",
                                     "Score a sensor against the ray-cast ground truth: precision, recall, F1, "
                                     "label accuracy, range/bearing error, and a calibrated noisy-sensor block");
  cmd->add_option("--config", a->config, "Config whose sensor: to evaluate (default: the noisy sensor)");
  cmd->add_option("--model", a->model, "Evaluate the learned sensor with this model file instead");
  cmd->add_option("--kind", a->kind, "World kind (default labyrinth; with --subgoal, the config's subgoal_data.kind)");
  cmd->add_option("--seeds", a->seeds, "World seeds A-B (held-out quality: seeds from 10000, never trained on)")
      ->capture_default_str();
  cmd->add_option("--samples-per-world", a->samples, "Poses per world")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--out", a->out, "Also write the sensor: block to this YAML file");
  cmd->add_flag("--subgoal", a->subgoal,
                "Score a subgoal (LSP) network's frontier estimates instead: Ps AUC, cross-entropy, cost errors, "
                "frontier order by exploration cost along runs through --seeds (optimistic in guided mazes, searches "
                "elsewhere; the config's sensor drives them)");
  cmd->add_option("--calibrate", a->calibrate,
                  "With --subgoal: run planner lsp through --seeds (tuning mazes, below 10000) instead, and write to "
                  "this file what its Ps means (the true share of each bin; lsp.calibration reads it)")
      ->needs(cmd->get_option("--subgoal"));
  cmd->add_option("--every", a->every, "With --subgoal: a sample every this many steps")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  return cmd;
}

}  // namespace

struct LearningCommands::Impl {
  DatagenArgs datagen;
  TrainArgs train;
  EvalSensorArgs eval;
  CLI::App *datagen_cmd = nullptr, *train_cmd = nullptr, *eval_cmd = nullptr;
};

LearningCommands::LearningCommands(CLI::App& app) : impl_(std::make_unique<Impl>()) {
  impl_->datagen_cmd = AddDatagenCommand(app, &impl_->datagen);
  impl_->train_cmd = AddTrainCommand(app, &impl_->train);
  impl_->eval_cmd = AddEvalSensorCommand(app, &impl_->eval);
}
LearningCommands::~LearningCommands() = default;

std::optional<int> LearningCommands::Run() {
  if (*impl_->datagen_cmd) return RunDatagen(impl_->datagen);
  if (*impl_->train_cmd) return RunTrain(impl_->train);
  if (*impl_->eval_cmd) return RunEvalSensor(impl_->eval);
  return std::nullopt;
}

}  // namespace toponav::cli

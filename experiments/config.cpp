#include "experiments/config.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/geometry.h"
#include "core/rng.h"
#include "experiments/internal/yaml_reader.h"
#include "experiments/navigation_trial.h"
#include "experiments/subgoal_calibration.h"

namespace toponav::experiments {

using internal::YamlSection;

const core::OptionFields<OpenWorldOptions>& OpenWorldOptions::Fields() {
  using O = OpenWorldOptions;
  static const core::OptionFields<O> fields{
      {"step_length", &O::step_length, 0.01, 50.0},
      {"mcmc_every", &O::mcmc_every, 1, 100000},
      {"sub_bin", &O::sub_bin},
      {"sigma_bearing", &O::sigma_bearing, 0.0, 3.0},
  };
  return fields;
}

const core::OptionFields<PictureOptions>& PictureOptions::Fields() {
  using O = PictureOptions;
  static const core::OptionFields<O> fields{
      {"pixels_per_unit", &O::pixels_per_unit, 0.1, 50.0},
      {"max_pixels", &O::max_pixels, 100, 20000},
  };
  return fields;
}

const core::OptionFields<BenchOptions>& BenchOptions::Fields() {
  using O = BenchOptions;
  static const core::OptionFields<O> fields{
      {"num_seeds", &O::num_seeds, 0, 1000000},
      {"max_steps", &O::max_steps, 1, 100000},
      {"mcmc_every", &O::mcmc_every, 0, 100000},
      {"videos", &O::videos},
  };
  return fields;
}

sim::MotionOptions MotionFor(const Config& config, const core::World& world) {
  sim::MotionOptions m = config.motion;
  if (!world.has_boundary()) m.step_length = config.open_world.step_length;
  return m;
}

SensorConfig SensorFor(const Config& config, const core::World& world) {
  SensorConfig s = config.sensor;
  if (world.has_boundary()) return s;
  s.learned.sub_bin = config.open_world.sub_bin;
  if (config.open_world.sigma_bearing > 0) s.learned.sigma_bearing = config.open_world.sigma_bearing;
  return s;
}

namespace {

// Rules that tie keys of different sections together (each names the key to change).
void ValidateAcrossSections(const Config& c) {
  // A split must not cut a frontier into pieces the planner ignores (an opening would vanish).
  if (c.mapping.frontier_split_min_length < c.planning.frontier_min_length)
    throw core::ConfigError(
        c.source, "mapping.frontier_split_min_length", std::to_string(c.mapping.frontier_split_min_length),
        "must be >= planning.frontier_min_length (" + std::to_string(c.planning.frontier_min_length) + ")");
  // Paths keep the agent's body off map walls, and stay below the inflation radius so the graph's nodes
  // (inflation_radius from each vertex) keep room to connect.
  const double lo = c.motion.agent_radius + 0.25, hi = 0.9 * c.planning.inflation_radius;
  if (c.planning.clearance < lo || c.planning.clearance > hi)
    throw core::ConfigError(c.source, "planning.clearance", std::to_string(c.planning.clearance),
                            "must be in [motion.agent_radius + 0.25, 0.9 * planning.inflation_radius] = [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + "]");
  const int held = c.navigation.scan_when_held;
  if (held > 0 && held >= c.navigation.stuck_window)
    throw core::ConfigError(c.source, "navigation.scan_when_held", std::to_string(held),
                            "must be 0 (off) or below navigation.stuck_window (" +
                                std::to_string(c.navigation.stuck_window) + "): a held agent scans before it is stuck");
  if (held > 0 && !c.sensor.range_ring.enabled())
    throw core::ConfigError(c.source, "navigation.scan_when_held", std::to_string(held),
                            "needs a range ring's scans: declare sensor.range_ring (rays, range)");
  if (c.bench.first_seed > core::kMaxSeed - uint64_t(c.bench.num_seeds))
    throw core::ConfigError(c.source, "bench.first_seed", std::to_string(c.bench.first_seed),
                            "first_seed + num_seeds must stay within [0, " + std::to_string(core::kMaxSeed) + "]");
  // The open worlds' bearing sigma replaces sensor.sigma_bearing there, so it meets the same range.
  const double sb = c.open_world.sigma_bearing;
  if (sb > 0 && sb < 1e-4)
    throw core::ConfigError(c.source, "open_world.sigma_bearing", std::to_string(sb),
                            "must be 0 (sensor.sigma_bearing) or in [0.0001, 3] as sensor.sigma_bearing");
  if (c.demo.seed > core::kMaxSeed)
    throw core::ConfigError(c.source, "demo.seed", std::to_string(c.demo.seed),
                            "must be in [0, " + std::to_string(core::kMaxSeed) + "]");
  if (c.demo.kinds.empty()) throw core::ConfigError(c.source, "demo.kinds", "[]", "list at least one world kind");
  for (auto k : c.demo.kinds)
    if (k == core::WorldKind::kCustom)
      throw core::ConfigError(c.source, "demo.kinds", "custom", "custom worlds cannot be generated");
}

// Runs a section's checks, naming the config file (and 'prefix' before the key) in the error.
template <class F>
void InSection(const Config& c, const std::string& prefix, F&& check) {
  try {
    check();
  } catch (const core::ConfigError& e) {
    throw core::ConfigError(c.source, prefix + e.key(), e.value(), e.problem());
  }
}

}  // namespace

void Validate(const Config& c) {
  InSection(c, "worlds.", [&] { c.worlds.Validate(); });
  InSection(c, "", [&] { c.sensor.Validate(); });
  InSection(c, "", [&] { c.mapping.Validate(); });
  InSection(c, "", [&] { c.planning.Validate(); });
  InSection(c, "", [&] { c.search.Validate(); });
  InSection(c, "", [&] { c.render.Validate(); });
  InSection(c, "", [&] { c.motion.Validate(); });
  InSection(c, "", [&] { core::CheckRanges(c.navigation, planning::NavigationOptions::Fields(), "navigation."); });
  InSection(c, "", [&] { c.lsp.Validate(); });
  InSection(c, "", [&] { core::CheckRanges(c.open_world, OpenWorldOptions::Fields(), "open_world."); });
  InSection(c, "", [&] { core::CheckRanges(c.picture, PictureOptions::Fields(), "picture."); });
  InSection(c, "", [&] { core::CheckRanges(c.bench, BenchOptions::Fields(), "bench."); });
  InSection(c, "", [&] { c.datagen.Validate(); });
  InSection(c, "", [&] { c.subgoal_data.Validate(); });
  InSection(c, "", [&] { c.train.Validate(); });
  ValidateAcrossSections(c);
}

namespace {

// A section that is an options struct with nothing but declared fields.
template <class Options>
void ReadSection(YamlSection s, Options* o) {
  s.ReadFields(o, Options::Fields());
  s.Finish();
}

core::WorldKind ReadWorldKind(YamlSection& s, const std::string& key, const std::string& name) {
  const auto k = core::ParseWorldKind(name);
  if (!k || *k == core::WorldKind::kCustom)
    s.Fail(key, name, "unknown world kind (labyrinth, office_park, guided_maze)");
  return *k;
}

void ReadSensor(YamlSection s, SensorConfig* sensor) {
  std::string kind = ToString(sensor->kind);
  s.Read("kind", &kind);
  const auto k = ParseSensorKind(kind);
  if (!k) s.Fail("kind", kind, fmt::format("unknown sensor kind (known: {})", fmt::join(SensorKindNames(), ", ")));
  sensor->kind = *k;
  if (sensor->kind == SensorKind::kNoisy) s.ReadFields(&sensor->noisy, sim::NoisySensorOptions::Fields());
  if (sensor->kind == SensorKind::kLearned || sensor->kind == SensorKind::kRecorded) {
    s.Read("model", &sensor->learned.model);
    s.Read("subgoal_model", &sensor->learned.subgoal_model);
    s.ReadFields(&sensor->learned, LearnedSensorOptions::Fields());
  }
  if (sensor->kind == SensorKind::kRecorded) {
    s.Read("images", &sensor->images);
    s.Read("poses", &sensor->poses);
  }
  if (s.Has("range_ring")) ReadSection(s.Section("range_ring"), &sensor->range_ring);
  s.Finish();  // keys of another kind are unknown here
}

void ReadSearch(YamlSection s, planning::SearchOptions* search) {
  s.ReadFields(search, planning::SearchOptions::Fields());
  s.Finish();
}

void ReadBench(YamlSection b, BenchOptions* bench) {
  b.Read("name", &bench->name);
  for (YamlSection row : b.Sequence("rows")) {
    BenchRow r;
    std::string kind = "labyrinth";
    row.Read("kind", &kind);
    r.kind = ReadWorldKind(row, "kind", kind);
    row.Read("agents", &r.agents, 1, 16);
    row.Read("planner", &r.planner);
    if (!r.planner.empty() && !ParseGoalPlanner(r.planner))
      row.Fail("planner", r.planner, "not a goal-directed planner (optimistic, oracle, lsp, known)");
    if (!r.planner.empty() && r.agents != 1)
      row.Fail("agents", std::to_string(r.agents), "navigation trials have one agent");
    row.Finish();
    bench->rows.push_back(r);
  }
  b.Read("first_seed", &bench->first_seed);
  b.ReadFields(bench, BenchOptions::Fields());
  static constexpr std::array<const char*, 3> kPictureSets{"false", "true", "failures"};  // PictureSet order
  std::string pictures = kPictureSets[size_t(bench->pictures)];
  b.Read("pictures", &pictures);
  const auto it = std::find_if(kPictureSets.begin(), kPictureSets.end(), [&](const char* n) { return pictures == n; });
  if (it == kPictureSets.end()) b.Fail("pictures", pictures, "expected true, false or failures");
  bench->pictures = PictureSet(it - kPictureSets.begin());
  b.Finish();
}

void ReadDemo(YamlSection d, DemoJob* demo) {
  if (d.Has("kinds")) {
    std::vector<std::string> kinds;
    d.Read("kinds", &kinds);
    demo->kinds.clear();
    for (const auto& k : kinds) demo->kinds.push_back(ReadWorldKind(d, "kinds", k));
  }
  d.Read("seed", &demo->seed);
  d.Read("out_dir", &demo->out_dir);
  d.Finish();
}

void ReadDatagen(YamlSection d, DatagenOptions* o) {
  if (d.Has("kinds")) {
    std::vector<std::string> kinds;
    d.Read("kinds", &kinds);
    o->kinds.clear();
    for (const auto& k : kinds) o->kinds.push_back(ReadWorldKind(d, "kinds", k));
  }
  d.ReadFields(o, DatagenOptions::Fields());
  d.Finish();
}

void ReadSubgoalData(YamlSection s, SubgoalDataOptions* o) {
  std::string kind = core::ToString(o->kind);
  s.Read("kind", &kind);
  o->kind = ReadWorldKind(s, "kind", kind);
  s.ReadFields(o, SubgoalDataOptions::Fields());
  s.Finish();
}

void ReadTrain(YamlSection t, learning::TrainOptions* o) {
  t.Read("init_from", &o->init_from);
  t.ReadFields(o, learning::TrainOptions::Fields());
  t.Finish();
}

// A relative file path as the config names it: from the working directory when it is there, else from the
// config file's folder or the nearest folder above it that has it (configs/maze/paper.yaml names
// models/lsp_net_cpu.pt from the repository root, and runs from any directory); else unchanged, so the
// error that follows names the path as written.
std::string FindFromConfig(const std::string& path, const std::string& source) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty() || fs::path(path).is_absolute() || fs::exists(path, ec)) return path;
  for (fs::path dir = fs::absolute(source, ec).parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (fs::exists(dir / path, ec)) return (dir / path).string();
    if (dir == dir.parent_path()) break;
  }
  return path;
}

// lsp:, and the file its key 'calibration' names (experiments/subgoal_calibration.h), read once here.
void ReadLsp(YamlSection s, planning::LspOptions* lsp, const std::string& source) {
  std::string calibration;
  s.Read("calibration", &calibration);
  s.ReadFields(lsp, planning::LspOptions::Fields());
  s.Finish();
  if (calibration.empty()) return;
  const std::string path = FindFromConfig(calibration, source);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw core::ConfigError(source, "lsp.calibration", calibration, "not a readable file");
  lsp->calibration = LoadSubgoalCalibration(path);
}

void ReadWorlds(YamlSection w, sim::WorldOptions* worlds) {
  ReadSection(w.Section("labyrinth"), &worlds->labyrinth);
  ReadSection(w.Section("office_park"), &worlds->office_park);
  ReadSection(w.Section("guided_maze"), &worlds->guided_maze);
  w.Finish();
}

}  // namespace

Config ParseConfig(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw core::ConfigError(source, "<file>", "", std::string("not valid YAML: ") + e.what());
  }
  Config c;
  c.source = source;
  YamlSection top(root, source, "");
  ReadWorlds(top.Section("worlds"), &c.worlds);
  ReadSection(top.Section("motion"), &c.motion);
  ReadSection(top.Section("render"), &c.render);
  ReadSensor(top.Section("sensor"), &c.sensor);
  ReadSection(top.Section("mapping"), &c.mapping);
  ReadSection(top.Section("planning"), &c.planning);
  ReadSearch(top.Section("search"), &c.search);
  ReadSection(top.Section("navigation"), &c.navigation);
  ReadLsp(top.Section("lsp"), &c.lsp, source);
  ReadSection(top.Section("open_world"), &c.open_world);
  ReadSection(top.Section("picture"), &c.picture);
  ReadBench(top.Section("bench"), &c.bench);
  ReadDemo(top.Section("demo"), &c.demo);
  ReadDatagen(top.Section("datagen"), &c.datagen);
  ReadTrain(top.Section("train"), &c.train);
  ReadSubgoalData(top.Section("subgoal_data"), &c.subgoal_data);
  top.Finish();
  for (std::string* path : {&c.sensor.learned.model, &c.sensor.learned.subgoal_model, &c.sensor.images,
                            &c.sensor.poses, &c.train.init_from})
    *path = FindFromConfig(*path, source);
  Validate(c);
  return c;
}

Config LoadConfig(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw core::ConfigError(path, "<file>", "", "not a readable file");
  std::ifstream in(path);
  if (!in) throw core::ConfigError(path, "<file>", "", "cannot open the config file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ParseConfig(ss.str(), path);
}

}  // namespace toponav::experiments

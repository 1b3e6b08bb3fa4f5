#pragma once
// Run configuration: every run is described by a YAML file under configs/.  Loading is strict (unknown keys,
// wrong types and out-of-range values are core::ConfigError naming the file, the key path and the value) and
// happens only here, at the edge; the rest of the program sees plain option structs.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/datagen.h"
#include "experiments/sensor_factory.h"
#include "experiments/subgoal_data_options.h"
#include "learning/train_options.h"
#include "mapping/mapping.h"
#include "planning/lsp_planner.h"
#include "planning/navigation.h"
#include "planning/navigator_options.h"
#include "sim/motion.h"
#include "sim/render.h"
#include "sim/worlds.h"

namespace toponav::experiments {

// `toponav demo`: one world of each kind, its picture, observation and panorama.
struct DemoJob {
  std::vector<core::WorldKind> kinds{core::WorldKind::kLabyrinth, core::WorldKind::kOfficePark,
                                     core::WorldKind::kGuidedMaze};
  uint64_t seed = 10000;
  std::string out_dir = "results/worlds";
};

// A search benchmark (paper Table I): rows of (world kind, agent count), each run over the same seeds.
// A row with a planner runs goal-directed navigation trials (one agent, start to goal) with that planner.
struct BenchRow {
  core::WorldKind kind = core::WorldKind::kLabyrinth;
  int agents = 1;
  std::string planner;  // "" (a search) or a goal-directed planner: "optimistic", "oracle", "lsp", "known"
};

// Which trials of a bench get a final picture (bench.pictures: true, false or failures).
enum class PictureSet { kNone, kAll, kFailures };  // the order of config.cpp's names

struct BenchOptions {
  std::string name = "search";
  std::vector<BenchRow> rows;
  uint64_t first_seed = 10000;   // seeds first_seed .. first_seed + num_seeds - 1 (benchmarks use >= 10000)
  int num_seeds = 0;
  int max_steps = 400;
  int mcmc_every = 5;
  // A final PNG per trial (true), none (false), or only of failed trials and each row's first seed
  // (failures: a few representative pictures to commit, not one per trial).
  PictureSet pictures = PictureSet::kAll;
  bool videos = false;           // an MP4 of every trial (videos/<row>_s<seed>.mp4; slow: one frame a step)
  static const core::OptionFields<BenchOptions>& Fields();  // the numeric and boolean keys (under bench:)
};

// What differs in open worlds (the office park), YAML section `open_world:`: agents take the longer outdoor
// step (the reference's outdoor motion primitive), MCMC runs more often at the same proposals per step
// (a call proposes mapping.mcmc_samples * mcmc_every / bench.mcmc_every, at least 1), and the learned sensor
// may place each detection within its network cell, with its own bearing sigma.
struct OpenWorldOptions {
  double step_length = 3.6;  // world units per agent step (motion.step_length elsewhere)
  int mcmc_every = 2;        // MCMC cadence in steps (bench.mcmc_every elsewhere; 0 there turns MCMC off)
  bool sub_bin = false;      // learned sensor: a peak's range and bearing move to the centroid of its cell
                             // and neighbours (learning::DecodeOptions::sub_bin); elsewhere it sits at the
                             // cell's centre
  double sigma_bearing = 0.0;  // > 0: the learned sensor's reported bearing sigma (radians; sensor.sigma_bearing
                               // elsewhere); 0: sensor.sigma_bearing here too
  static const core::OptionFields<OpenWorldOptions>& Fields();
};

struct PictureOptions {
  double pixels_per_unit = 3.0;  // scale of top-down pictures
  int max_pixels = 2400;         // the longer image side is capped at this
  static const core::OptionFields<PictureOptions>& Fields();
};

struct Config {
  std::string source = "<defaults>";  // the file it was loaded from
  sim::WorldOptions worlds;
  sim::MotionOptions motion;
  sim::RenderOptions render;
  SensorConfig sensor;
  mapping::MapperOptions mapping;
  planning::PlannerOptions planning;
  planning::SearchOptions search;
  planning::NavigationOptions navigation;
  planning::LspOptions lsp;
  OpenWorldOptions open_world;
  DatagenOptions datagen;
  learning::TrainOptions train;
  SubgoalDataOptions subgoal_data;
  PictureOptions picture;
  DemoJob demo;
  BenchOptions bench;
};

// The motion options agents use in 'world' (open worlds take open_world.step_length): derived once, here.
sim::MotionOptions MotionFor(const Config& config, const core::World& world);
// The sensor that observes 'world' (open worlds take open_world.sub_bin and sigma_bearing): derived once, here.
SensorConfig SensorFor(const Config& config, const core::World& world);

// Loads and validates 'path'.  Every section and key is optional (defaults above); unknown keys are errors.
Config LoadConfig(const std::string& path);
// Parses YAML text as if it came from 'source' (used by tests).
Config ParseConfig(const std::string& yaml_text, const std::string& source);
// Validates cross-field rules of a config built in code; throws core::ConfigError naming config.source.
void Validate(const Config& config);

}  // namespace toponav::experiments

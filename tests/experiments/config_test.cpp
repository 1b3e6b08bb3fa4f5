#include "experiments/config.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>

#include "core/error.h"

namespace toponav::experiments {
namespace {

core::ConfigError ErrorOf(const std::string& yaml) {
  try {
    ParseConfig(yaml, "configs/bad.yaml");
  } catch (const core::ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << yaml;
  return core::ConfigError("", "", "", "");
}

TEST(Config, EmptyFileGivesDefaults) {
  const Config c = ParseConfig("", "empty.yaml");
  EXPECT_EQ(c.worlds.labyrinth.num_rooms, 4);
  EXPECT_DOUBLE_EQ(c.motion.step_length, 1.8);
  EXPECT_EQ(c.demo.kinds.size(), 3u);
}

TEST(Config, ValuesAreRead) {
  const Config c = ParseConfig(
      "worlds:\n  labyrinth:\n    num_rooms: 5\nmotion:\n  step_length: 2.5\n"
      "demo:\n  kinds: [guided_maze]\n  seed: 12345\n",
      "x.yaml");
  EXPECT_EQ(c.worlds.labyrinth.num_rooms, 5);
  EXPECT_DOUBLE_EQ(c.motion.step_length, 2.5);
  ASSERT_EQ(c.demo.kinds.size(), 1u);
  EXPECT_EQ(c.demo.kinds[0], core::WorldKind::kGuidedMaze);
  EXPECT_EQ(c.demo.seed, 12345u);
}

TEST(Config, TheLspCalibrationFileIsReadFromBesideTheConfigAndAMissingOneIsAnErrorNamingTheKey) {
  const auto dir = std::filesystem::temp_directory_path() / "toponav_config_calibration";
  std::filesystem::create_directories(dir / "models");
  std::ofstream(dir / "models" / "cal.yaml") << "ps: [[0.1, 0.0], [0.9, 0.8]]\n";
  const Config c = ParseConfig("lsp:\n  calibration: models/cal.yaml\n", (dir / "run.yaml").string());
  ASSERT_EQ(c.lsp.calibration.ps.knots.size(), 2u);
  EXPECT_DOUBLE_EQ(c.lsp.calibration.ps(0.9), 0.8);
  const core::ConfigError e = ErrorOf("lsp:\n  calibration: models/none.yaml\n");
  EXPECT_NE(std::string(e.what()).find("lsp.calibration"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("models/none.yaml"), std::string::npos) << e.what();
  std::filesystem::remove_all(dir);
}

TEST(Config, OpenWorldSettingsFormOneBlock) {
  const Config d = ParseConfig("", "empty.yaml");
  EXPECT_EQ(d.open_world.mcmc_every, 2);
  EXPECT_DOUBLE_EQ(d.open_world.step_length, 3.6);
  const Config c = ParseConfig("bench:\n  mcmc_every: 5\nopen_world:\n  mcmc_every: 1\n  step_length: 3.0\n", "x.yaml");
  EXPECT_EQ(c.bench.mcmc_every, 5);
  EXPECT_EQ(c.open_world.mcmc_every, 1);
  EXPECT_EQ(ErrorOf("open_world:\n  mcmc_every: 0\n").key(), "open_world.mcmc_every");
  EXPECT_EQ(ErrorOf("bench:\n  open_world_mcmc_every: 2\n").key(), "bench.open_world_mcmc_every")
      << "the old key is gone";
  EXPECT_EQ(ErrorOf("motion:\n  open_world_step_length: 3\n").key(), "motion.open_world_step_length");
  // Derived once: agents in an open world take the open-world step.
  core::World open;
  open.bounds = {{0, 0}, {100, 100}};
  EXPECT_DOUBLE_EQ(MotionFor(c, open).step_length, 3.0);
  core::World closed = open;
  closed.boundary = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  EXPECT_DOUBLE_EQ(MotionFor(c, closed).step_length, c.motion.step_length);
}

TEST(Config, SubBinDecodingAndItsBearingSigmaApplyInOpenWorldsOnly) {
  const Config c = ParseConfig(
      "sensor:\n  kind: learned\n  model: m.pt\n  sigma_bearing: 0.025\nopen_world:\n  sub_bin: true\n"
      "  sigma_bearing: 0.02\n",
      "x.yaml");
  core::World open;
  open.bounds = {{0, 0}, {100, 100}};
  core::World closed = open;
  closed.boundary = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  EXPECT_TRUE(SensorFor(c, open).learned.sub_bin);
  EXPECT_DOUBLE_EQ(SensorFor(c, open).learned.sigma_bearing, 0.02);
  EXPECT_FALSE(SensorFor(c, closed).learned.sub_bin);
  EXPECT_DOUBLE_EQ(SensorFor(c, closed).learned.sigma_bearing, 0.025);
  EXPECT_FALSE(SensorFor(ParseConfig("", "empty.yaml"), open).learned.sub_bin) << "off by default";
  EXPECT_EQ(ErrorOf("sensor:\n  sub_bin: true\n").key(), "sensor.sub_bin") << "the key lives in open_world";
  EXPECT_EQ(ErrorOf("open_world:\n  sigma_bearing: 0.00001\n").key(), "open_world.sigma_bearing");
}

// Every declared numeric key of a section: the YAML reader rejects a value past its range naming the key, and
// Validate() rejects the same value set in code, naming the same key.
template <class Options, class Get>
void ExpectOneRangePerKey(const std::string& section, Get get) {
  int checked = 0;
  for (const auto& f : Options::Fields()) {
    if (std::holds_alternative<bool Options::*>(f.member)) continue;
    const double bad = std::isfinite(f.hi) ? f.hi + 1 : f.lo - 1;
    std::ostringstream yaml;
    yaml << section << ":\n  " << f.key << ": " << bad << "\n";
    EXPECT_EQ(ErrorOf(yaml.str()).key(), section + "." + f.key);
    Config c;
    Options& o = get(c);
    if (const auto* d = std::get_if<double Options::*>(&f.member))
      o.*(*d) = bad;
    else
      o.*std::get<int Options::*>(f.member) = int(bad);
    try {
      Validate(c);
      ADD_FAILURE() << section << "." << f.key << " = " << bad << " passed Validate()";
    } catch (const core::ConfigError& e) {
      EXPECT_EQ(e.key(), section + "." + f.key);
    }
    ++checked;
  }
  EXPECT_GT(checked, 0) << section;
}

TEST(Config, EachKeysRangeIsDeclaredOnceForTheReaderAndValidate) {
  ExpectOneRangePerKey<mapping::MapperOptions>(
      "mapping", [](Config & c) -> auto& { return c.mapping; });
  ExpectOneRangePerKey<planning::PlannerOptions>(
      "planning", [](Config & c) -> auto& { return c.planning; });
  ExpectOneRangePerKey<planning::SearchOptions>(
      "search", [](Config & c) -> auto& { return c.search; });
  ExpectOneRangePerKey<sim::NoisySensorOptions>(
      "sensor", [](Config & c) -> auto& { return c.sensor.noisy; });
  ExpectOneRangePerKey<sim::MotionOptions>(
      "motion", [](Config & c) -> auto& { return c.motion; });
  ExpectOneRangePerKey<sim::RenderOptions>(
      "render", [](Config & c) -> auto& { return c.render; });
  ExpectOneRangePerKey<OpenWorldOptions>(
      "open_world", [](Config & c) -> auto& { return c.open_world; });
  ExpectOneRangePerKey<planning::NavigationOptions>(
      "navigation", [](Config & c) -> auto& { return c.navigation; });
  ExpectOneRangePerKey<BenchOptions>(
      "bench", [](Config & c) -> auto& { return c.bench; });
  ExpectOneRangePerKey<PictureOptions>(
      "picture", [](Config & c) -> auto& { return c.picture; });
  ExpectOneRangePerKey<SubgoalDataOptions>(
      "subgoal_data", [](Config & c) -> auto& { return c.subgoal_data; });
  ExpectOneRangePerKey<learning::TrainOptions>(
      "train", [](Config & c) -> auto& { return c.train; });
}

TEST(Config, TheSubgoalNetworksDataAndStartingModelAreRead) {
  const Config c = ParseConfig(
      "subgoal_data:\n  train_first_seed: 100\n  train_num_seeds: 5\n  val_first_seed: 200\n  val_num_seeds: 2\n  "
      "every: 4\n"
      "train:\n  subgoal: true\n  init_from: models/vertex_net_cpu.pt\n",
      "configs/lsp.yaml");
  EXPECT_EQ(c.subgoal_data.train_num_seeds, 5);
  EXPECT_EQ(c.subgoal_data.every, 4);
  EXPECT_TRUE(c.train.subgoal);
  EXPECT_TRUE(std::filesystem::equivalent(c.train.init_from, TOPONAV_SOURCE_DIR "/models/vertex_net_cpu.pt"))
      << c.train.init_from << ": the committed model, from whatever folder the test runs in";
  EXPECT_EQ(ErrorOf("subgoal_data:\n  train_first_seed: 9990\n  train_num_seeds: 20\n").key(),
            "subgoal_data.train_num_seeds")
      << "benchmark mazes (seeds from 10000) are never trained on";
  EXPECT_EQ(ErrorOf("subgoal_data:\n  train_first_seed: 2000\n  val_first_seed: 2050\n").key(),
            "subgoal_data.val_first_seed")
      << "validation mazes are not training mazes";
}

TEST(Config, RelativeFilesAreFoundFromTheConfigsFolderOrAFolderAboveIt) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("toponav_config_paths_" + std::to_string(::getpid()));
  fs::create_directories(root / "configs" / "maze");
  fs::create_directories(root / "models");
  std::ofstream(root / "models" / "net.pt") << "x";
  const std::string config = (root / "configs" / "maze" / "c.yaml").string();
  std::ofstream(config) << "sensor:\n  kind: learned\n  model: models/net.pt\ntrain:\n  init_from: models/none.pt\n";
  const Config c = LoadConfig(config);
  EXPECT_EQ(fs::path(c.sensor.learned.model), root / "models" / "net.pt") << "found two folders up";
  EXPECT_EQ(c.train.init_from, "models/none.pt") << "a file found nowhere stays as written, for the error to name";
  fs::remove_all(root);
}

TEST(Config, SearchAndNavigationAreReadAndCheckedBySection) {
  const Config c = ParseConfig("search:\n  give_up_steps: 12\n  tour: true\n", "x.yaml");
  EXPECT_EQ(c.search.give_up_steps, 12);
  EXPECT_TRUE(c.search.tour);
  EXPECT_FALSE(c.search.block_when_stuck);
  EXPECT_FALSE(c.search.close_buildings);
  EXPECT_TRUE(ParseConfig("search:\n  close_buildings: true\n", "x.yaml").search.close_buildings);
  EXPECT_EQ(c.search.dropped_wall_steps, 0) << "off unless set";
  EXPECT_EQ(ParseConfig("search:\n  dropped_wall_steps: 10\n", "x.yaml").search.dropped_wall_steps, 10);
  EXPECT_EQ(ErrorOf("search:\n  dropped_wall_steps: -1\n").key(), "search.dropped_wall_steps");
  EXPECT_DOUBLE_EQ(c.search.sealed_reach, 0.0) << "off unless set";
  EXPECT_DOUBLE_EQ(ParseConfig("search:\n  sealed_reach: 10\n", "x.yaml").search.sealed_reach, 10.0);
  EXPECT_EQ(ErrorOf("search:\n  sealed_reach: -1\n").key(), "search.sealed_reach");
  EXPECT_DOUBLE_EQ(c.search.push_distance, planning::SearchOptions{}.push_distance) << "unset keys keep their defaults";
  const auto e = ErrorOf("search:\n  give_up_steps: 0\n");
  EXPECT_EQ(e.file(), "configs/bad.yaml");
  EXPECT_EQ(e.key(), "search.give_up_steps");
  EXPECT_EQ(e.value(), "0");
  EXPECT_EQ(ErrorOf("search:\n  give_up_step: 12\n").key(), "search.give_up_step");
  // The reference's values that no config sets are not keys; navigation owns its own.
  EXPECT_EQ(ErrorOf("search:\n  switch_ratio: 2.0\n").key(), "search.switch_ratio");
  EXPECT_EQ(ErrorOf("navigation:\n  stuck_window: 50\n").key(), "navigation.stuck_window");
  EXPECT_TRUE(ParseConfig("navigation:\n  block_when_stuck: true\n", "x.yaml").navigation.block_when_stuck);
  EXPECT_FALSE(ParseConfig("navigation:\n  block_when_stuck: true\n", "x.yaml").search.block_when_stuck);
  EXPECT_LE(planning::SearchOptions::Fields().size() + planning::NavigationOptions::Fields().size(), 15u);
  EXPECT_EQ(ErrorOf("search:\n  depth_weight: 0.5\n").key(), "search.depth_weight") << "a dropped option is unknown";
  // Built in code, not read: the same rules, named by key.
  Config bad;
  bad.source = "in-code";
  bad.search.give_up_steps = 0;
  try {
    Validate(bad);
    ADD_FAILURE() << "no error";
  } catch (const core::ConfigError& x) {
    EXPECT_EQ(x.key(), "search.give_up_steps");
    EXPECT_EQ(x.file(), "in-code");
  }
}

TEST(Config, UnknownKeyNamesFileAndKeyPath) {
  const auto e = ErrorOf("worlds:\n  labyrinth:\n    num_romos: 5\n");
  EXPECT_EQ(e.file(), "configs/bad.yaml");
  EXPECT_EQ(e.key(), "worlds.labyrinth.num_romos");
  EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos);
}

TEST(Config, UnknownTopLevelSectionIsAnError) { EXPECT_EQ(ErrorOf("mapper:\n  x: 1\n").key(), "mapper"); }

TEST(Config, WrongTypeNamesKeyAndValue) {
  const auto e = ErrorOf("motion:\n  step_length: fast\n");
  EXPECT_EQ(e.key(), "motion.step_length");
  EXPECT_EQ(e.value(), "fast");
  EXPECT_NE(std::string(e.what()).find("expected a number"), std::string::npos);
  EXPECT_EQ(ErrorOf("worlds:\n  labyrinth:\n    num_rooms: 4.5\n").key(), "worlds.labyrinth.num_rooms");
  EXPECT_EQ(ErrorOf("demo:\n  seed: -3\n").key(), "demo.seed");
  EXPECT_EQ(ErrorOf("demo:\n  kinds: labyrinth\n").key(), "demo.kinds");
  EXPECT_EQ(ErrorOf("worlds: [1, 2]\n").key(), "worlds");
}

TEST(Config, OutOfRangeNamesKeyValueAndRange) {
  const auto e = ErrorOf("worlds:\n  guided_maze:\n    cells_x: 500\n");
  EXPECT_EQ(e.key(), "worlds.guided_maze.cells_x");
  EXPECT_EQ(e.value(), "500");
  EXPECT_NE(std::string(e.what()).find("[2, 50]"), std::string::npos);
}

TEST(Config, CrossFieldRulesNameTheFile) {
  const auto e = ErrorOf("worlds:\n  office_park:\n    min_building_gap: 50\n    max_building_gap: 40\n");
  EXPECT_EQ(e.file(), "configs/bad.yaml");
  EXPECT_EQ(e.key(), "worlds.office_park.min_building_gap");
}

TEST(Config, AFrontierPieceShorterThanTheLspCellIsAnError) {
  const auto e = ErrorOf("lsp:\n  cell: 2\n  piece_length: 0.5\n");
  EXPECT_EQ(e.file(), "configs/bad.yaml");
  EXPECT_EQ(e.key(), "lsp.piece_length");
  EXPECT_NO_THROW(ParseConfig("lsp:\n  piece_length: 0\n", "k.yaml")) << "0: frontiers whole";
}

TEST(Config, AHeldAgentScansWithADeclaredRangeRingBeforeTheStuckTestEndsItsTrial) {
  EXPECT_EQ(planning::NavigationOptions{}.scan_when_held, 0) << "off unless set";
  const std::string ring = "sensor:\n  range_ring: {rays: 360, range: 12}\n";
  const Config c = ParseConfig(ring + "navigation:\n  scan_when_held: 20\n", "k.yaml");
  EXPECT_EQ(c.navigation.scan_when_held, 20);
  EXPECT_EQ(c.sensor.range_ring.rays, 360);
  EXPECT_EQ(SensorsUsed(c.sensor), "noisy+range_ring");
  const auto none = ErrorOf("navigation:\n  scan_when_held: 20\n");
  EXPECT_EQ(none.key(), "navigation.scan_when_held") << "scans need a declared range ring";
  EXPECT_NE(std::string(none.what()).find("sensor.range_ring"), std::string::npos) << none.what();
  EXPECT_EQ(ErrorOf("sensor:\n  range_ring: {rays: -3}\n").key(), "sensor.range_ring.rays");
  const auto e = ErrorOf(ring + "navigation:\n  scan_when_held: 100\n");
  EXPECT_EQ(e.key(), "navigation.scan_when_held") << "not below navigation.stuck_window (100)";
  EXPECT_EQ(e.value(), "100");
  EXPECT_EQ(ErrorOf("navigation:\n  scan_when_held: -1\n").key(), "navigation.scan_when_held");
}

TEST(Config, UnknownWorldKindIsNamed) {
  const auto e = ErrorOf("demo:\n  kinds: [labyrinth, castle]\n");
  EXPECT_EQ(e.key(), "demo.kinds");
  EXPECT_EQ(e.value(), "castle");
}

TEST(Config, MissingFileIsAConfigError) { EXPECT_THROW(LoadConfig("/nonexistent/config.yaml"), core::ConfigError); }

TEST(Config, InvalidYamlIsAConfigError) {
  EXPECT_THROW(ParseConfig("worlds: [unclosed\n", "broken.yaml"), core::ConfigError);
}

}  // namespace
}  // namespace toponav::experiments

namespace toponav::experiments {
namespace {

TEST(Config, DuplicateKeyIsAnError) {
  try {
    ParseConfig("motion:\n  step_length: 1.0\n  step_length: 2.0\n", "dup.yaml");
    FAIL();
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "motion.step_length");
    EXPECT_NE(std::string(e.what()).find("twice"), std::string::npos);
  }
}

TEST(Config, QuotedNumberIsAnError) {
  try {
    ParseConfig("motion:\n  step_length: \"2.0\"\n", "q.yaml");
    FAIL();
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "motion.step_length");
  }
}

TEST(Config, NonScalarKeyIsAConfigError) { EXPECT_THROW(ParseConfig("? [a, b]\n: 1\n", "k.yaml"), core::ConfigError); }

TEST(Config, DirectoryIsNotAConfigFile) { EXPECT_THROW(LoadConfig(TOPONAV_SOURCE_DIR "/configs"), core::ConfigError); }

}  // namespace
}  // namespace toponav::experiments

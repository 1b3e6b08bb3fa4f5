#include "experiments/cli/common.h"

#include <filesystem>

#include "core/error.h"
#include "experiments/cli_parse.h"
#include "sim/world_io.h"
#include "sim/worlds.h"

namespace toponav::cli {

namespace fs = std::filesystem;

double MsSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

core::WorldKind ParseKind(const std::string& text) {
  auto k = core::ParseWorldKind(text);
  if (!k || *k == core::WorldKind::kCustom)
    throw core::ConfigError("<command line>", "--kind", text, "expected labyrinth, office_park or guided_maze");
  return *k;
}

experiments::Config LoadOrDefault(const std::string& path) {
  return path.empty() ? experiments::Config{} : experiments::LoadConfig(path);
}

experiments::Config LoadWithModel(const std::string& path, const std::string& model) {
  experiments::Config cfg = LoadOrDefault(path);
  if (!model.empty()) {
    cfg.sensor.kind = experiments::SensorKind::kLearned;
    cfg.sensor.learned.model = model;
  }
  return cfg;
}

void EnsureDir(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw core::DataError(dir, "cannot create the directory: " + ec.message());
}


void AddWorldSourceOptions(CLI::App* cmd, WorldSource* src, const std::string& config_help) {
  cmd->add_option("--world", src->world_file, "World file (world.json)");
  cmd->add_option("--kind,--world-kind", src->kind,
                  "Or generate a world of this kind (labyrinth, office_park, guided_maze) ...");
  cmd->add_option("--seed", src->seed, "... from this seed")->capture_default_str();
  cmd->add_option("--config", src->config, config_help);
  cmd->add_option("--pose", src->pose, "Agent pose x,y,yaw (world units, radians); default: the world's start");
}

// The world with its start moved to --pose (trial, map), which must lie in free space.
core::World StartAtPose(core::World w, const std::string& pose) {
  if (pose.empty()) return w;
  const core::Pose2 p = experiments::ParsePose(pose);
  if (!w.bounds.Contains(p.position()) || !core::IsFree(w, p.position(), true))
    throw core::ConfigError("<command line>", "--pose", pose, "must lie in the world's free space");
  w.start = p;
  return w;
}

core::World WorldFromSource(const WorldSource& src, const experiments::Config& cfg) {
  if (!src.world_file.empty()) return sim::LoadWorld(src.world_file);
  if (!src.kind.empty()) return sim::GenerateWorld(ParseKind(src.kind), cfg.worlds, experiments::ParseSeed(src.seed));
  throw core::ConfigError("<command line>", "--world", "", "give --world FILE or --kind K --seed N");
}

}  // namespace toponav::cli

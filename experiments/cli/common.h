#pragma once
// What the toponav subcommands share: strict parsing of a world kind, config loading, checked file writes,
// and where a command's world comes from.
#include <CLI/CLI.hpp>

#include <chrono>
#include <string>

#include "core/world.h"
#include "experiments/config.h"
#include "experiments/results_io.h"

namespace toponav::cli {

using Clock = std::chrono::steady_clock;
double MsSince(Clock::time_point t0);

core::WorldKind ParseKind(const std::string& text);  // --kind: a generated kind
experiments::Config LoadOrDefault(const std::string& path);  // "" -> the defaults
// The same, with the sensor made the learned one on 'model' when one is given (--model).
experiments::Config LoadWithModel(const std::string& path, const std::string& model);
using experiments::WriteTextFile;  // checked writes (experiments/results_io.h)
void EnsureDir(const std::string& dir);

// Where a command's world comes from: a file, or a generator kind and seed (with an optional config).
struct WorldSource {
  std::string world_file, kind, config, pose;
  std::string seed = "0";  // parsed strictly (experiments::ParseSeed)
};
void AddWorldSourceOptions(CLI::App* cmd, WorldSource* src, const std::string& config_help);
// The world with its start moved to --pose (trial, map), which must lie in free space.
core::World StartAtPose(core::World w, const std::string& pose);
core::World WorldFromSource(const WorldSource& src, const experiments::Config& cfg);

}  // namespace toponav::cli

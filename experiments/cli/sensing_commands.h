#pragma once
// The subcommands that look at a world through a sensor: observe (the ground truth, or the config's sensor, at
// one pose), render (a panorama, a contact sheet, or a recorded sequence: panoramas + poses.csv), map (a map
// built along a drive, or from a recorded sequence of panoramas).
#include <CLI/CLI.hpp>

#include <memory>
#include <optional>

namespace toponav::cli {

class SensingCommands {
 public:
  explicit SensingCommands(CLI::App& app);  // registers the subcommands
  ~SensingCommands();
  // Runs the subcommand given on the command line, if it is one of these (its exit code).
  std::optional<int> Run();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::cli

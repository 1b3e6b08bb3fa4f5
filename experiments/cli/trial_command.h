#pragma once
// The trial subcommand: one search trial (one agent, or a team over distinct frontiers), or with --planner one
// goal-directed navigation trial; trial.png, and on request a video, a CSV trace, or navigation frames.
#include <CLI/CLI.hpp>

#include <memory>
#include <optional>

namespace toponav::cli {

class TrialCommand {
 public:
  explicit TrialCommand(CLI::App& app);  // registers the subcommand
  ~TrialCommand();
  // Runs the trial if it is the subcommand given on the command line (its exit code).
  std::optional<int> Run();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::cli

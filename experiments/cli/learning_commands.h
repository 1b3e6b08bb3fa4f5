#pragma once
// The learned vertex sensor's subcommands: datagen (export training data), train, eval-sensor.
#include <CLI/CLI.hpp>

#include <memory>
#include <optional>

namespace toponav::cli {

class LearningCommands {
 public:
  explicit LearningCommands(CLI::App& app);  // registers the subcommands
  ~LearningCommands();
  // Runs the subcommand given on the command line, if it is one of these (its exit code).
  std::optional<int> Run();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::cli

// Every shipped config under configs/ loads and validates.
#include <gtest/gtest.h>

#include <filesystem>

#include "experiments/config.h"

namespace toponav::experiments {
namespace {

TEST(ShippedConfigs, EveryYamlFileLoadsAndValidates) {
  const std::filesystem::path root = std::filesystem::path(TOPONAV_SOURCE_DIR) / "configs";
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(LoadConfig(entry.path().string()));
    ++count;
  }
  EXPECT_GE(count, 1);
}

TEST(ShippedConfigs, EveryCommittedModelTheyNameIsThere) {
  const std::filesystem::path source(TOPONAV_SOURCE_DIR);
  int named = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(source / "configs")) {
    if (entry.path().extension() != ".yaml") continue;
    const Config c = LoadConfig(entry.path().string());
    for (const std::string& model : {c.sensor.learned.model, c.train.init_from}) {
      if (model.rfind("models/", 0) != 0) continue;  // a model a recipe writes elsewhere first
      EXPECT_TRUE(std::filesystem::is_regular_file(source / model)) << entry.path() << " names " << model;
      ++named;
    }
  }
  EXPECT_GE(named, 1);
}

}  // namespace
}  // namespace toponav::experiments

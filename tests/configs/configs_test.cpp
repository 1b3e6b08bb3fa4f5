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

}  // namespace
}  // namespace toponav::experiments

#include "experiments/datagen.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <unistd.h>

#include "core/error.h"
#include "tests/testing/training_data.h"
#include "experiments/config.h"
#include "sim/raycast.h"

namespace toponav::experiments {
namespace {

namespace fs = std::filesystem;

DatagenOptions Tiny() { return testing::TinyDatagen(); }

TEST(Datagen, ABenchmarkSeedInTheConfigIsRefusedNamingTheKey) {
  try {
    ParseConfig("datagen:\n  train_first_seed: 10000\n", "x.yaml");
    ADD_FAILURE() << "a benchmark seed was accepted for training";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "datagen.train_first_seed");
  }
}

TEST(Datagen, TheExportHoldsTheDocumentedFiles) {
  const fs::path dir = fs::temp_directory_path() / ("toponav_datagen_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const ExportSummary s = ExportDataset(Tiny(), {}, {}, core::RangeBearingGrid{}, dir.string(), 2);
  EXPECT_EQ(s.samples, 4) << "two per split";
  for (const char* f : {"dataset.json", "index.csv", "contact_sheet.png", "train/000000.png", "train/000001_labels.png",
                        "val/000001.png"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  std::ifstream index(dir / "index.csv");
  std::string line;
  int lines = 0;
  while (std::getline(index, line)) ++lines;
  EXPECT_EQ(lines, 5) << "a header and one line per sample";
  EXPECT_EQ(fs::file_size(dir / "train/000000_labels.png") > 0, true);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace toponav::experiments

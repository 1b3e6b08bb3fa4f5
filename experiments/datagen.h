#pragma once
// Exporting the vertex sensor's training data (sim/training_data.h) as files a user can open elsewhere.
#include <chrono>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/range_bearing_grid.h"
#include "sim/render.h"
#include "sim/training_data.h"
#include "sim/worlds.h"

namespace toponav::experiments {

using sim::DatagenOptions;
using sim::ListSamples;
using sim::Sample;
using sim::SampleId;
using sim::Split;
using sim::WorldSampler;

struct ExportSummary {
  int samples = 0;
  double seconds = 0.0;
  double samples_per_second() const { return seconds > 0 ? samples / seconds : 0.0; }
};

// What every export writes beside its samples: DIR/index.csv (a header, then a row a sample), and
// DIR/contact_sheet.png of the first few panoramas with their labels drawn; Finish() writes both and times
// the export from construction.
class ExportWriter {
 public:
  ExportWriter(std::string out_dir, const std::string& index_header);
  std::ostringstream& index() { return index_; }
  bool WantsPicture() const { return sheet_.size() < 6; }
  void AddPicture(core::Panorama picture, std::string caption);
  void CountSample() { ++summary_.samples; }
  ExportSummary Finish();

 private:
  std::string out_dir_;
  std::ostringstream index_;
  std::vector<core::Panorama> sheet_;
  std::vector<std::string> captions_;
  ExportSummary summary_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Writes the dataset (README "Training data" documents the layout): DIR/dataset.json, DIR/index.csv,
// DIR/<split>/NNNNNN.png (panorama) and NNNNNN_labels.png (the grid: 0 no vertex, 1-4 the label), and
// DIR/contact_sheet.png with the labels drawn on the first panoramas.  'max_samples' > 0 caps each split.
ExportSummary ExportDataset(const DatagenOptions& options, const sim::WorldOptions& worlds,
                            const sim::RenderOptions& render, const core::RangeBearingGrid& grid,
                            const std::string& out_dir, int max_samples = 0);

}  // namespace toponav::experiments

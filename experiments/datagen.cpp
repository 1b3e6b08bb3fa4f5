#include "experiments/datagen.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "experiments/draw.h"
#include "experiments/results_io.h"
#include "sim/raycast.h"

namespace toponav::experiments {

namespace fs = std::filesystem;

namespace {

// The labels drawn on a copy of the panorama: a coloured tick at each labelled column, with a box at a
// height that grows with range (near: top).  Colours: right gap orange, corner yellow, left gap magenta,
// point cyan.
core::Panorama WithLabels(core::Panorama pano, const sim::VertexLabelGrid& labels) {
  static const uint8_t kColour[4][3] = {{255, 140, 0}, {255, 230, 0}, {230, 0, 230}, {0, 220, 230}};
  const auto& g = labels.grid;
  auto put = [&](int x, int y, const uint8_t* c) {
    if (x < 0 || x >= pano.width || y < 0 || y >= pano.height) return;
    for (int k = 0; k < 3; ++k) pano.rgb[3 * (size_t(y) * size_t(pano.width) + size_t(x)) + size_t(k)] = c[k];
  };
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      const uint8_t cell = labels.cells[g.Index(r, c)];
      if (cell == sim::kNoVertex) continue;
      const uint8_t* colour = kColour[cell - 1];
      const int x = int(std::lround(double(c) * pano.width / g.cols));
      const int y = int((r + 0.5) * pano.height / g.rows);
      for (int yy = 0; yy < pano.height; yy += 3) put(x, yy, colour);
      for (int dx = -3; dx <= 3; ++dx)
        for (int dy = -3; dy <= 3; ++dy)
          if (std::abs(dx) == 3 || std::abs(dy) == 3) put(x + dx, y + dy, colour);
    }
  return pano;
}

nlohmann::json DatasetJson(const DatagenOptions& o, const sim::RenderOptions& render, const core::RangeBearingGrid& g) {
  nlohmann::json j;
  j["format"] = "toponav-vertex-dataset-1";
  j["grid"] = {{"rows", g.rows},
               {"cols", g.cols},
               {"max_range", g.max_range},
               {"row_range", "row k holds ranges nearest (k + 1) * max_range / rows"},
               {"col_bearing", "column j looks along bearing -pi + 2 pi j / cols, counter-clockwise from the heading"}};
  j["labels_png"] =
      "one byte per cell, row-major (rows = range bins): 0 no vertex, 1 right gap, 2 corner, 3 left gap, 4 point";
  j["image"] = {{"width", render.width},
                {"height", render.height},
                {"vertical_fov_deg", render.vertical_fov_deg},
                {"columns", "column j looks along bearing -pi + 2 pi j / width"}};
  j["worlds"] = sim::DatagenJson(o);
  return j;
}

}  // namespace

ExportWriter::ExportWriter(std::string out_dir, const std::string& index_header) : out_dir_(std::move(out_dir)) {
  fs::create_directories(out_dir_);
  index_ << index_header << "\n";
}

void ExportWriter::AddPicture(core::Panorama picture, std::string caption) {
  sheet_.push_back(std::move(picture));
  captions_.push_back(std::move(caption));
}

ExportSummary ExportWriter::Finish() {
  WriteTextFile((fs::path(out_dir_) / "index.csv").string(), index_.str());
  if (!sheet_.empty()) WriteContactSheet(sheet_, captions_, (fs::path(out_dir_) / "contact_sheet.png").string());
  summary_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return summary_;
}

ExportSummary ExportDataset(const DatagenOptions& o, const sim::WorldOptions& worlds, const sim::RenderOptions& render,
                            const core::RangeBearingGrid& grid, const std::string& out_dir, int max_samples) {
  o.Validate();
  ExportWriter writer(out_dir, "sample,split,kind,world_seed,index,x,y,yaw,vertices,image,labels");
  WriteTextFile((fs::path(out_dir) / "dataset.json").string(), DatasetJson(o, render, grid).dump(1) + "\n");
  for (const Split split : {Split::kTrain, Split::kVal}) {
    const fs::path dir = fs::path(out_dir) / ToString(split);
    fs::create_directories(dir);
    std::vector<SampleId> ids = ListSamples(o, split);
    if (max_samples > 0 && int(ids.size()) > max_samples) ids.resize(size_t(max_samples));
    std::unique_ptr<WorldSampler> sampler;
    SampleId world{};
    for (size_t k = 0; k < ids.size(); ++k) {
      const SampleId& id = ids[k];
      if (!sampler || id.kind != world.kind || id.world_seed != world.world_seed) {
        sampler = std::make_unique<WorldSampler>(id.kind, id.world_seed, worlds, render, grid, o);
        world = id;
      }
      const Sample s = sampler->Make(id);
      char name[32];
      std::snprintf(name, sizeof name, "%06zu", k);
      const std::string image = (fs::path(ToString(split)) / (std::string(name) + ".png")).string();
      const std::string labels = (fs::path(ToString(split)) / (std::string(name) + "_labels.png")).string();
      WritePanoramaPng(s.image, (fs::path(out_dir) / image).string());
      WriteGreyPng(s.labels.cells, grid.cols, grid.rows, (fs::path(out_dir) / labels).string());
      writer.index() << ToString(split) << "/" << name << "," << ToString(split) << "," << core::ToString(id.kind)
                     << "," << id.world_seed << "," << id.index << "," << s.pose.x << "," << s.pose.y << ","
                     << s.pose.yaw << "," << s.labels.num_vertices() << "," << image << "," << labels << "\n";
      if (writer.WantsPicture() && id.index == 0)
        writer.AddPicture(WithLabels(s.image, s.labels), std::string(ToString(split)) + " " + core::ToString(id.kind) +
                                                             " seed " + std::to_string(id.world_seed) + ": " +
                                                             std::to_string(s.labels.num_vertices()) + " vertices");
      writer.CountSample();
    }
  }
  return writer.Finish();
}

}  // namespace toponav::experiments

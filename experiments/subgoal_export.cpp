#include "experiments/subgoal_export.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "experiments/draw.h"
#include "experiments/results_io.h"
#include "experiments/subgoal_data.h"

namespace toponav::experiments {

namespace fs = std::filesystem;

namespace {

// The frontier cells drawn on a copy of the panorama: a box per cell at a height that grows with range (near:
// top), green where the frontier leads to the goal, red where it does not; the goal's bearing a white line.
core::Panorama WithFrontiers(core::Panorama pano, const SubgoalExample& e) {
  const auto put = [&](int x, int y, uint8_t r, uint8_t g, uint8_t b) {
    if (y < 0 || y >= pano.height) return;
    const size_t i = 3 * (size_t(y) * size_t(pano.width) + size_t((x % pano.width + pano.width) % pano.width));
    pano.rgb[i] = r;
    pano.rgb[i + 1] = g;
    pano.rgb[i + 2] = b;
  };
  const core::RangeBearingGrid& g = e.subgoal.grid;
  for (int row = 0; row < g.rows; ++row)
    for (int col = 0; col < g.cols; ++col) {
      const size_t i = g.Index(row, col);
      if (!e.subgoal.mask[i]) continue;
      const bool leads = e.subgoal.ps[i] > 0.5f;
      const int x = int(std::lround(double(col) * pano.width / g.cols)), y = int((row + 0.5) * pano.height / g.rows);
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) put(x + dx, y + dy, leads ? 0 : 255, leads ? 230 : 0, 0);
    }
  const double bearing = std::atan2(e.goal.y, e.goal.x);
  const int goal_x = int(std::lround((bearing + M_PI) / (2 * M_PI) * pano.width));
  for (int y = 0; y < pano.height; y += 2) put(goal_x, y, 255, 255, 255);
  return pano;
}

nlohmann::json SubgoalDatasetJson(const Config& c) {
  const SubgoalDataOptions& o = c.subgoal_data;
  nlohmann::json j;
  j["format"] = "toponav-subgoal-dataset-1";
  j["mazes"] = {{"kind", core::ToString(o.kind)},
                {"train_seeds", {o.train_first_seed, o.train_first_seed + o.train_num_seeds - 1}},
                {"val_seeds", {o.val_first_seed, o.val_first_seed + o.val_num_seeds - 1}},
                {"every", o.every},
                {"runs", "one run through each world (its seed the world's): " + SubgoalRunsText(o) +
                             "; a sample every 'every' steps"}};
  j["vertex_grid"] = {{"rows", 32}, {"cols", 128}, {"max_range", 100.0}};
  j["subgoal_grid"] = {
      {"rows", 64},
      {"cols", 256},
      {"max_range", 100.0},
      {"row_range", "row k holds ranges nearest (k + 1) * max_range / rows"},
      {"col_bearing", "column j looks along bearing -pi + 2 pi j / cols, counter-clockwise from the heading"}};
  j["subgoal_csv"] =
      "the frontier cells the pose sees: row, col, ps (1: the goal is reachable through the frontier), "
      "delta_success (cost beyond the optimistic distance if it is), exploration (cost of exploring it if not)";
  j["goal"] = "goal_x, goal_y in index.csv: the goal in the agent's frame (x along the heading, y to its left)";
  return j;
}

std::string SubgoalCsv(const core::SubgoalLabelGrid& s) {
  std::ostringstream out;
  out << "row,col,ps,delta_success,exploration\n";
  for (int row = 0; row < s.grid.rows; ++row)
    for (int col = 0; col < s.grid.cols; ++col) {
      const size_t i = s.grid.Index(row, col);
      if (s.mask[i])
        out << row << "," << col << "," << s.ps[i] << "," << s.delta_success[i] << "," << s.exploration[i] << "\n";
    }
  return out.str();
}

}  // namespace

ExportSummary ExportSubgoalDataset(const Config& config, const std::string& out_dir, int max_samples) {
  ExportWriter writer(
      out_dir, "sample,split,world_seed,step,x,y,yaw,goal_x,goal_y,vertices,frontier_cells,image,labels,subgoal");
  WriteTextFile((fs::path(out_dir) / "subgoal_dataset.json").string(), SubgoalDatasetJson(config).dump(1) + "\n");
  for (const Split split : {Split::kTrain, Split::kVal}) {
    const std::string name = ToString(split);
    fs::create_directories(fs::path(out_dir) / name);
    std::vector<SubgoalExample> examples = MakeSubgoalExamples(config, split);
    if (max_samples > 0 && int(examples.size()) > max_samples) examples.resize(size_t(max_samples));
    for (size_t k = 0; k < examples.size(); ++k) {
      const SubgoalExample& e = examples[k];
      char stem[32];
      std::snprintf(stem, sizeof stem, "%06zu", k);
      const std::string base = name + "/" + stem;
      WritePanoramaPng(e.image, (fs::path(out_dir) / (base + ".png")).string());
      WriteGreyPng(e.labels.cells, e.labels.grid.cols, e.labels.grid.rows,
                   (fs::path(out_dir) / (base + "_labels.png")).string());
      WriteTextFile((fs::path(out_dir) / (base + "_subgoal.csv")).string(), SubgoalCsv(e.subgoal));
      size_t cells = 0;
      for (uint8_t m : e.subgoal.mask) cells += m;
      writer.index() << base << "," << name << "," << e.world_seed << "," << e.step << "," << e.pose.x << ","
                     << e.pose.y << "," << e.pose.yaw << "," << e.goal.x << "," << e.goal.y << ","
                     << e.labels.num_vertices() << "," << cells << "," << base << ".png," << base << "_labels.png,"
                     << base << "_subgoal.csv\n";
      if (writer.WantsPicture() && k % 7 == 0)
        writer.AddPicture(WithFrontiers(e.image, e), name + " maze " + std::to_string(e.world_seed) + " step " +
                                                         std::to_string(e.step) + ": " + std::to_string(cells) +
                                                         " frontier cells (green: leads to the goal)");
      writer.CountSample();
    }
  }
  return writer.Finish();
}

}  // namespace toponav::experiments

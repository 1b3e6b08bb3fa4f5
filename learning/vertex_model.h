#pragma once
// The learned vertex sensor's network (paper Sec. III-A; vertexnav.md §4.2, §4.4) behind a small header: a
// fully-convolutional encoder-decoder from a 128x512 RGB panorama to the 32x128 range-bearing grid, with a
// vertex logit and 4 label logits per cell.  Bearing is circular, so convolutions pad circularly along the
// image's width.  LibTorch stays inside learning/*.cpp.
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry.h"
#include "core/image.h"
#include "core/range_bearing_grid.h"
#include "core/subgoal_labels.h"
#include "sim/vertex_labels.h"

namespace toponav::learning {

struct VertexNetOptions {
  double width = 1.0;  // channel multiplier: 1.0 is the paper's [64,64,128,128,256] / [128,64,64]; 0.25 a CPU-sized net
  // The LSP extension (paper Sec. V): the goal as input, and one more decoder block to a 64x256 grid of
  // subgoal outputs (Ps, success cost, exploration cost); its loss (lsp.md §2.7) adds masked means over the
  // frontier cells: the Ps cross-entropy, and the squared cost errors scaled by 1/100^2 and 1/200^2.
  bool subgoal = false;
  // Loss (vertexnav.md §4.4): weighted BCE on the vertex logit (positives count positive_weight times), times
  // vertex_weight, plus the label cross-entropy over vertex cells.
  double positive_weight = 8.0;
  double vertex_weight = 500.0;
  bool operator==(const VertexNetOptions& o) const {
    return width == o.width && positive_weight == o.positive_weight && vertex_weight == o.vertex_weight &&
           subgoal == o.subgoal;
  }
};

// The network's output for one panorama: per cell, the vertex probability and the 4 label probabilities
// [right gap, corner, left gap, point] (row-major, rows = range bins).
struct GridOutput {
  core::RangeBearingGrid grid;
  std::vector<float> vertex;  // grid.size()
  std::vector<float> labels;  // 4 * grid.size()
};

// The subgoal network's output for one panorama and goal, on its 64x256 grid: per cell the probability that
// a frontier there leads to the goal, and the success and exploration costs.
struct SubgoalOutput {
  core::RangeBearingGrid grid = core::kSubgoalGrid;
  std::vector<float> ps, delta_success, exploration;
};

// Where the goal is, seen from the panorama's pose (radians counter-clockwise from the heading).
struct GoalInView {
  double range = 0.0, bearing = 0.0;
  // From the goal's position in the agent's frame (x along the heading, y to its left): training and the
  // sensor derive it the same way.
  static GoalInView FromAgentFrame(const core::Vec2& g) { return {core::Norm(g), std::atan2(g.y, g.x)}; }
};

// One training example (subgoal models also need 'goal' and 'subgoal', labels on their 64x256 grid).
struct LabelledImage {
  const core::Panorama* image = nullptr;
  const sim::VertexLabelGrid* labels = nullptr;
  GoalInView goal;
  const core::SubgoalLabelGrid* subgoal = nullptr;
};

class VertexModel {
 public:
  // A freshly initialised network (weights from 'seed'); on the CPU unless 'device' is "cuda:0".
  VertexModel(const VertexNetOptions& options, uint64_t seed, const std::string& device = "cpu");
  ~VertexModel();
  VertexModel(VertexModel&&) noexcept;
  VertexModel& operator=(VertexModel&&) noexcept;

  // Inference on 128x512 panoramas (throws core::DataError for another size).
  GridOutput Predict(const core::Panorama& image) const;
  // A subgoal model's inference: the vertex grid and the subgoal grid for the goal (core::InternalError for a
  // model without the extension; Predict gives its vertex grid for a goal straight ahead at range 0).
  std::pair<GridOutput, SubgoalOutput> PredictWithGoal(const core::Panorama& image, const GoalInView& goal) const;
  // The loss on a batch, without training.
  double Loss(const std::vector<LabelledImage>& batch) const;
  // One Adam step on a batch (learning rate 'lr'); returns the batch's loss before the step.
  double TrainStep(const std::vector<LabelledImage>& batch, double lr);

  // Copies the weights of 'source' (another width-compatible model, with or without the extension) where a
  // tensor of the same role has the same shape; the third encoder block's first convolution of a subgoal
  // model takes a vertex model's weights for its image channels (its goal channels keep theirs).  All or
  // nothing: returns the number of tensors copied, 0 (and nothing copied) if a shared tensor does not fit.
  int InitFrom(const VertexModel& source);

  // Saves weights and metadata (format, options, free-form 'notes' such as the training data and metrics).
  void Save(const std::string& path, const std::string& notes = "") const;
  // Loads a model saved by Save.  A missing, truncated or foreign file, or one whose weights do not fit its
  // declared architecture, is a core::DataError naming the file.
  static VertexModel Load(const std::string& path, const std::string& device = "cpu");

  const VertexNetOptions& options() const;
  const std::string& notes() const;  // as saved
  int64_t num_parameters() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::learning

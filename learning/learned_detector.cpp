#include "learning/learned_detector.h"

#include <cmath>
#include <optional>

#include "core/error.h"
#include "learning/vertex_model.h"

namespace toponav::learning {

namespace {

// The subgoal outputs as the observation's cell grid (channels "ps" a probability, "delta_success",
// "exploration").
core::CellGrid SubgoalCells(const SubgoalOutput& s) {
  core::CellGrid c;
  c.rows = s.grid.rows;
  c.cols = s.grid.cols;
  c.max_range = s.grid.max_range;
  c.channels = {"ps", "delta_success", "exploration"};
  c.values.resize(s.ps.size() * 3);
  for (size_t i = 0; i < s.ps.size(); ++i) {
    c.values[3 * i] = s.ps[i];
    c.values[3 * i + 1] = s.delta_success[i];
    c.values[3 * i + 2] = s.exploration[i];
  }
  return c;
}

class LearnedDetector : public core::VertexDetectorInterface {
 public:
  LearnedDetector(VertexModel model, const DecodeOptions& decode, std::optional<VertexModel> subgoal)
      : model_(std::move(model)), decode_(decode), subgoal_(std::move(subgoal)) {}

  core::Observation Detect(const core::Panorama& image, const core::DetectionContext& context) override {
    core::Observation z;
    z.pose = context.pose;
    z.agent = context.agent;
    if (subgoal_ && context.goal) {
      const GridOutput out = model_.Predict(image);
      z.detections = DecodeDetections(out.vertex, out.labels, out.grid, decode_);
      z.cells = SubgoalCells(subgoal_->PredictWithGoal(image, GoalInView::FromAgentFrame(*context.goal)).second);
      return z;
    }
    if (!model_.options().subgoal || !context.goal) {
      const GridOutput out = model_.Predict(image);
      z.detections = DecodeDetections(out.vertex, out.labels, out.grid, decode_);
      return z;
    }
    const auto [out, subgoal] = model_.PredictWithGoal(image, GoalInView::FromAgentFrame(*context.goal));
    z.detections = DecodeDetections(out.vertex, out.labels, out.grid, decode_);
    z.cells = SubgoalCells(subgoal);
    return z;
  }

 private:
  VertexModel model_;
  DecodeOptions decode_;
  std::optional<VertexModel> subgoal_;
};

}  // namespace

std::unique_ptr<core::VertexDetectorInterface> CreateLearnedDetector(const std::string& model_path,
                                                                     const DecodeOptions& decode,
                                                                     const std::string& subgoal_path) {
  std::optional<VertexModel> subgoal;
  if (!subgoal_path.empty()) {
    subgoal = VertexModel::Load(subgoal_path);
    if (!subgoal->options().subgoal)
      throw core::DataError(subgoal_path, "sensor.subgoal_model is a vertex network without subgoal outputs "
                                          "(not trained with train.subgoal)");
  }
  return std::make_unique<LearnedDetector>(VertexModel::Load(model_path), decode, std::move(subgoal));
}

}  // namespace toponav::learning

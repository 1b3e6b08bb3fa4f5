#include "learning/learned_detector.h"

#include <cmath>
#include <optional>

#include "core/error.h"
#include "learning/mirror_average.h"
#include "learning/vertex_model.h"

namespace toponav::learning {

namespace {

// The subgoal outputs as the observation's typed cells.
core::SubgoalCells SubgoalCells(const SubgoalOutput& s) {
  core::SubgoalCells c;
  c.rows = s.grid.rows;
  c.cols = s.grid.cols;
  c.max_range = s.grid.max_range;
  c.values.resize(s.ps.size());
  for (size_t i = 0; i < s.ps.size(); ++i) c.values[i] = {s.ps[i], s.delta_success[i], s.exploration[i]};
  return c;
}

class LearnedDetector : public core::VertexDetectorInterface {
 public:
  LearnedDetector(VertexModel model, const DecodeOptions& decode, std::optional<VertexModel> subgoal, bool mirror)
      : model_(std::move(model)), decode_(decode), subgoal_(std::move(subgoal)), mirror_(mirror) {}

  core::Observation Detect(const core::Panorama& image, const core::DetectionContext& context) override {
    core::Observation z;
    z.pose = context.pose;
    z.agent = context.agent;
    std::optional<core::Panorama> mirrored;
    if (mirror_) mirrored = MirroredPanorama(image);
    const bool own_cells = model_.options().subgoal && context.goal && !subgoal_;
    if (own_cells) {
      auto [out, cells] = PredictWithGoal(model_, image, mirrored, *context.goal);
      z.detections = DecodeDetections(out.vertex, out.labels, out.grid, decode_);
      z.subgoal = SubgoalCells(cells);
      return z;
    }
    GridOutput out = model_.Predict(image);
    if (mirrored) out = Mean(out, MirroredBack(model_.Predict(*mirrored)));
    z.detections = DecodeDetections(out.vertex, out.labels, out.grid, decode_);
    if (subgoal_ && context.goal)
      z.subgoal = SubgoalCells(PredictWithGoal(*subgoal_, image, mirrored, *context.goal).second);
    return z;
  }

 private:
  static std::pair<GridOutput, SubgoalOutput> PredictWithGoal(const VertexModel& m, const core::Panorama& image,
                                                              const std::optional<core::Panorama>& mirrored,
                                                              const core::Vec2& goal) {
    const GoalInView g = GoalInView::FromAgentFrame(goal);
    auto out = m.PredictWithGoal(image, g);
    if (!mirrored) return out;
    const auto back = m.PredictWithGoal(*mirrored, {g.range, -g.bearing});
    return {Mean(out.first, MirroredBack(back.first)), Mean(out.second, MirroredBack(back.second))};
  }

  VertexModel model_;
  DecodeOptions decode_;
  std::optional<VertexModel> subgoal_;
  bool mirror_;
};

}  // namespace

std::unique_ptr<core::VertexDetectorInterface> CreateLearnedDetector(const std::string& model_path,
                                                                     const DecodeOptions& decode,
                                                                     const std::string& subgoal_path, bool mirror) {
  std::optional<VertexModel> subgoal;
  if (!subgoal_path.empty()) {
    subgoal = VertexModel::Load(subgoal_path);
    if (!subgoal->options().subgoal)
      throw core::DataError(subgoal_path, "sensor.subgoal_model is a vertex network without subgoal outputs "
                                          "(not trained with train.subgoal)");
  }
  return std::make_unique<LearnedDetector>(VertexModel::Load(model_path), decode, std::move(subgoal), mirror);
}

}  // namespace toponav::learning

#include "learning/learned_detector.h"

#include "learning/vertex_model.h"

namespace toponav::learning {

namespace {

class LearnedDetector : public core::VertexDetectorInterface {
 public:
  LearnedDetector(VertexModel model, const DecodeOptions& decode) : model_(std::move(model)), decode_(decode) {}

  core::Observation Detect(const core::Panorama& image, const core::DetectionContext& context) override {
    const GridOutput out = model_.Predict(image);
    core::Observation z;
    z.pose = context.pose;
    z.agent = context.agent;
    z.detections = DecodeDetections(out.vertex, out.labels, out.grid, decode_);
    return z;
  }

 private:
  VertexModel model_;
  DecodeOptions decode_;
};

}  // namespace

std::unique_ptr<core::VertexDetectorInterface> CreateLearnedDetector(const std::string& model_path,
                                                                     const DecodeOptions& decode) {
  return std::make_unique<LearnedDetector>(VertexModel::Load(model_path), decode);
}

}  // namespace toponav::learning

#include "sim/rendering_sensor.h"

#include "core/error.h"

namespace toponav::sim {

namespace {

class RenderingSensor : public core::VertexSensorInterface {
 public:
  RenderingSensor(const core::World& world, const RenderOptions& render,
                  std::unique_ptr<core::VertexDetectorInterface> detector, std::optional<core::Vec2> goal,
                  bool goal_at_agent)
      : renderer_(world, render), detector_(std::move(detector)), goal_(goal), goal_at_agent_(goal_at_agent) {
    TOPONAV_CHECK(detector_ != nullptr, "a rendering sensor needs a detector");
  }

  core::Observation Observe(const core::Pose2& pose, int agent) override {
    core::DetectionContext context{pose, agent, std::nullopt};
    if (goal_) context.goal = core::GoalInAgentFrame(pose, *goal_);
    if (goal_at_agent_) context.goal = core::Vec2{0, 0};
    core::Observation z = detector_->Detect(renderer_.Render(pose), context);
    z.pose = pose;
    z.agent = agent;
    return z;
  }

 private:
  Renderer renderer_;
  std::unique_ptr<core::VertexDetectorInterface> detector_;
  std::optional<core::Vec2> goal_;
  bool goal_at_agent_ = false;
};

}  // namespace

std::unique_ptr<core::VertexSensorInterface> CreateRenderingSensor(
    const core::World& world, const RenderOptions& render, std::unique_ptr<core::VertexDetectorInterface> detector,
    std::optional<core::Vec2> goal, bool goal_at_agent) {
  return std::make_unique<RenderingSensor>(world, render, std::move(detector), goal, goal_at_agent);
}

}  // namespace toponav::sim

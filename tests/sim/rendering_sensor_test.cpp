#include "sim/rendering_sensor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/testing/worlds.h"

namespace toponav::sim {
namespace {

// Records what it was given and reports one detection per call at the image's width as range.
class RecordingDetector : public core::VertexDetectorInterface {
 public:
  struct Seen {
    int width = 0, height = 0;
    size_t pixels = 0;
    core::DetectionContext context;
  };
  explicit RecordingDetector(std::vector<Seen>* seen) : seen_(seen) {}
  core::Observation Detect(const core::Panorama& image, const core::DetectionContext& context) override {
    seen_->push_back({image.width, image.height, image.rgb.size(), context});
    core::Observation z;
    z.pose = {-1, -1, -1};  // the sensor stamps the pose it was asked for
    z.detections.push_back({double(image.width), 0.0, {1, 0, 0.01}, {0, 1, 0, 0}});
    return z;
  }

 private:
  std::vector<Seen>* seen_;
};

TEST(RenderingSensor, RendersThePanoramaAtThePoseAndPassesTheGoalInTheAgentsFrame) {
  const core::World w = testing::RoomWorld(40, 30);
  std::vector<RecordingDetector::Seen> seen;
  RenderOptions render;
  render.width = 64;
  render.height = 16;
  auto sensor = CreateRenderingSensor(w, render, std::make_unique<RecordingDetector>(&seen), core::Vec2{30, 15});
  const core::Pose2 pose{20, 15, core::kPi / 2};  // facing +y: the goal 10 to the east is on the agent's right
  const core::Observation z = sensor->Observe(pose, 2);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].width, 64);
  EXPECT_EQ(seen[0].height, 16);
  EXPECT_EQ(seen[0].pixels, size_t(3 * 64 * 16));
  EXPECT_EQ(seen[0].context.agent, 2);
  ASSERT_TRUE(seen[0].context.goal);
  EXPECT_NEAR(seen[0].context.goal->x, 0.0, 1e-9);
  EXPECT_NEAR(seen[0].context.goal->y, -10.0, 1e-9);
  EXPECT_EQ(z.pose.x, 20.0);
  EXPECT_EQ(z.pose.yaw, pose.yaw);
  EXPECT_EQ(z.agent, 2);
  ASSERT_EQ(z.detections.size(), 1u);
  EXPECT_EQ(z.detections[0].range, 64.0);
  auto no_goal = CreateRenderingSensor(w, render, std::make_unique<RecordingDetector>(&seen));
  no_goal->Observe(pose, 0);
  EXPECT_FALSE(seen.back().context.goal);
  // A search's subgoal network is told the goal is where the agent stands, wherever that is.
  auto at_agent = CreateRenderingSensor(w, render, std::make_unique<RecordingDetector>(&seen), std::nullopt, true);
  at_agent->Observe({12, 9, 1.0}, 0);
  ASSERT_TRUE(seen.back().context.goal);
  EXPECT_EQ(seen.back().context.goal->x, 0.0);
  EXPECT_EQ(seen.back().context.goal->y, 0.0);
}

TEST(GoalInAgentFrame, IsTheGoalRotatedIntoTheAgentsHeading) {
  const core::Vec2 g = core::GoalInAgentFrame({1, 1, core::kPi}, {-2, 1});  // 3 behind the origin along -x
  EXPECT_NEAR(g.x, 3.0, 1e-12);
  EXPECT_NEAR(g.y, 0.0, 1e-12);
}

}  // namespace
}  // namespace toponav::sim

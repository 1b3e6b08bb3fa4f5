#include "experiments/recorded.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "experiments/config.h"
#include "experiments/map_drive.h"
#include "experiments/sensor_factory.h"
#include "sim/paths.h"
#include "sim/raycast.h"
#include "sim/render.h"
#include "sim/worlds.h"

namespace toponav::experiments {
namespace {

namespace fs = std::filesystem;

std::string TempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("toponav_rec_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

void WriteFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string ErrorOf(const std::string& dir) {
  try {
    ReadRecording(dir);
  } catch (const core::DataError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Recording, ABadPosesFileIsAnErrorNamingTheFileAndLine) {
  const std::string d = TempDir("bad");
  EXPECT_NE(ErrorOf(d).find("poses.csv"), std::string::npos) << "missing file";
  WriteFile(d + "/poses.csv", "img,x,y,yaw\n");
  EXPECT_NE(ErrorOf(d).find("header"), std::string::npos);
  WriteFile(d + "/poses.csv", "image,x,y,yaw\n");
  EXPECT_NE(ErrorOf(d).find("no frames"), std::string::npos);
  WriteFile(d + "/poses.csv", "image,x,y,yaw\na.png,1,2,0\nb.png,1,nan,0\n");
  EXPECT_NE(ErrorOf(d).find("line 3: y 'nan'"), std::string::npos) << ErrorOf(d);
  WriteFile(d + "/poses.csv", "image,x,y,yaw\na.png,1,2\n");
  EXPECT_NE(ErrorOf(d).find("line 2"), std::string::npos);
  WriteFile(d + "/poses.csv", "image,x,y,yaw\r\na.png,1,2.5,-0.5\r\n");
  const Recording r = ReadRecording(d);
  ASSERT_EQ(r.frames.size(), 1u);
  EXPECT_EQ(r.frames[0].pose.y, 2.5);
  EXPECT_EQ(r.frames[0].pose.yaw, -0.5);
  EXPECT_EQ(r.ImagePath(0), (fs::path(d) / "a.png").string());
  fs::remove_all(d);
}

TEST(Recording, WrittenPanoramasReadBackExactlyWithTheirPoses) {
  const core::World w = sim::GenerateLabyrinth({}, 4);
  const sim::Renderer renderer(w, {});
  const std::vector<core::Pose2> poses{w.start, core::Pose2{w.start.x, w.start.y, 1.25}};
  std::vector<core::Panorama> panos;
  for (const auto& p : poses) panos.push_back(renderer.Render(p));
  const std::string d = TempDir("rt");
  WriteRecording(d, poses, panos);
  const Recording r = ReadRecording(d);
  ASSERT_EQ(r.frames.size(), 2u);
  EXPECT_EQ(r.frames[1].pose.yaw, 1.25);
  EXPECT_EQ(r.frames[0].pose.x, w.start.x) << "poses are written with full precision";
  const core::Panorama back = ReadPanorama(r.ImagePath(1));
  EXPECT_EQ(back.width, panos[1].width);
  EXPECT_EQ(back.height, panos[1].height);
  EXPECT_EQ(back.rgb, panos[1].rgb);
  EXPECT_THROW(ReadPanorama(d + "/poses.csv"), core::DataError);
  fs::remove_all(d);
}

// A detector that reports the ground truth at the pose it is told (a test stand-in for the network), and
// counts the images it was given.
class GroundTruthDetector : public core::VertexDetectorInterface {
 public:
  GroundTruthDetector(const core::World& w, int* images) : caster_(w), images_(images) {}
  core::Observation Detect(const core::Panorama& image, const core::DetectionContext& c) override {
    EXPECT_EQ(image.width, 512);
    ++*images_;
    core::Observation z;
    z.pose = c.pose;
    for (const auto& v : caster_.VisibleVertices(c.pose, 100.0)) {
      core::Detection d;
      d.range = v.range;
      d.bearing = v.bearing;
      d.polar = {1.0, 0.0, 0.003};
      d.labels = core::OneHot(v.label);
      z.detections.push_back(d);
    }
    std::sort(z.detections.begin(), z.detections.end(), [](auto& a, auto& b) { return a.bearing < b.bearing; });
    return z;
  }

 private:
  sim::RayCaster caster_;
  int* images_;
};

TEST(Recording, TheRecordedSensorReplaysItsFramesAndTheMapIsBuiltFromThem) {
  const core::World w = sim::GenerateLabyrinth({}, 6);
  const auto path = sim::FreePath(w, w.start.position(), w.goal, 2.0);
  const auto poses = sim::PosesAlong(path, 30);
  const sim::Renderer renderer(w, {});
  std::vector<core::Panorama> panos;
  for (const auto& p : poses) panos.push_back(renderer.Render(p));
  const std::string d = TempDir("map");
  WriteRecording(d, poses, panos);
  int images = 0;
  auto sensor = CreateRecordedSensor(ReadRecording(d), std::make_unique<GroundTruthDetector>(w, &images));
  EXPECT_THROW(sensor->Observe(core::Pose2{1e4, 1e4, 0}, 0), core::DataError) << "a pose the recording does not hold";
  const Config config;
  const RecordedMapResult r = BuildRecordedMap(ReadRecording(d), *sensor, config.mapping, {});
  EXPECT_EQ(r.frames, 30);
  EXPECT_EQ(images, 30);
  EXPECT_EQ(r.path.size(), 30u);
  EXPECT_GT(r.view.vertices.size(), 6u);
  EXPECT_GT(r.view.walls.size(), 4u);
  EXPECT_GT(KnownSpaceIoU(w, r.view), 0.2) << "the known space along the way to the goal";
  fs::remove_all(d);
}

TEST(Recording, TheRecordedKindNeedsItsFolderAndAModel) {
  SensorConfig c;
  c.kind = SensorKind::kRecorded;
  c.learned.model = "m.pt";
  try {
    c.Validate();
    ADD_FAILURE() << "no error";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "sensor.images");
  }
  const Config parsed =
      ParseConfig("sensor:\n  kind: recorded\n  model: m.pt\n  images: rec\n  poses: rec/p.csv\n", "x.yaml");
  EXPECT_EQ(parsed.sensor.images, "rec");
  EXPECT_EQ(parsed.sensor.poses, "rec/p.csv");
}

}  // namespace
}  // namespace toponav::experiments

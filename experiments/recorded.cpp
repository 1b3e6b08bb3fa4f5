#include "experiments/recorded.h"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "core/error.h"
#include "core/rng.h"
#include "experiments/draw.h"
#include "experiments/results_io.h"

namespace toponav::experiments {

namespace fs = std::filesystem;

namespace {

double ParseNumber(const std::string& text, const std::string& file, int line, const char* column) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(v))
    throw core::DataError(file, fmt::format("line {}: {} '{}' is not a finite number", line, column, text));
  return v;
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

}  // namespace

std::string Recording::ImagePath(size_t i) const { return (fs::path(dir) / frames.at(i).image).string(); }

Recording ReadRecording(const std::string& dir, const std::string& poses_csv) {
  Recording rec;
  rec.dir = dir;
  const std::string file = poses_csv.empty() ? (fs::path(dir) / "poses.csv").string() : poses_csv;
  std::ifstream in(file);
  if (!in) throw core::DataError(file, "cannot open the poses file (a recording needs image,x,y,yaw rows)");
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto f = SplitCsv(line);
    if (rec.frames.empty() && n == 1) {
      if (f != std::vector<std::string>{"image", "x", "y", "yaw"})
        throw core::DataError(file, "line 1: expected the header 'image,x,y,yaw', got '" + line + "'");
      continue;
    }
    if (f.size() != 4 || f[0].empty())
      throw core::DataError(file, fmt::format("line {}: expected image,x,y,yaw, got '{}'", n, line));
    rec.frames.push_back({f[0], core::Pose2{ParseNumber(f[1], file, n, "x"), ParseNumber(f[2], file, n, "y"),
                                            ParseNumber(f[3], file, n, "yaw")}});
  }
  if (n == 0) throw core::DataError(file, "empty file: expected the header 'image,x,y,yaw'");
  if (rec.frames.empty()) throw core::DataError(file, "no frames: a recording needs at least one image,x,y,yaw row");
  return rec;
}

void WriteRecording(const std::string& dir, const std::vector<core::Pose2>& poses,
                    const std::vector<core::Panorama>& panoramas) {
  TOPONAV_CHECK(poses.size() == panoramas.size(), poses.size() << " poses for " << panoramas.size() << " panoramas");
  std::string csv = "image,x,y,yaw\n";
  for (size_t i = 0; i < poses.size(); ++i) {
    const std::string name = fmt::format("pano_{:05d}.png", i);
    WritePanoramaPng(panoramas[i], (fs::path(dir) / name).string());
    csv += fmt::format("{},{:.17g},{:.17g},{:.17g}\n", name, poses[i].x, poses[i].y, poses[i].yaw);
  }
  WriteTextFile((fs::path(dir) / "poses.csv").string(), csv);
}

core::Panorama ReadPanorama(const std::string& path) {
  cv::Mat bgr;
  try {
    bgr = cv::imread(path, cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    throw core::DataError(path, std::string("cannot read the image: ") + e.what());
  }
  if (bgr.empty()) throw core::DataError(path, "cannot read the image (missing, or not a PNG/JPEG file)");
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  core::Panorama p;
  p.width = rgb.cols;
  p.height = rgb.rows;
  p.rgb.resize(size_t(p.width) * size_t(p.height) * 3);
  for (int r = 0; r < p.height; ++r)
    std::copy(rgb.ptr<uint8_t>(r), rgb.ptr<uint8_t>(r) + 3 * p.width, p.rgb.data() + 3 * size_t(r) * p.width);
  return p;
}

namespace {

bool SamePose(const core::Pose2& a, const core::Pose2& b) {
  return std::abs(a.x - b.x) < 1e-6 && std::abs(a.y - b.y) < 1e-6 && std::abs(a.yaw - b.yaw) < 1e-6;
}

class RecordedSensor : public core::VertexSensorInterface {
 public:
  RecordedSensor(Recording rec, std::unique_ptr<core::VertexDetectorInterface> detector)
      : rec_(std::move(rec)), detector_(std::move(detector)) {}

  core::Observation Observe(const core::Pose2& pose, int agent) override {
    const size_t n = rec_.frames.size();
    for (size_t k = 0; k < n; ++k) {
      const size_t i = (next_ + k) % n;
      if (!SamePose(rec_.frames[i].pose, pose)) continue;
      next_ = i + 1;
      const std::string path = rec_.ImagePath(i);
      try {
        return detector_->Detect(ReadPanorama(path), core::DetectionContext{pose, agent, std::nullopt});
      } catch (const core::DataError& e) {
        throw core::DataError(path, e.what());
      }
    }
    throw core::DataError(rec_.dir, fmt::format("the recording holds no panorama at pose {:.6g},{:.6g},{:.6g}", pose.x,
                                                pose.y, pose.yaw));
  }

 private:
  Recording rec_;
  std::unique_ptr<core::VertexDetectorInterface> detector_;
  size_t next_ = 0;
};

double MsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::unique_ptr<core::VertexSensorInterface> CreateRecordedSensor(
    Recording recording, std::unique_ptr<core::VertexDetectorInterface> detector) {
  TOPONAV_CHECK(detector != nullptr, "a recorded sensor needs a detector");
  return std::make_unique<RecordedSensor>(std::move(recording), std::move(detector));
}

RecordedMapResult BuildRecordedMap(const Recording& recording, core::VertexSensorInterface& sensor,
                                   const mapping::MapperOptions& mapping, const RecordedMapOptions& o) {
  mapping::MapperOptions mo = mapping;
  mo.world_bounds.reset();
  mo.open_region.reset();
  if (o.mcmc_every <= 0) mo.defer_to_mcmc = false;
  mapping::Mapper mapper(mo);
  core::Rng rng(core::DeriveSeed(o.seed, 2));
  RecordedMapResult r;
  double observe_ms = 0, update_ms = 0;
  for (const auto& frame : recording.frames) {
    auto t0 = std::chrono::steady_clock::now();
    const core::Observation ob = sensor.Observe(frame.pose, 0);
    observe_ms += MsSince(t0);
    t0 = std::chrono::steady_clock::now();
    mapper.AddObservation(ob);
    ++r.frames;
    if (o.mcmc_every > 0 && (r.frames % o.mcmc_every == 0 || r.frames == int(recording.frames.size())))
      mapper.SampleMostLikelyMap(rng);
    update_ms += MsSince(t0);
    r.path.push_back(frame.pose.position());
  }
  r.view = mapper.ExactView();
  r.log_posterior = mapper.LogPosterior();
  r.mean_observe_ms = observe_ms / std::max(1, r.frames);
  r.mean_update_ms = update_ms / std::max(1, r.frames);
  return r;
}

}  // namespace toponav::experiments

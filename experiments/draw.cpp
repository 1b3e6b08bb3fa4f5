#include "experiments/draw.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/error.h"
#include "experiments/internal/picture_io.h"

namespace toponav::experiments {

using core::Vec2;

namespace {

void Save(const cv::Mat& image, const std::string& path) { internal::SavePicture(image, path); }

// World -> pixel mapping with a margin; colours are BGR.
class Canvas {
 public:
  Canvas(const core::World& world, const PictureOptions& o) {
    const core::Aabb2& b = world.bounds;
    scale_ = o.pixels_per_unit;
    const double longest = std::max(b.width(), b.height()) + 2 * kMargin;
    if (longest * scale_ > o.max_pixels) scale_ = o.max_pixels / longest;
    origin_ = {b.min.x - kMargin, b.max.y + kMargin};
    image = cv::Mat(int(std::ceil((b.height() + 2 * kMargin) * scale_)),
                    int(std::ceil((b.width() + 2 * kMargin) * scale_)), CV_8UC3, cv::Scalar(70, 70, 70));
  }
  cv::Point Px(const Vec2& p) const {
    return {int(std::lround((p.x - origin_.x) * scale_)), int(std::lround((origin_.y - p.y) * scale_))};
  }
  std::vector<cv::Point> Px(const core::Ring& r) const {
    std::vector<cv::Point> pts;
    for (const auto& p : r) pts.push_back(Px(p));
    return pts;
  }
  int Len(double units) const { return std::max(1, int(std::lround(units * scale_))); }
  void Fill(const core::Ring& r, const cv::Scalar& c) {
    std::vector<std::vector<cv::Point>> polys{Px(r)};
    cv::fillPoly(image, polys, c, cv::LINE_AA);
  }
  void Outline(const core::Ring& r, const cv::Scalar& c, int thickness) {
    std::vector<std::vector<cv::Point>> polys{Px(r)};
    cv::polylines(image, polys, true, c, thickness, cv::LINE_AA);
  }
  void Save(const std::string& path) const { experiments::Save(image, path); }
  cv::Mat image;

 private:
  static constexpr double kMargin = 8.0;
  double scale_ = 1.0;
  Vec2 origin_;
};

const cv::Scalar kWay(235, 190, 0);  // cyan (BGR)
const cv::Scalar kAgentColours[] = {cv::Scalar(220, 90, 20), cv::Scalar(30, 160, 30), cv::Scalar(160, 40, 170)};
const cv::Scalar kFree(250, 250, 250), kWall(20, 20, 20), kObstacle(150, 150, 150), kGuide(60, 190, 60);
const cv::Scalar kBox(40, 90, 160), kCylinder(190, 120, 40), kTree(40, 140, 40), kStart(220, 90, 20),
    kGoal(40, 40, 220), kRegion(235, 245, 235);

void DrawWorld(Canvas& c, const core::World& w) {
  if (w.has_boundary()) {
    c.Fill(w.boundary, kFree);
  } else {
    const auto& b = w.bounds;
    c.Fill({b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}}, kRegion);
    c.Outline({b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}}, cv::Scalar(150, 170, 150), 1);
  }
  if (w.guide_path.size() > 1) {
    std::vector<cv::Point> pts;
    for (const auto& p : w.guide_path) pts.push_back(c.Px(p));
    cv::polylines(c.image, std::vector<std::vector<cv::Point>>{pts}, false, kGuide, c.Len(w.guide_path_width),
                  cv::LINE_AA);
  }
  for (const auto& o : w.obstacles) c.Fill(o, kObstacle);
  for (const auto& o : w.obstacles) c.Outline(o, kWall, 2);
  if (w.has_boundary()) c.Outline(w.boundary, kWall, 2);
  for (const auto& cl : w.clutter) {
    if (cl.shape == core::ClutterShape::kBox) {
      core::Ring r;
      for (const Vec2 k : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}})
        r.push_back(cl.center + core::Rotate(k * cl.size, cl.yaw));
      c.Fill(r, kBox);
    } else if (cl.shape == core::ClutterShape::kTree) {
      cv::circle(c.image, c.Px(cl.center), c.Len(cl.size * 3), cv::Scalar(120, 200, 120), cv::FILLED, cv::LINE_AA);
      cv::circle(c.image, c.Px(cl.center), c.Len(cl.size), kTree, cv::FILLED, cv::LINE_AA);
    } else {
      cv::circle(c.image, c.Px(cl.center), c.Len(cl.size), kCylinder, cv::FILLED, cv::LINE_AA);
    }
  }
}

void DrawAgent(Canvas& c, const core::Pose2& pose, const cv::Scalar& color) {
  const Vec2 p = pose.position();
  const double r = 3.0;
  const core::Ring tri{p + core::Rotate({2 * r, 0}, pose.yaw), p + core::Rotate({-r, r}, pose.yaw),
                       p + core::Rotate({-r, -r}, pose.yaw)};
  c.Fill(tri, color);
}

cv::Mat ToBgr(const sim::Panorama& p) {
  if (p.rgb.empty()) throw core::InternalError("panorama has no colour image");
  cv::Mat rgb(p.height, p.width, CV_8UC3, const_cast<uint8_t*>(p.rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

}  // namespace

void WritePanoramaPng(const sim::Panorama& pano, const std::string& png_path) { Save(ToBgr(pano), png_path); }

void WriteGreyPng(const std::vector<uint8_t>& pixels, int width, int height, const std::string& png_path) {
  TOPONAV_CHECK(pixels.size() == size_t(width) * size_t(height), "grey image of " << pixels.size() << " bytes");
  cv::Mat image(height, width, CV_8UC1);
  std::copy(pixels.begin(), pixels.end(), image.data);
  Save(image, png_path);
}

void WriteDepthPng(const sim::Panorama& pano, double max_depth, const std::string& png_path) {
  if (pano.depth.empty()) throw core::InternalError("panorama has no depth image");
  cv::Mat grey(pano.height, pano.width, CV_8UC1);
  for (int r = 0; r < pano.height; ++r)
    for (int c = 0; c < pano.width; ++c) {
      const double d = pano.depth[size_t(r) * pano.width + c];
      grey.at<uint8_t>(r, c) = uint8_t(std::lround(255.0 * std::clamp(1.0 - d / max_depth, 0.0, 1.0)));
    }
  Save(grey, png_path);
}

void WriteContactSheet(const std::vector<sim::Panorama>& panos, const std::vector<std::string>& captions,
                       const std::string& png_path) {
  if (panos.empty()) throw core::InternalError("contact sheet of no panoramas");
  const int gap = 4, w = panos[0].width;
  int h = 0;
  for (const auto& p : panos) h += p.height + gap;
  cv::Mat sheet(h - gap, w, CV_8UC3, cv::Scalar(255, 255, 255));
  int y = 0;
  for (size_t i = 0; i < panos.size(); ++i) {
    cv::Mat bgr = ToBgr(panos[i]);
    bgr.copyTo(sheet(cv::Rect(0, y, w, panos[i].height)));
    if (i < captions.size()) {
      cv::putText(sheet, captions[i], {6, y + 14}, cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
      cv::putText(sheet, captions[i], {6, y + 14}, cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(255, 255, 255), 1,
                  cv::LINE_AA);
    }
    y += panos[i].height + gap;
  }
  Save(sheet, png_path);
}

void DrawWorldPicture(const core::World& world, const PictureOptions& options, const std::string& png_path) {
  Canvas c(world, options);
  DrawWorld(c, world);
  DrawAgent(c, world.start, kStart);
  cv::circle(c.image, c.Px(world.goal), c.Len(3.0), kGoal, cv::FILLED, cv::LINE_AA);
  cv::circle(c.image, c.Px(world.goal), c.Len(3.0), kWall, 1, cv::LINE_AA);
  c.Save(png_path);
}

void PaintMap(Canvas& c, const core::World& world, const mapping::MapView& map,
              const std::vector<std::vector<core::Vec2>>& agent_paths, const MapPictureExtras& extras = {}) {
  c.image.setTo(cv::Scalar(200, 200, 200));  // unknown
  for (const auto& poly : map.known_space) {
    std::vector<std::vector<cv::Point>> rings{c.Px(poly.outer)};
    for (const auto& h : poly.holes) rings.push_back(c.Px(h));
    cv::fillPoly(c.image, rings, cv::Scalar(252, 252, 252), cv::LINE_AA);
  }
  for (const core::Ring* r : core::MapRings(world)) c.Outline(*r, cv::Scalar(170, 170, 170), 1);  // true walls
  for (size_t a = 0; a < agent_paths.size(); ++a) {
    std::vector<cv::Point> pts;
    for (const auto& p : agent_paths[a]) pts.push_back(c.Px(p));
    if (pts.size() > 1)
      cv::polylines(c.image, std::vector<std::vector<cv::Point>>{pts}, false, kAgentColours[a % 3], 1, cv::LINE_AA);
  }
  const auto dashed = [&](const std::vector<core::Vec2>& points, const cv::Scalar& colour, int thickness) {
    for (size_t i = 1; i < points.size(); ++i) {
      const core::Vec2 a = points[i - 1], b = points[i];
      const double len = core::Distance(a, b);
      for (double t = 0; t < len; t += 3.0)
        cv::line(c.image, c.Px(a + (b - a) * (t / len)), c.Px(a + (b - a) * (std::min(t + 1.8, len) / len)), colour,
                 thickness, cv::LINE_AA);
    }
  };
  for (const auto& f : map.frontiers) {
    const auto& e = extras.frontier_ps;
    if (std::none_of(e.begin(), e.end(), [&](const planning::FrontierEstimate& x) { return x.frontier_id == f.id; }))
      dashed(f.points, cv::Scalar(200, 0, 200), 2);
  }
  for (const auto& e : extras.frontier_ps) {
    const double p = std::clamp(e.ps, 0.0, 1.0);
    dashed(e.points, cv::Scalar(0, 190 * p, 220 * (1 - p)), e.subgoal ? 6 : 3);  // the subgoal thicker
  }
  for (const auto& w : map.walls) cv::line(c.image, c.Px(w.pa), c.Px(w.pb), cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  for (const auto& b : extras.blocks) cv::line(c.image, c.Px(b.a), c.Px(b.b), cv::Scalar(0, 140, 255), 3, cv::LINE_AA);
  for (const auto& w : extras.scan_walls)
    cv::line(c.image, c.Px(w.a), c.Px(w.b), cv::Scalar(160, 160, 0), 2, cv::LINE_AA);
  std::vector<cv::Point> way;
  for (const auto& p : extras.way) way.push_back(c.Px(p));
  if (way.size() > 1)
    cv::polylines(c.image, std::vector<std::vector<cv::Point>>{way}, false, kWay, 1, cv::LINE_AA);
  for (const auto& v : map.vertices)
    cv::circle(c.image, c.Px(v.position), 3, cv::Scalar(0, 0, 0), cv::FILLED, cv::LINE_AA);
  for (const auto& v : map.rejected) cv::circle(c.image, c.Px(v.position), 4, cv::Scalar(0, 0, 230), 2, cv::LINE_AA);
  for (size_t a = 0; a < agent_paths.size(); ++a)
    if (!agent_paths[a].empty())
      cv::circle(c.image, c.Px(agent_paths[a].back()), c.Len(1.0) + 2, kAgentColours[a % 3], cv::FILLED, cv::LINE_AA);
  if (extras.goal) {
    cv::circle(c.image, c.Px(*extras.goal), c.Len(2.5), kGoal, cv::FILLED, cv::LINE_AA);
    cv::circle(c.image, c.Px(*extras.goal), c.Len(2.5), kWall, 1, cv::LINE_AA);
  }
}

void DrawMapPicture(const core::World& world, const mapping::MapView& map,
                    const std::vector<std::vector<core::Vec2>>& agent_paths, const PictureOptions& options,
                    const std::string& png_path, const MapPictureExtras& extras) {
  Canvas c(world, options);
  PaintMap(c, world, map, agent_paths, extras);
  c.Save(png_path);
}

struct TrialVideo::Impl {
  core::World world;
  PictureOptions options;
  std::string path;
  cv::VideoWriter writer;
  cv::Size size;
};

TrialVideo::TrialVideo(const core::World& world, const PictureOptions& options, const std::string& path, double fps)
    : impl_(std::make_unique<Impl>()) {
  impl_->world = world;
  impl_->options = options;
  impl_->path = path;
  const std::string ext = std::filesystem::path(path).extension().string();
  int fourcc = 0;
  if (ext == ".mp4") fourcc = cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  else if (ext == ".avi") fourcc = cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
  else throw core::DataError(path, "a trial video must be .mp4 or .avi, not '" + ext + "'");
  Canvas c(world, options);
  impl_->size = {c.image.cols + (c.image.cols % 2), c.image.rows + (c.image.rows % 2)};  // even sides for codecs
  bool ok = false;
  try {
    ok = impl_->writer.open(path, fourcc, fps, impl_->size, true);
  } catch (const cv::Exception& e) {
    throw core::DataError(path, std::string("cannot open the video: ") + e.what());
  }
  if (!ok) throw core::DataError(path, "cannot open the video (no OpenCV video backend for " + ext + "?)");
}

TrialVideo::~TrialVideo() = default;

void TrialVideo::AddFrame(const mapping::MapView& map, const std::vector<std::vector<core::Vec2>>& agent_paths,
                          const MapPictureExtras& extras) {
  Canvas c(impl_->world, impl_->options);
  PaintMap(c, impl_->world, map, agent_paths, extras);
  cv::Mat frame(impl_->size, CV_8UC3, cv::Scalar(70, 70, 70));
  c.image.copyTo(frame(cv::Rect(0, 0, c.image.cols, c.image.rows)));
  impl_->writer.write(frame);
  ++frames_;
}

void DrawObservationPicture(const core::World& world, const core::Pose2& pose,
                            const std::vector<sim::VisibleVertex>& visible, const core::Ring& visibility_polygon,
                            const PictureOptions& options, const std::string& png_path,
                            const std::vector<core::Detection>& detections) {
  Canvas c(world, options);
  DrawWorld(c, world);
  if (visibility_polygon.size() >= 3) {
    cv::Mat overlay = c.image.clone();
    std::vector<std::vector<cv::Point>> polys{c.Px(visibility_polygon)};
    cv::fillPoly(overlay, polys, cv::Scalar(120, 230, 250), cv::LINE_AA);
    cv::addWeighted(overlay, 0.5, c.image, 0.5, 0, c.image);
    c.Outline(visibility_polygon, cv::Scalar(0, 160, 220), 1);
  }
  static const cv::Scalar colours[4] = {cv::Scalar(0, 140, 255), cv::Scalar(0, 0, 0), cv::Scalar(180, 40, 150),
                                        cv::Scalar(140, 140, 140)};
  for (const auto& v : visible) {
    const cv::Scalar col = colours[static_cast<int>(v.label)];
    cv::line(c.image, c.Px(pose.position()), c.Px(v.position), col, 1, cv::LINE_AA);
    cv::circle(c.image, c.Px(v.position), c.Len(1.5) + 2, col, cv::FILLED, cv::LINE_AA);
  }
  for (const auto& d : detections) {
    const auto best = std::max_element(d.labels.begin(), d.labels.end());
    const int half = c.Len(1.5) + 3 + int(std::lround(6 * *best));
    const cv::Point p = c.Px(core::DetectionPosition(pose, d));
    cv::rectangle(c.image, p - cv::Point(half, half), p + cv::Point(half, half), colours[best - d.labels.begin()], 2,
                  cv::LINE_AA);
  }
  DrawAgent(c, pose, kStart);
  c.Save(png_path);
}

}  // namespace toponav::experiments

#include "experiments/batch.h"

namespace toponav::experiments {

void WriteStepsPlot(const std::vector<TrialRecord>& records, const std::string& png_path) {
  // One panel per world kind: steps of each seed's trial, single agent (blue) and team (orange), sorted by
  // the single-agent steps so the gap between the two is easy to see.
  std::map<int, std::map<uint64_t, std::pair<int, int>>> panels;  // kind -> seed -> (single, team)
  int max_steps = 1;
  for (const auto& r : records) {
    if (!r.ok) continue;
    auto& cell = panels[int(r.id.kind)][r.id.seed];
    (r.id.agents == 1 ? cell.first : cell.second) = r.steps;
    max_steps = std::max(max_steps, r.steps);
  }
  const int pw = 520, ph = 300, margin = 40;
  const int n = std::max<int>(1, int(panels.size()));
  cv::Mat img(ph * n, pw, CV_8UC3, cv::Scalar(255, 255, 255));
  int p = 0;
  for (const auto& [kind, seeds] : panels) {
    const int top = p * ph;
    std::vector<std::pair<int, int>> v;
    for (const auto& [s, c] : seeds) v.push_back(c);
    std::sort(v.begin(), v.end());
    cv::rectangle(img, {margin, top + 20}, {pw - 10, top + ph - margin}, cv::Scalar(180, 180, 180), 1);
    cv::putText(img,
                std::string(core::ToString(static_cast<core::WorldKind>(kind))) +
                    ": steps per trial (blue 1 agent, orange team)",
                {margin, top + 14}, cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    cv::putText(img, std::to_string(max_steps), {2, top + 28}, cv::FONT_HERSHEY_SIMPLEX, 0.35, cv::Scalar(0, 0, 0), 1);
    cv::putText(img, "0", {20, top + ph - margin}, cv::FONT_HERSHEY_SIMPLEX, 0.35, cv::Scalar(0, 0, 0), 1);
    const double plot_w = pw - 10 - margin - 10, plot_h = ph - margin - 20 - 5;
    for (size_t i = 0; i < v.size(); ++i) {
      const int x = margin + 5 + int(plot_w * (v.size() == 1 ? 0.5 : double(i) / double(v.size() - 1)));
      auto y = [&](int steps) { return top + ph - margin - int(plot_h * steps / max_steps); };
      if (v[i].first > 0) cv::circle(img, {x, y(v[i].first)}, 3, cv::Scalar(200, 100, 20), cv::FILLED, cv::LINE_AA);
      if (v[i].second > 0) cv::circle(img, {x, y(v[i].second)}, 3, cv::Scalar(20, 120, 240), cv::FILLED, cv::LINE_AA);
    }
    ++p;
  }
  Save(img, png_path);
}

}  // namespace toponav::experiments

#pragma once
// Top-down pictures (PNG).  North is up; one world unit is PictureOptions::pixels_per_unit pixels.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/config.h"
#include "mapping/mapping.h"
#include "planning/lsp_planner.h"
#include "sim/raycast.h"
#include "sim/render.h"

namespace toponav::experiments {

// Walls, obstacles, clutter (boxes brown, cylinders blue, trees green), the guiding path, start (blue arrow)
// and goal (red).  Throws core::DataError if the file cannot be written.
void DrawWorldPicture(const core::World& world, const PictureOptions& options, const std::string& png_path);

// The world, the visibility polygon shaded, and a ray to each visible vertex coloured by its label
// (corner black, right gap orange, left gap purple, point grey); a sensor's detections, if any, as hollow
// squares in the colour of their most likely label (the square's size grows with that label's probability).
void DrawObservationPicture(const core::World& world, const core::Pose2& pose,
                            const std::vector<sim::VisibleVertex>& visible, const core::Ring& visibility_polygon,
                            const PictureOptions& options, const std::string& png_path,
                            const std::vector<core::Detection>& detections = {});

// What a navigation picture adds: the goal, and each frontier's estimated Ps (frontier id -> [0, 1]); a
// search picture: the motion blocks the planners were given (search.block_when_stuck).
struct MapPictureExtras {
  std::optional<core::Vec2> goal;
  // Drawn in place of their frontiers, red (Ps 0) to green (1), the subgoal thicker.
  std::vector<planning::FrontierEstimate> frontier_ps;
  std::vector<core::Segment2> blocks;
  std::vector<core::Segment2> scan_walls;  // a held agent's range scans (navigation.scan_when_held)
  std::vector<core::Vec2> way;  // the way the agent follows this step (navigation frames and videos)
};

// A map over the true world: true walls faint, known space shaded, frontiers dashed (magenta; with an
// estimated Ps from red at 0 to green at 1), map walls and vertices black, rejected vertices red, the agents'
// paths in their own colours, motion blocks orange, range-scan walls teal, the way the agent follows a thin
// cyan line, the goal (if given) a red disc.
void DrawMapPicture(const core::World& world, const mapping::MapView& map,
                    const std::vector<std::vector<core::Vec2>>& agent_paths, const PictureOptions& options,
                    const std::string& png_path, const MapPictureExtras& extras = {});

// A video of a trial, one DrawMapPicture frame per AddFrame: MP4 ('.mp4',
// MPEG-4 part 2) or Motion-JPEG AVI ('.avi').  Throws core::DataError naming the file if it cannot be opened.
class TrialVideo {
 public:
  TrialVideo(const core::World& world, const PictureOptions& options, const std::string& path, double fps = 15.0);
  ~TrialVideo();
  TrialVideo(const TrialVideo&) = delete;
  TrialVideo& operator=(const TrialVideo&) = delete;
  void AddFrame(const mapping::MapView& map, const std::vector<std::vector<core::Vec2>>& agent_paths,
                const MapPictureExtras& extras = {});
  int frames() const { return frames_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int frames_ = 0;
};

// A panorama as a PNG (RGB), its depth as a grey PNG (near bright, 'max_depth' and beyond black), or K
// panoramas stacked top to bottom with a caption on each (a contact sheet).
void WritePanoramaPng(const sim::Panorama& pano, const std::string& png_path);
void WriteDepthPng(const sim::Panorama& pano, double max_depth, const std::string& png_path);
void WriteContactSheet(const std::vector<sim::Panorama>& panos, const std::vector<std::string>& captions,
                       const std::string& png_path);
// A width x height single-channel image (row-major bytes) as a grey PNG, values unchanged.
void WriteGreyPng(const std::vector<uint8_t>& pixels, int width, int height, const std::string& png_path);

}  // namespace toponav::experiments

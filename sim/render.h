#pragma once
// Off-screen 360-degree panoramas (OSMesa, no GPU or display needed): what the robot's camera sees.
// Column j of a W-wide panorama looks along bearing core::ColumnToBearing(j, W) relative to the heading
// (counter-clockwise bearings grow to the right, so the image is the mirror of a hand-held panorama);
// rows span elevations +vertical_fov/2 (row 0, top) to -vertical_fov/2.  Rendering is deterministic and
// safe from several threads: each thread gets its own OpenGL context, created once and reused.
#include <cstdint>
#include <memory>
#include <vector>

#include "core/image.h"
#include "core/option_fields.h"
#include "core/world.h"

namespace toponav::sim {

struct RenderOptions {
  int width = 512;                 // pixels; a multiple of 4
  int height = 128;                // pixels
  double vertical_fov_deg = 90.0;  // 128 rows over 90 degrees: square pixels at 512 columns
  double camera_height = 10.0;     // world units (the reference camera: 1.5 m at 0.15 m per unit)
  double wall_height = 30.0;       // indoor walls and ceiling
  int supersample = 1;             // render the cube faces this many times larger before resampling (less blur)
  double plain_wall_fraction = 0.35;  // share of textureless walls in indoor worlds
  static const core::OptionFields<RenderOptions>& Fields();  // YAML keys and their ranges
  void Validate() const;           // throws core::ConfigError ("render.width", ...)
};

// What each pixel of the obstacle-id image holds.
constexpr int32_t kNoObstacle = -1;                 // floor, ceiling, sky, guide path
constexpr int32_t WallId(int ring, int edge) { return ring * 65536 + edge; }  // map wall: ring, edge index
constexpr int32_t kClutterIdBase = 0x40000000;
constexpr int32_t ClutterId(int index) { return kClutterIdBase + index; }

using core::Panorama;  // what Render returns (core/image.h)

enum RenderOutput : int { kRenderRgb = 1, kRenderDepth = 2, kRenderIds = 4 };

class Renderer {
 public:
  // Builds the scene of 'world' (walls, floor, ceiling or sky, clutter, trees, guide path); colours and
  // textures come from the world's seed.  Throws core::ConfigError for bad options.
  Renderer(const core::World& world, const RenderOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders at 'pose' (camera at options.camera_height).  'outputs' is a mask of RenderOutput.
  // Throws core::InternalError if OpenGL fails (no OSMesa context, framebuffer incomplete).
  Panorama Render(const core::Pose2& pose, int outputs = kRenderRgb) const;

  const RenderOptions& options() const;
  int num_triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::sim

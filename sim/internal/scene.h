#pragma once
// The triangle soup of a world's 3D scene (no OpenGL here: the renderer uploads it).
#include <cstdint>
#include <vector>

#include "core/world.h"
#include "sim/render.h"

namespace toponav::sim::internal {

// Surface patterns drawn by the fragment shader (keep in sync with osmesa_renderer.cpp).
enum Pattern : int { kPlain = 0, kPanels, kBricks, kStripes, kWindows, kTiles, kGrass, kCeiling, kBark, kLeaves };

struct SceneVertex {
  float pos[3];
  float normal[3];
  float color[3];
  float uv[2];       // along-surface coordinates (world units)
  float material[2]; // pattern, surface length (for corner shading; 0 = none)
  int32_t id;
};

// A run of triangles with a bounding circle in the ground plane, for per-view culling.
struct SceneObject {
  uint32_t first = 0, count = 0;  // vertex range
  float cx = 0, cy = 0, radius = 0; // radius < 0: always drawn (floor, ceiling)
};

struct Scene {
  std::vector<SceneVertex> vertices;  // triangles: 3 per face
  std::vector<SceneObject> objects;   // cover 'vertices' in order
  float sky[3] = {0.62f, 0.76f, 0.92f};
};

Scene BuildScene(const core::World& world, const RenderOptions& options);

}  // namespace toponav::sim::internal

#pragma once
// Images the robot's camera produces: a 360-degree panorama (RGB, and optionally per-pixel depth and
// obstacle ids from the simulator).  Column j of a W-wide panorama looks along bearing
// core::ColumnToBearing(j, W) relative to the agent's heading; row 0 is the top.  A plain type shared by
// the renderer (sim), the learned detector (learning) and recorded image folders.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace toponav::core {

struct Panorama {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;     // row-major RGB, row 0 at the top
  std::vector<float> depth;     // distance from the camera per pixel (infinity: sky); empty unless rendered
  std::vector<int32_t> ids;     // obstacle id per pixel (sim::WallId, sim::ClutterId); empty unless rendered
  uint8_t r(int row, int col) const { return rgb[3 * (size_t(row) * width + col)]; }
  uint8_t g(int row, int col) const { return rgb[3 * (size_t(row) * width + col) + 1]; }
  uint8_t b(int row, int col) const { return rgb[3 * (size_t(row) * width + col) + 2]; }
  bool empty() const { return rgb.empty(); }
};

}  // namespace toponav::core

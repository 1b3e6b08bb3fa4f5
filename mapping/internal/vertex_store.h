#pragma once
// The map's potential vertices: association of each observation's detections to them and Kalman updates.
#include <vector>

#include "mapping/internal/map_data.h"

namespace toponav::mapping::internal {

class VertexStore {
 public:
  explicit VertexStore(const MapperOptions& options) : o_(options) {}

  // Associates detections at world positions 'z' with covariances 'R' one-to-one to vertices, Kalman-updates
  // the matched vertices and makes new ones for the rest; returns the vertex of each detection.
  std::vector<int> Update(const std::vector<Eigen::Vector2d>& z, const std::vector<Eigen::Matrix2d>& R);

  size_t size() const { return v_.size(); }
  const Vertex& operator[](size_t i) const { return v_[i]; }
  core::Vec2 Pos(int i) const { return ToVec(v_[size_t(i)].x); }
  // Enough detections to be a candidate for the map (MCMC decides whether it is in).
  bool Seen(int i) const { return v_[size_t(i)].n >= o_.min_detections; }
  bool Mapped(int i) const { return Seen(i) && v_[size_t(i)].in_map; }
  void SetInMap(int i, bool on) { v_[size_t(i)].in_map = on; }

 private:
  std::vector<int> Associate(const std::vector<Eigen::Vector2d>& z, const std::vector<Eigen::Matrix2d>& R) const;
  MapperOptions o_;
  std::vector<Vertex> v_;
};

}  // namespace toponav::mapping::internal

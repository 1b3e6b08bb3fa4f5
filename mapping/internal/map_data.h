#pragma once
// What the concerns of the vertex map share (internal to the mapping layer): vertices with their Kalman
// state, the observations with their associations and star polygons, and the map states MCMC proposes.
// Each concern lives in its own file under mapping/internal/:
//   vertex_store   association of detections to vertices and Kalman updates
//   wall_evidence  evidence for walls between vertices, and which walls a map state has
//   stars          star polygons of real and hypothetical observations
//   posterior      hypothetical observations and the log posterior; mcmc: sampling the most likely map
//   known_space    the incremental union of per-observation known space
//   frontiers      frontier extraction with stable ids
#include <Eigen/Dense>

#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/geometry.h"
#include "core/observation.h"
#include "mapping/mapping.h"

namespace toponav::mapping::internal {

inline Eigen::Matrix2d ToEigen(const core::Cov2& c) {
  Eigen::Matrix2d m;
  m << c.xx, c.xy, c.xy, c.yy;
  return m;
}
inline core::Cov2 FromEigen(const Eigen::Matrix2d& m) { return {m(0, 0), 0.5 * (m(0, 1) + m(1, 0)), m(1, 1)}; }
inline core::Vec2 ToVec(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
// The key of the wall between vertices a and b (either order).
inline uint64_t WallKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
}
inline std::pair<int, int> WallEnds(uint64_t key) { return {int(key >> 32), int(key & 0xffffffffu)}; }
double Wrap2Pi(double a);

using Wall = std::pair<int, int>;  // vertex ids, first < second

struct Vertex {
  Eigen::Vector2d x;
  Eigen::Matrix2d P;
  int n = 0;
  bool in_map = true;  // the MCMC state; only counts once n >= min_detections
};

// One observation as the map keeps it.
struct Obs {
  core::Pose2 pose;
  std::vector<core::Detection> det;               // sorted by bearing
  std::vector<int> vid;                           // vertex of each detection
  std::vector<core::Vec2> at;                     // each detection's position in the world ...
  std::vector<Eigen::LDLT<Eigen::Matrix2d>> cov;  // ... and its covariance, factored (for the likelihood)
  // Star polygon of the real observation from the positions its vertices had when it was built.
  core::Ring star;
  core::Aabb2 box;
  std::vector<core::Vec2> star_src;
};

// A proposed map: which vertices are in it and its walls (sorted pairs, a < b), with a key set for lookups.
struct MapState {
  std::vector<char> mapped;
  std::vector<Wall> walls;
  std::unordered_set<uint64_t> wall_keys;
  int num_vertices = 0;
  bool HasWall(int a, int b) const { return wall_keys.count(WallKey(a, b)) > 0; }
};

}  // namespace toponav::mapping::internal

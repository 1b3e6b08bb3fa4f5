#pragma once
// Evidence for walls between vertices, gathered from every observation, and the walls a map state has.
// Evidence is partly conditional on the map: a detection lying on the segment between two detections damps
// their wall evidence only while its vertex is in the map (so MCMC weighs a doorway's jamb and the wall
// across the door together).
#include <unordered_map>
#include <vector>

#include "mapping/internal/map_data.h"
#include "mapping/internal/vertex_store.h"

namespace toponav::mapping::internal {

class WallEvidence {
 public:
  explicit WallEvidence(const MapperOptions& options) : o_(options) {}

  // Adds the evidence of one observation (its detections already associated, 'num_vertices' vertices now).
  void Add(const Obs& ob, size_t num_vertices);

  // The wall's averaged evidence under the map 'mapped' (with vertex 'flip' set to 'flip_on' if given).
  double Prob(int a, int b, const std::vector<char>& mapped, int flip = -1, bool flip_on = false) const;
  // The walls between mapped vertices whose evidence exceeds the threshold, sorted.
  std::vector<Wall> MappedWalls(const std::vector<char>& mapped) const;
  // The map as the vertices' MCMC flags have it.
  MapState State(const VertexStore& vertices) const;
  // Flips vertex i in 'ms', updating its walls.
  void SetMapped(int i, bool on, MapState* ms) const;
  // Walls whose existence changes when vertex i flips in 'ms': its own walls to mapped vertices, and walls
  // between two mapped vertices whose evidence i damps while mapped (it lies on their segment).
  std::vector<Wall> ChangedWalls(int i, const MapState& ms) const;

  // Vertices that share wall evidence with vertex i.
  const std::vector<int>& Neighbours(int i) const { return neighbours_[size_t(i)]; }
  size_t size() const { return walls_.size(); }  // vertex pairs with evidence

 private:
  // Evidence samples that do not depend on the map ('sum'), and samples with detections lying on the segment
  // between the two vertices, which damp the sample only while their vertex is in the map.
  struct CondSample {
    double value = 0.0;
    std::vector<int> on_segment;  // vertices of those detections
  };
  struct Stats {
    double sum = 0.0;
    int count = 0;
    std::vector<CondSample> cond;
  };
  bool OnSegment(const core::Vec2& p, const core::Vec2& a, const core::Vec2& b) const;

  MapperOptions o_;
  std::unordered_map<uint64_t, Stats> walls_;
  std::vector<std::vector<uint64_t>> spans_;   // vertex -> walls whose evidence it can damp (on their segment)
  std::vector<std::vector<int>> neighbours_;   // vertex -> vertices it shares wall evidence with
};

}  // namespace toponav::mapping::internal

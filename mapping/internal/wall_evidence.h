#pragma once
// Evidence for walls between vertices, gathered from every observation, and the walls a map state has.
// Evidence is partly conditional on the map: a detection lying on the segment between two detections damps
// their wall evidence only while its vertex is in the map (so MCMC weighs a doorway's jamb and the wall
// across the door together), and an observation that missed a vertex lying between its pose and that segment
// gives the pair no evidence while that vertex is in the map (MapperOptions::wall_front_vertex_tolerance).
#include <unordered_map>
#include <vector>

#include "mapping/internal/map_data.h"
#include "mapping/internal/vertex_store.h"

namespace toponav::mapping::internal {

class WallEvidence {
 public:
  explicit WallEvidence(const MapperOptions& options) : o_(options) {}

  // Adds the evidence of one observation (its detections already associated to 'vertices').
  void Add(const Obs& ob, const VertexStore& vertices);

  // The wall's averaged evidence under the map 'mapped' (with vertex 'flip' set to 'flip_on' if given).
  double Prob(int a, int b, const std::vector<char>& mapped, int flip = -1, bool flip_on = false) const;
  // The walls between mapped vertices whose evidence exceeds the threshold, sorted.
  std::vector<Wall> MappedWalls(const std::vector<char>& mapped) const;
  // The map as the vertices' MCMC flags have it.
  MapState State(const VertexStore& vertices) const;
  // Flips vertex i in 'ms', updating its walls.
  void SetMapped(int i, bool on, MapState* ms) const;
  // Walls whose existence changes when vertex i flips in 'ms': its own walls to mapped vertices, and walls
  // between two mapped vertices whose evidence depends on i (it lies on their segment, or in front of it
  // unseen by some of their sightings).
  std::vector<Wall> ChangedWalls(int i, const MapState& ms) const;

  // Vertices that share wall evidence with vertex i.
  const std::vector<int>& Neighbours(int i) const { return neighbours_[size_t(i)]; }
  size_t size() const { return walls_.size(); }  // vertex pairs with evidence

 private:
  // Evidence samples that do not depend on the map ('sum'), and samples that do: the vertices of detections
  // lying on the segment between the two vertices damp such a sample while in the map, and a sample with a
  // vertex in the map that the observation missed between its pose and that segment does not count.
  struct CondSample {
    double value = 0.0;
    std::vector<int> damping;  // the vertices of detections on the segment
    std::vector<int> front;    // the vertices missed in front of it
  };
  struct Stats {
    double sum = 0.0;
    int count = 0;
    std::vector<CondSample> cond;
  };
  bool OnSegment(const core::Vec2& p, const core::Vec2& a, const core::Vec2& b) const;
  // Candidates for lying in front of a pair's segment: the vertices that had enough detections when the
  // observation was added, within the mapper's range of the pose (none when wall_front_vertex_tolerance is 0).
  struct FrontCandidate {
    int id;   // the vertex
    int det;  // the observation's detection of it, -1 if none
  };
  std::vector<FrontCandidate> FrontCandidates(const Obs& ob, const VertexStore& vertices) const;
  // The candidates (at their positions in 'vertices') lying between the pose and the segment from detection
  // i to detection i + steps (counter-clockwise of it, less than pi on), or within the tolerance of the two
  // sight lines, and farther than it from the segment and its ends; not those of the pair's detections or of
  // the ones between them (a candidate detected elsewhere in bearing counts: its detection missed its place).
  void AddFront(const Obs& ob, size_t i, size_t steps, const std::vector<FrontCandidate>& candidates,
                const VertexStore& vertices, std::vector<int>* out) const;

  MapperOptions o_;
  std::unordered_map<uint64_t, Stats> walls_;
  std::vector<std::vector<uint64_t>> spans_;   // vertex -> walls whose evidence depends on it
  std::vector<std::vector<int>> neighbours_;   // vertex -> vertices it shares wall evidence with
};

}  // namespace toponav::mapping::internal

#pragma once
// The map's evidence in one place: options, vertices, wall evidence and the observations.  The concerns that
// derive things from it (the posterior, MCMC, known space, frontiers) read it; only the Mapper's
// AddObservation and MCMC's vertex flags change it.
#include <vector>

#include "mapping/internal/map_data.h"
#include "mapping/internal/vertex_store.h"
#include "mapping/internal/wall_evidence.h"

namespace toponav::mapping::internal {

struct MapCore {
  explicit MapCore(const MapperOptions& options) : o(options), vertices(options), walls(options) {}
  MapperOptions o;
  VertexStore vertices;
  WallEvidence walls;
  std::vector<Obs> obs;
  core::Vec2 Pos(int i) const { return vertices.Pos(i); }
};

}  // namespace toponav::mapping::internal

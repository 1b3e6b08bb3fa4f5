#pragma once
// Properties a generated world must have, checked by `toponav world --check` and the tests.
#include <string>
#include <vector>

#include "core/world.h"
#include "sim/worlds.h"

namespace toponav::experiments {

struct WorldStats {
  int num_vertices = 0;
  int num_obstacles = 0;
  int num_clutter = 0;
  double free_area = 0.0;            // polygon-map free space (clutter not subtracted)
  int free_components = 0;           // connected pieces of free space (exact polygon Booleans)
  double min_building_gap = 0.0;     // office park: smallest distance between two buildings
  double max_nearest_building_gap = 0.0;  // office park: largest distance from a building to its nearest one
};

WorldStats ComputeWorldStats(const core::World& world);

// Problems with a world generated with 'options' ("free space has 2 pieces", "buildings 3 and 5 are 12.1
// apart"); empty when the world is fine.
std::vector<std::string> CheckWorld(const core::World& world, const sim::WorldOptions& options);

}  // namespace toponav::experiments

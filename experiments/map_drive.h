#pragma once
// Building a map along a scripted drive: one agent follows a path through the world on the agent loop,
// observing with the config's sensor each step, MCMC on a cadence.  Used by `toponav map` and the mapping
// quality tests.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/config.h"
#include "mapping/mapping.h"
#include "mapping/polygon_set.h"

namespace toponav::experiments {

struct MapDriveOptions {
  std::string path = "tour";   // "tour" (visit the whole free space), "guide" (the guide path), "goal" (start to goal)
  double tour_spacing = 0.0;   // tour waypoint grid spacing; 0: 20, or 11 in a guided maze (half its cell pitch)
  int max_steps = 3000;        // stop after this many agent steps even if the path goes on
  int mcmc_every = 5;          // run MCMC every this many steps (and once at the end); 0: never
  uint64_t seed = 0;           // sensor and MCMC randomness
};

struct MapDriveResult {
  mapping::MapView view;
  std::vector<core::Vec2> agent_path;
  int steps = 0;
  double known_space_iou = 0.0;   // known space vs true free space
  std::optional<double> building_iou;  // open worlds: the search's building-placement IoU (BuildingPlacementIoU)
  int map_vertices = 0;
  int false_vertices = 0;         // map vertices farther than 'vertex_match_radius' from any true vertex
  double mean_vertex_error = 0.0; // mean distance of the other map vertices to the nearest true vertex
  int map_walls = 0;
  int false_walls = 0;            // map walls whose ends are not (within the radius) the ends of one true wall
  int walls_across_free_space = 0;  // map walls reaching deeper than kAcrossDepth into true free space (a
                                    // wall across a corridor or jutting into one, not one a little off its place)
  int walls_across_corridor = 0;    // of those, the walls that cut the agent's free space (FreeSpaceRegions:
                                    // more regions of kCutMinArea or more): across a corridor or a doorway
  double log_posterior = 0.0;     // of the final map
  double mean_update_ms = 0.0;    // Mapper::AddObservation + View (known space, frontiers)
  double mean_mcmc_ms = 0.0;      // Mapper::SampleMostLikelyMap
};

constexpr double kVertexMatchRadius = 5.0;
constexpr double kAcrossDepth = 3.0;
constexpr double kCutMinArea = 100.0;  // square world units: half a guided maze's 14x14 corridor cell

MapDriveResult RunMapDrive(const core::World& world, const Config& config, const MapDriveOptions& options);

// The map's known space as an exact set: the view's own when it has one; a view put together by hand only
// has the double-precision polygons.
mapping::PolygonSet KnownSet(const mapping::MapView& map);

// Intersection over union of the map's known space and the world's true free space (map walls only).
double KnownSpaceIoU(const core::World& world, const mapping::MapView& map);

}  // namespace toponav::experiments

#pragma once
// Procedural worlds.  Every generator is a pure function of (options, seed): the same seed gives the same
// world, byte for byte once written as JSON.
#include <cstdint>

#include "core/option_fields.h"
#include "core/world.h"

namespace toponav::sim {

// Indoor labyrinth: rooms on a cell grid joined by L-shaped corridors (vertexnav.md §5.2).
struct LabyrinthOptions {
  int num_rooms = 4;
  int grid_cells = 18;             // the room grid is grid_cells x grid_cells cells
  int room_min_cells = 3;          // rooms span room_min_cells..room_max_cells cells per side
  int room_max_cells = 4;
  double room_separation_cells = 2.05;  // a room set with two rooms this close is redrawn (cells between the
                                        // rooms' edge-cell centres; on a diagonal, the sum over both axes)
  int max_corridor_offset_cells = 6;    // a connection spanning more cells on either axis is rejected
  int max_straight_run_cells = 11;      // maps with a longer straight run of free cells are rejected
  double hall_width = 20.0;             // corridor width in world units
  double inflate_ratio = 0.30;          // cell size = hall_width / (1 + inflate_ratio)
  int num_clutter = 40;                 // boxes and cylinders near walls (not part of the map)
  double box_half_size = 1.125;
  double cylinder_radius = 1.0;
  double clutter_height = 2.25;
  double clutter_max_wall_gap = 1.5;    // clutter stands at most this far from a wall
  double start_clearance = 6.0;         // start and goal at least this far from walls and clutter
  static const core::OptionFields<LabyrinthOptions>& Fields();  // YAML keys and their ranges
};

// Office park: rotated building footprints 25-40 units apart, and round trees (vertexnav.md §5.3).
struct OfficeParkOptions {
  int num_buildings = 8;
  int candidates_per_round = 1000;
  double min_building_gap = 25.0;
  double max_building_gap = 40.0;
  double scale_min = 2.0;          // footprint scales (x and y independently)
  double scale_max = 3.5;
  int num_trees = 30;
  double tree_radius = 1.5;        // the trunk part that blocks motion and rays
  double tree_min_gap = 15.0;      // trees stand 15-40 units from the nearest building
  double tree_max_gap = 40.0;
  double bounds_margin = 20.0;     // the search region is the buildings' bounding box grown by this
  double start_min_gap = 6.0;      // start 6-12 units from the nearest building
  double start_max_gap = 12.0;
  static const core::OptionFields<OfficeParkOptions>& Fields();
};

// Guided maze: a randomized-Kruskal spanning-tree maze with a guiding path from start to goal (lsp.md §5.1).
struct GuidedMazeOptions {
  int cells_x = 6;
  int cells_y = 8;
  double corridor_width = 14.0;
  double wall_thickness = 8.0;
  double border = 10.0;
  double guide_path_width = 4.0;
  static const core::OptionFields<GuidedMazeOptions>& Fields();
};

struct WorldOptions {
  LabyrinthOptions labyrinth;
  OfficeParkOptions office_park;
  GuidedMazeOptions guided_maze;
  void Validate() const;  // ranges (Fields) and rules between keys; throws core::ConfigError naming the key
};

core::World GenerateLabyrinth(const LabyrinthOptions& options, uint64_t seed);
core::World GenerateOfficePark(const OfficeParkOptions& options, uint64_t seed);
core::World GenerateGuidedMaze(const GuidedMazeOptions& options, uint64_t seed);
// Dispatches on 'kind' (kCustom is not generated: throws core::ConfigError).
core::World GenerateWorld(core::WorldKind kind, const WorldOptions& options, uint64_t seed);

}  // namespace toponav::sim

#include <string>

#include "core/error.h"
#include "sim/worlds.h"

namespace toponav::sim {

namespace {

constexpr double kBig = 1e6;

void Require(bool ok, const std::string& key, double value, const std::string& problem) {
  if (!ok) throw core::ConfigError("<options>", key, std::to_string(value), problem);
}

}  // namespace

const core::OptionFields<LabyrinthOptions>& LabyrinthOptions::Fields() {
  using O = LabyrinthOptions;
  static const core::OptionFields<O> fields{
      {"num_rooms", &O::num_rooms, 2, 12},
      {"grid_cells", &O::grid_cells, 4, 64},
      {"room_min_cells", &O::room_min_cells, 3, 20},  // a room has an interior cell
      {"room_max_cells", &O::room_max_cells, 3, 20},
      {"room_separation_cells", &O::room_separation_cells, 0.0, 20.0},
      {"max_corridor_offset_cells", &O::max_corridor_offset_cells, 1, 64},
      {"max_straight_run_cells", &O::max_straight_run_cells, 2, 64},
      {"hall_width", &O::hall_width, 1.0, 1000.0},
      {"inflate_ratio", &O::inflate_ratio, 0.0, 0.99},
      {"num_clutter", &O::num_clutter, 0, 1000},
      {"box_half_size", &O::box_half_size, 0.01, 100.0},
      {"cylinder_radius", &O::cylinder_radius, 0.01, 100.0},
      {"clutter_height", &O::clutter_height, 0.01, 100.0},
      {"clutter_max_wall_gap", &O::clutter_max_wall_gap, 0.2, 100.0},
      {"start_clearance", &O::start_clearance, 0.0, 500.0},
  };
  return fields;
}

const core::OptionFields<OfficeParkOptions>& OfficeParkOptions::Fields() {
  using O = OfficeParkOptions;
  static const core::OptionFields<O> fields{
      {"num_buildings", &O::num_buildings, 1, 30},
      {"candidates_per_round", &O::candidates_per_round, 1, 100000},
      {"min_building_gap", &O::min_building_gap, 0.01, kBig},
      {"max_building_gap", &O::max_building_gap, 0.01, kBig},
      {"scale_min", &O::scale_min, 0.01, 100.0},
      {"scale_max", &O::scale_max, 0.01, 100.0},
      {"num_trees", &O::num_trees, 0, 500},
      {"tree_radius", &O::tree_radius, 0.01, 100.0},
      {"tree_min_gap", &O::tree_min_gap, 0.0, kBig},
      {"tree_max_gap", &O::tree_max_gap, 0.0, kBig},
      {"bounds_margin", &O::bounds_margin, 0.0, kBig},
      {"start_min_gap", &O::start_min_gap, 0.0, kBig},
      {"start_max_gap", &O::start_max_gap, 0.0, kBig},
  };
  return fields;
}

const core::OptionFields<GuidedMazeOptions>& GuidedMazeOptions::Fields() {
  using O = GuidedMazeOptions;
  static const core::OptionFields<O> fields{
      {"cells_x", &O::cells_x, 2, 50},
      {"cells_y", &O::cells_y, 2, 50},
      {"corridor_width", &O::corridor_width, 0.1, 1000.0},
      {"wall_thickness", &O::wall_thickness, 0.1, 1000.0},
      {"border", &O::border, 0.1, 1000.0},
      {"guide_path_width", &O::guide_path_width, 0.01, 1000.0},
  };
  return fields;
}

void WorldOptions::Validate() const {
  core::CheckRanges(labyrinth, LabyrinthOptions::Fields(), "labyrinth.");
  core::CheckRanges(office_park, OfficeParkOptions::Fields(), "office_park.");
  core::CheckRanges(guided_maze, GuidedMazeOptions::Fields(), "guided_maze.");
  const auto& l = labyrinth;
  Require(l.room_min_cells <= l.room_max_cells, "labyrinth.room_min_cells", l.room_min_cells,
          "must be <= room_max_cells");
  Require(l.grid_cells >= 2 * l.room_max_cells + 3, "labyrinth.grid_cells", l.grid_cells,
          "must be >= 2*room_max_cells+3");
  Require(l.max_straight_run_cells >= l.room_max_cells, "labyrinth.max_straight_run_cells", l.max_straight_run_cells,
          "must be >= room_max_cells");
  Require(l.start_clearance < l.hall_width / 2, "labyrinth.start_clearance", l.start_clearance,
          "must be < hall_width/2");
  const auto& p = office_park;
  Require(p.min_building_gap < p.max_building_gap, "office_park.min_building_gap", p.min_building_gap,
          "must be < max_building_gap");
  Require(p.scale_min <= p.scale_max, "office_park.scale_min", p.scale_min, "must be <= scale_max");
  Require(p.tree_min_gap <= p.tree_max_gap, "office_park.tree_min_gap", p.tree_min_gap, "must be <= tree_max_gap");
  Require(p.start_min_gap <= p.start_max_gap, "office_park.start_min_gap", p.start_min_gap, "must be <= start_max_gap");
  const auto& m = guided_maze;
  Require(m.guide_path_width <= m.corridor_width, "guided_maze.guide_path_width", m.guide_path_width,
          "must be <= corridor_width");
}

}  // namespace toponav::sim

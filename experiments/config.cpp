#include "experiments/config.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/geometry.h"
#include "experiments/internal/yaml_reader.h"

namespace toponav::experiments {

using internal::YamlSection;

namespace {

constexpr double kBig = 1e6;

void ReadLabyrinth(YamlSection s, sim::LabyrinthOptions* o) {
  s.Read("num_rooms", &o->num_rooms, 2, 12);
  s.Read("grid_cells", &o->grid_cells, 4, 64);
  s.Read("room_min_cells", &o->room_min_cells, 2, 20);
  s.Read("room_max_cells", &o->room_max_cells, 2, 20);
  s.Read("room_separation_cells", &o->room_separation_cells, 0.0, 20.0);
  s.Read("max_corridor_offset_cells", &o->max_corridor_offset_cells, 1, 64);
  s.Read("max_straight_run_cells", &o->max_straight_run_cells, 2, 64);
  s.Read("hall_width", &o->hall_width, 1.0, 1000.0);
  s.Read("inflate_ratio", &o->inflate_ratio, 0.0, 0.99);
  s.Read("num_clutter", &o->num_clutter, 0, 1000);
  s.Read("box_half_size", &o->box_half_size, 0.01, 100.0);
  s.Read("cylinder_radius", &o->cylinder_radius, 0.01, 100.0);
  s.Read("clutter_height", &o->clutter_height, 0.01, 100.0);
  s.Read("clutter_max_wall_gap", &o->clutter_max_wall_gap, 0.2, 100.0);
  s.Read("start_clearance", &o->start_clearance, 0.0, 500.0);
  s.Finish();
}

void ReadOfficePark(YamlSection s, sim::OfficeParkOptions* o) {
  s.Read("num_buildings", &o->num_buildings, 1, 30);
  s.Read("candidates_per_round", &o->candidates_per_round, 1, 100000);
  s.Read("min_building_gap", &o->min_building_gap, 0.0, kBig);
  s.Read("max_building_gap", &o->max_building_gap, 0.0, kBig);
  s.Read("scale_min", &o->scale_min, 0.01, 100.0);
  s.Read("scale_max", &o->scale_max, 0.01, 100.0);
  s.Read("num_trees", &o->num_trees, 0, 500);
  s.Read("tree_radius", &o->tree_radius, 0.01, 100.0);
  s.Read("tree_min_gap", &o->tree_min_gap, 0.0, kBig);
  s.Read("tree_max_gap", &o->tree_max_gap, 0.0, kBig);
  s.Read("bounds_margin", &o->bounds_margin, 0.0, kBig);
  s.Read("start_min_gap", &o->start_min_gap, 0.0, kBig);
  s.Read("start_max_gap", &o->start_max_gap, 0.0, kBig);
  s.Finish();
}

void ReadGuidedMaze(YamlSection s, sim::GuidedMazeOptions* o) {
  s.Read("cells_x", &o->cells_x, 2, 50);
  s.Read("cells_y", &o->cells_y, 2, 50);
  s.Read("corridor_width", &o->corridor_width, 0.1, 1000.0);
  s.Read("wall_thickness", &o->wall_thickness, 0.1, 1000.0);
  s.Read("border", &o->border, 0.1, 1000.0);
  s.Read("guide_path_width", &o->guide_path_width, 0.01, 1000.0);
  s.Finish();
}

}  // namespace

void SearchOptions::Validate() const {
  auto fail = [](const char* key, double v, const char* why) {
    throw core::ConfigError("<options>", key, std::to_string(v), why);
  };
  if (stuck_steps < 1) fail("search.stuck_steps", stuck_steps, "must be >= 1");
  if (unreachable_steps < 1) fail("search.unreachable_steps", unreachable_steps, "must be >= 1");
  if (!(success_iou >= 0 && success_iou <= 1)) fail("search.success_iou", success_iou, "must be in [0, 1]");
  if (!(switch_ratio >= 1)) fail("search.switch_ratio", switch_ratio, "must be >= 1");
  if (!(switch_margin >= 0)) fail("search.switch_margin", switch_margin, "must be >= 0");
  if (!(give_up_distance > 0)) fail("search.give_up_distance", give_up_distance, "must be > 0");
  if (give_up_steps < 1) fail("search.give_up_steps", give_up_steps, "must be >= 1");
  if (!(push_distance >= 0)) fail("search.push_distance", push_distance, "must be >= 0");
  if (!(give_up_reach >= 0)) fail("search.give_up_reach", give_up_reach, "must be >= 0");
  if (!(give_up_probe_radius >= 0)) fail("search.give_up_probe_radius", give_up_probe_radius, "must be >= 0");
}

namespace {

// Rules that tie keys of different sections together (each names the key to change).
void ValidateAcrossSections(const Config& c) {
  // A split must not cut a frontier into pieces the planner ignores (an opening would vanish).
  if (c.mapping.frontier_split_min_length < c.planning.frontier_min_length)
    throw core::ConfigError(c.source, "mapping.frontier_split_min_length", std::to_string(c.mapping.frontier_split_min_length),
                            "must be >= planning.frontier_min_length (" + std::to_string(c.planning.frontier_min_length) + ")");
  // Paths keep the agent's body off map walls, and stay below the inflation radius so the graph's nodes
  // (inflation_radius from each vertex) keep room to connect.
  const double lo = c.motion.agent_radius + 0.25, hi = 0.9 * c.planning.inflation_radius;
  if (c.planning.clearance < lo || c.planning.clearance > hi)
    throw core::ConfigError(c.source, "planning.clearance", std::to_string(c.planning.clearance),
                            "must be in [motion.agent_radius + 0.25, 0.9 * planning.inflation_radius] = [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

}  // namespace

void Validate(const Config& c) {
  try {
    c.worlds.Validate();
  } catch (const core::ConfigError& e) {
    throw core::ConfigError(c.source, "worlds." + e.key(), e.value(), e.problem());
  }
  for (auto validate : {+[](const Config& x) { x.sensor.Validate(); }, +[](const Config& x) { x.mapping.Validate(); },
                        +[](const Config& x) { x.planning.Validate(); }, +[](const Config& x) { x.search.Validate(); },
                        +[](const Config& x) { x.render.Validate(); }, +[](const Config& x) { x.motion.Validate(); }}) {
    try {
      validate(c);
    } catch (const core::ConfigError& e) {
      throw core::ConfigError(c.source, e.key(), e.value(), e.problem());
    }
  }
  ValidateAcrossSections(c);
  if (c.demo.kinds.empty()) throw core::ConfigError(c.source, "demo.kinds", "[]", "list at least one world kind");
  for (auto k : c.demo.kinds)
    if (k == core::WorldKind::kCustom)
      throw core::ConfigError(c.source, "demo.kinds", "custom", "custom worlds cannot be generated");
}

Config ParseConfig(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw core::ConfigError(source, "<file>", "", std::string("not valid YAML: ") + e.what());
  }
  Config c;
  c.source = source;
  YamlSection top(root, source, "");
  {
    YamlSection w = top.Section("worlds");
    ReadLabyrinth(w.Section("labyrinth"), &c.worlds.labyrinth);
    ReadOfficePark(w.Section("office_park"), &c.worlds.office_park);
    ReadGuidedMaze(w.Section("guided_maze"), &c.worlds.guided_maze);
    w.Finish();
  }
  {
    YamlSection m = top.Section("motion");
    m.Read("step_length", &c.motion.step_length, 0.01, 50.0);
    m.Read("open_world_step_length", &c.motion.open_world_step_length, 0.01, 50.0);
    m.Read("agent_radius", &c.motion.agent_radius, 0.25, 20.0);
    m.Read("substeps", &c.motion.substeps, 1, 1000);
    m.Read("avoid_margin", &c.motion.avoid_margin, 0.0, 10.0);
    m.Read("avoid_window", &c.motion.avoid_window, 1.0, 100.0);
    m.Read("avoid_cell", &c.motion.avoid_cell, 0.05, 5.0);
    m.Finish();
  }
  {
    YamlSection r = top.Section("render");
    r.Read("width", &c.render.width, 8, 4096);
    r.Read("height", &c.render.height, 2, 2048);
    r.Read("vertical_fov_deg", &c.render.vertical_fov_deg, 10.0, 150.0);
    r.Read("camera_height", &c.render.camera_height, 0.01, 1000.0);
    r.Read("wall_height", &c.render.wall_height, 0.01, 1000.0);
    r.Read("supersample", &c.render.supersample, 1, 4);
    r.Read("plain_wall_fraction", &c.render.plain_wall_fraction, 0.0, 1.0);
    r.Finish();
  }
  {
    YamlSection r = top.Section("sensor");
    std::string kind = ToString(c.sensor.kind);
    r.Read("kind", &kind);
    const auto k = ParseSensorKind(kind);
    if (!k) r.Fail("kind", kind, "unknown sensor kind (known: " + fmt::format("{}", fmt::join(SensorKindNames(), ", ")) + ")");
    c.sensor.kind = *k;
    auto& o = c.sensor.noisy;
    r.Read("max_range", &o.max_range, 1.0, 1e4);
    r.Read("range_bins", &o.range_bins, 0, 1024);
    r.Read("bearing_bins", &o.bearing_bins, 0, 4096);
    r.Read("range_sigma", &o.range_sigma, 0.0, 100.0);
    r.Read("range_sigma_per_unit", &o.range_sigma_per_unit, 0.0, 1.0);
    r.Read("bearing_sigma", &o.bearing_sigma, 0.0, 1.0);
    r.Read("miss_probability", &o.miss_probability, 0.0, 0.99);
    r.Read("false_positives_per_observation", &o.false_positives_per_observation, 0.0, 50.0);
    r.Read("merge_bins", &o.merge_bins, 0, 10);
    r.Read("label_confusion", &o.label_confusion, 0.0, 1.0);
    r.Read("label_softness", &o.label_softness, 0.0, 1.0);
    r.Read("reported_sigma_range", &o.reported_sigma_range, 1e-3, 100.0);
    r.Read("reported_sigma_bearing", &o.reported_sigma_bearing, 1e-4, 3.0);
    r.Finish();
  }
  {
    YamlSection r = top.Section("mapping");
    auto& o = c.mapping;
    r.Read("association_gate_chi2", &o.association_gate_chi2, 0.01, 1000.0);
    r.Read("association_count_bias", &o.association_count_bias, 0.0, 100.0);
    r.Read("false_positive_rate", &o.false_positive_rate, 1e-6, 0.999);
    r.Read("false_negative_rate", &o.false_negative_rate, 1e-6, 0.999);
    r.Read("vertex_log_prior", &o.vertex_log_prior, -100.0, 0.0);
    r.Read("wall_log_prior", &o.wall_log_prior, -100.0, 0.0);
    r.Read("min_detections", &o.min_detections, 1, 1000);
    r.Read("wall_threshold", &o.wall_threshold, 0.01, 0.99);
    r.Read("wall_skip_damping", &o.wall_skip_damping, 0.0, 1.0);
    r.Read("wall_on_segment_tolerance", &o.wall_on_segment_tolerance, 0.0, 100.0);
    r.Read("wall_past_detection_min", &o.wall_past_detection_min);
    r.Read("edge_log_floor", &o.edge_log_floor, -100.0, -1e-6);
    r.Read("mcmc_samples", &o.mcmc_samples, 0, 100000);
    r.Read("mcmc_window", &o.mcmc_window, 1, 1000000);
    r.Read("defer_to_mcmc", &o.defer_to_mcmc);
    r.Read("max_range", &o.max_range, 1.0, 1e4);
    r.Read("star_rebuild_tolerance", &o.star_rebuild_tolerance, 0.0, 100.0);
    r.Read("union_block", &o.union_block, 1, 100000);
    r.Read("frontier_wall_tolerance", &o.frontier_wall_tolerance, 0.0, 100.0);
    r.Read("open_sample_step", &o.open_sample_step, 1e-3, 0.5);
    r.Read("frontier_split_angle", &o.frontier_split_angle, 0.0, core::kPi);
    r.Read("frontier_split_min_length", &o.frontier_split_min_length, 0.0, 1000.0);
    r.Read("open_frontier_reach", &o.open_frontier_reach, 0.0, 1000.0);
    r.Read("known_space_candidates", &o.known_space_candidates);
    r.Finish();
  }
  {
    YamlSection p = top.Section("picture");
    p.Read("pixels_per_unit", &c.picture.pixels_per_unit, 0.1, 50.0);
    p.Read("max_pixels", &c.picture.max_pixels, 100, 20000);
    p.Finish();
  }
  {
    YamlSection pl = top.Section("planning");
    pl.Read("inflation_radius", &c.planning.inflation_radius, 0.01, 100.0);
    pl.Read("clearance", &c.planning.clearance, 0.0, 100.0);
    pl.Read("frontier_min_length", &c.planning.frontier_min_length, 0.0, 1000.0);
    pl.Read("frontier_setback", &c.planning.frontier_setback, 0.01, 100.0);
    pl.Read("frontier_row_gap", &c.planning.frontier_row_gap, 0.0, 1000.0);
    pl.Read("frontier_row_tolerance", &c.planning.frontier_row_tolerance, 0.01, 100.0);
    pl.Finish();
  }
  {
    YamlSection r = top.Section("search");
    SearchOptions& o = c.search;
    r.Read("stuck_steps", &o.stuck_steps, 1, 1000);
    r.Read("unreachable_steps", &o.unreachable_steps, 1, 100000);
    r.Read("success_iou", &o.success_iou, 0.0, 1.0);
    r.Read("switch_ratio", &o.switch_ratio, 1.0, 100.0);
    r.Read("switch_margin", &o.switch_margin, 0.0, 10000.0);
    r.Read("give_up_distance", &o.give_up_distance, 0.01, 1000.0);
    r.Read("give_up_steps", &o.give_up_steps, 1, 100000);
    r.Read("push_distance", &o.push_distance, 0.0, 1000.0);
    r.Read("give_up_reach", &o.give_up_reach, 0.0, 1000.0);
    r.Read("give_up_probe_radius", &o.give_up_probe_radius, 0.0, 100000.0);
    r.Finish();
  }
  {
    YamlSection b = top.Section("bench");
    b.Read("name", &c.bench.name);
    for (YamlSection row : b.Sequence("rows")) {
      BenchRow r;
      std::string kind = "labyrinth";
      row.Read("kind", &kind);
      const auto k = core::ParseWorldKind(kind);
      if (!k || *k == core::WorldKind::kCustom) row.Fail("kind", kind, "unknown world kind (labyrinth, office_park, guided_maze)");
      r.kind = *k;
      row.Read("agents", &r.agents, 1, 16);
      row.Finish();
      c.bench.rows.push_back(r);
    }
    b.Read("first_seed", &c.bench.first_seed);
    b.Read("num_seeds", &c.bench.num_seeds, 0, 1000000);
    b.Read("max_steps", &c.bench.max_steps, 1, 100000);
    b.Read("mcmc_every", &c.bench.mcmc_every, 0, 100000);
    b.Read("open_world_mcmc_every", &c.bench.open_world_mcmc_every, 1, 100000);
    b.Read("pictures", &c.bench.pictures);
    b.Read("videos", &c.bench.videos);
    b.Finish();
  }
  {
    YamlSection d = top.Section("demo");
    std::vector<std::string> kinds;
    if (d.Has("kinds")) {
      d.Read("kinds", &kinds);
      c.demo.kinds.clear();
      for (const auto& k : kinds) {
        auto kind = core::ParseWorldKind(k);
        if (!kind || *kind == core::WorldKind::kCustom)
          d.Fail("kinds", k, "unknown world kind (labyrinth, office_park, guided_maze)");
        c.demo.kinds.push_back(*kind);
      }
    }
    d.Read("seed", &c.demo.seed);
    d.Read("out_dir", &c.demo.out_dir);
    d.Finish();
  }
  top.Finish();
  Validate(c);
  return c;
}

Config LoadConfig(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw core::ConfigError(path, "<file>", "", "not a readable file");
  std::ifstream in(path);
  if (!in) throw core::ConfigError(path, "<file>", "", "cannot open the config file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ParseConfig(ss.str(), path);
}

}  // namespace toponav::experiments

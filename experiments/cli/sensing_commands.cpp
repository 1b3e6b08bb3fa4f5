#include "experiments/cli/sensing_commands.h"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "experiments/cli/common.h"
#include "experiments/cli_parse.h"
#include "experiments/experiments.h"
#include "experiments/map_json.h"
#include "sim/sim.h"

namespace toponav::cli {

namespace fs = std::filesystem;

namespace {

nlohmann::json ObservationJson(const core::Pose2& pose, const std::vector<sim::VisibleVertex>& visible,
                               const core::Ring& poly) {
  nlohmann::json j;
  j["pose"] = {{"x", pose.x}, {"y", pose.y}, {"yaw", pose.yaw}};
  j["visible_vertices"] = nlohmann::json::array();
  for (const auto& v : visible)
    j["visible_vertices"].push_back({{"ring", v.ref.ring},
                                     {"index", v.ref.index},
                                     {"x", v.position.x},
                                     {"y", v.position.y},
                                     {"range", v.range},
                                     {"bearing", v.bearing},
                                     {"label", core::ToString(v.label)}});
  j["visibility_polygon"] = nlohmann::json::array();
  for (const auto& p : poly) j["visibility_polygon"].push_back({p.x, p.y});
  return j;
}


// ---------------------------------------------------------------- observe

struct ObserveArgs : WorldSource {
  std::string png, model;
  double max_range = 0;
  bool sensor = false;
};

nlohmann::json DetectionsJson(const core::Observation& ob) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& d : ob.detections) {
    const core::Vec2 p = core::DetectionPosition(ob.pose, d);
    out.push_back(
        {{"x", p.x},
         {"y", p.y},
         {"range", d.range},
         {"bearing", d.bearing},
         {"labels",
          {{"right_gap", d.labels[0]}, {"corner", d.labels[1]}, {"left_gap", d.labels[2]}, {"point", d.labels[3]}}},
         {"sigma_range", std::sqrt(d.polar.xx)},
         {"sigma_bearing", std::sqrt(d.polar.yy)}});
  }
  return out;
}

// The ground truth at a pose; with --sensor (or --model), also what the config's sensor reports there.
int RunObserve(const ObserveArgs& a) {
  const experiments::Config cfg = LoadWithModel(a.config, a.model);
  const core::World w = WorldFromSource(a, cfg);
  const core::Pose2 pose = StartAtPose(w, a.pose).start;
  const sim::RayCaster caster(w);
  const double range = a.max_range > 0 ? a.max_range : std::numeric_limits<double>::infinity();
  const auto visible = caster.VisibleVertices(pose, range);
  const core::Ring poly = caster.VisibilityPolygon(pose.position());
  nlohmann::json j = ObservationJson(pose, visible, poly);
  core::Observation ob;
  if (a.sensor || !a.model.empty()) {
    experiments::SensorSetup setup;
    setup.world = &w;
    setup.render = cfg.render;
    setup.goal = w.goal;
    setup.seed = experiments::ParseSeed(a.seed);
    ob = experiments::CreateSensor(experiments::SensorFor(cfg, w), setup)->Observe(pose, 0);
    j["sensor"] = experiments::ToString(cfg.sensor.kind);
    j["detections"] = DetectionsJson(ob);
  }
  std::cout << j.dump(1) << "\n";
  if (!a.png.empty()) {
    experiments::DrawObservationPicture(w, pose, visible, poly, cfg.picture, a.png, ob.detections);
    std::cerr << "wrote " << a.png << "\n";
  }
  return 0;
}

// ---------------------------------------------------------------- render

struct RenderArgs : WorldSource {
  std::string out = "pano.png", depth, ids, sequence;
  int poses = 0;
  double spacing = 0;
};

// The guiding path where there is one, otherwise a shortest clear path from the start to the goal.
std::vector<core::Vec2> PathToGoal(const core::World& w, const experiments::Config& cfg) {
  std::vector<core::Vec2> path = w.guide_path;
  if (path.size() < 2) path = sim::FreePath(w, w.start.position(), w.goal, cfg.motion.agent_radius * 3);
  if (path.size() < 2) throw core::DataError("<world>", "no clear path from the start to the goal");
  return path;
}

// A recording along the path to the goal: --poses panoramas, or one every --spacing units (default: the
// motion step).
int RenderSequence(const RenderArgs& a, const core::World& w, const experiments::Config& cfg,
                   const sim::Renderer& renderer) {
  const auto path = PathToGoal(w, cfg);
  const double spacing = a.spacing > 0 ? a.spacing : cfg.motion.step_length;
  const int count = a.poses > 0 ? a.poses : 1 + int(std::ceil(core::PolylineLength(path) / spacing));
  const auto poses = sim::PosesAlong(path, count);
  std::vector<core::Panorama> panos;
  const auto t0 = Clock::now();
  for (const auto& pose : poses) panos.push_back(renderer.Render(pose));
  const double ms = MsSince(t0);
  EnsureDir(a.sequence);
  experiments::WriteRecording(a.sequence, poses, panos);
  fmt::print("wrote {} panoramas ({:.1f} ms each) and {}/poses.csv\n", panos.size(), ms / double(panos.size()),
             a.sequence);
  return 0;
}

int RunRender(const RenderArgs& a) {
  const experiments::Config cfg = LoadOrDefault(a.config);
  const core::World w = WorldFromSource(a, cfg);
  const sim::Renderer renderer(w, cfg.render);
  if (!a.sequence.empty()) return RenderSequence(a, w, cfg, renderer);
  if (a.poses > 0) {  // a contact sheet of K panoramas along the path to the goal
    std::vector<sim::Panorama> panos;
    std::vector<std::string> captions;
    double total_ms = 0;
    for (const auto& pose : sim::PosesAlong(PathToGoal(w, cfg), a.poses)) {
      const auto t0 = Clock::now();
      panos.push_back(renderer.Render(pose));
      total_ms += MsSince(t0);
      captions.push_back(fmt::format("x {:.1f}  y {:.1f}  yaw {:.2f}", pose.x, pose.y, pose.yaw));
    }
    experiments::WriteContactSheet(panos, captions, a.out);
    fmt::print("wrote {} ({} panoramas of {}x{}, {:.1f} ms each)\n", a.out, panos.size(), cfg.render.width,
               cfg.render.height, total_ms / double(panos.size()));
    return 0;
  }
  const core::Pose2 pose = StartAtPose(w, a.pose).start;
  const int outputs =
      sim::kRenderRgb | (a.depth.empty() ? 0 : sim::kRenderDepth) | (a.ids.empty() ? 0 : sim::kRenderIds);
  const auto t0 = Clock::now();
  const sim::Panorama pano = renderer.Render(pose, outputs);
  const double ms = MsSince(t0);
  experiments::WritePanoramaPng(pano, a.out);
  if (!a.depth.empty()) experiments::WriteDepthPng(pano, 100.0, a.depth);
  if (!a.ids.empty()) {
    std::ofstream out(a.ids);
    if (!out) throw core::DataError(a.ids, "cannot open for writing");
    out << "# obstacle id per pixel, " << pano.height << " rows x " << pano.width
        << " columns; -1 none, ring*65536+edge for walls, 1073741824+i for clutter item i\n";
    for (int r = 0; r < pano.height; ++r)
      for (int c = 0; c < pano.width; ++c)
        out << pano.ids[size_t(r) * pano.width + c] << (c + 1 < pano.width ? ' ' : '\n');
  }
  fmt::print("wrote {} ({}x{}, {} triangles, rendered in {:.1f} ms)\n", a.out, pano.width, pano.height,
             renderer.num_triangles(), ms);
  return 0;
}

// ---------------------------------------------------------------- map

struct MapArgs : WorldSource {
  std::string out = "results/map", seeds, images, poses_csv, model;
  experiments::MapDriveOptions drive;
  bool no_mcmc = false;
};

// A world for the picture of a recorded map when none is given: no walls, bounds around the path and the map.
core::World BareWorld(const experiments::RecordedMapResult& r) {
  core::World w;
  core::Aabb2 b{r.path.front(), r.path.front()};
  auto grow = [&](const core::Vec2& p) {
    b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y)};
    b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y)};
  };
  for (const auto& p : r.path) grow(p);
  for (const auto& v : r.view.vertices) grow(v.position);
  for (const auto& poly : r.view.known_space)
    for (const auto& p : poly.outer) grow(p);
  w.bounds = b;
  w.start = core::Pose2{r.path.front().x, r.path.front().y, 0.0};
  w.goal = r.path.back();
  return w;
}

// The map from a recording (--images): the config's sensor becomes kind recorded on it.
int RunRecordedMap(const MapArgs& a) {
  experiments::Config cfg = LoadOrDefault(a.config);
  cfg.sensor.kind = experiments::SensorKind::kRecorded;
  cfg.sensor.images = a.images;
  cfg.sensor.poses = a.poses_csv;
  if (!a.model.empty()) cfg.sensor.learned.model = a.model;
  const auto recording = experiments::ReadRecording(a.images, a.poses_csv);
  auto sensor = experiments::CreateSensor(cfg.sensor, {});
  experiments::RecordedMapOptions o;
  o.mcmc_every = a.no_mcmc ? 0 : a.drive.mcmc_every;
  o.seed = experiments::ParseSeed(a.seed);
  EnsureDir(a.out);
  const auto t0 = Clock::now();
  const auto r = experiments::BuildRecordedMap(recording, *sensor, cfg.mapping, o);
  const double ms = MsSince(t0);
  const bool has_world = !a.world_file.empty() || !a.kind.empty();
  const core::World w = has_world ? WorldFromSource(a, cfg) : BareWorld(r);
  experiments::DrawMapPicture(w, r.view, {r.path}, cfg.picture, (fs::path(a.out) / "map.png").string());
  nlohmann::json j;
  j["images"] = a.images;
  j["frames"] = r.frames;
  j["map_vertices"] = r.view.vertices.size();
  j["map_walls"] = r.view.walls.size();
  j["frontiers"] = r.view.frontiers.size();
  j["log_posterior"] = r.log_posterior;
  if (has_world) j["known_space_iou"] = experiments::KnownSpaceIoU(w, r.view);
  j["mean_observe_ms"] = r.mean_observe_ms;
  j["mean_update_ms"] = r.mean_update_ms;
  j["wall_time_ms"] = ms;
  j["map"] = experiments::MapGeometryJson(r.view);
  WriteTextFile((fs::path(a.out) / "map.json").string(), j.dump(1) + "\n");
  fmt::print(
      "{} frames: vertices {}  walls {}  frontiers {}{}  detect {:.1f} ms/frame  map {:.1f} ms/frame  total {:.1f} s "
      "-> {}/map.png, map.json\n",
      r.frames, r.view.vertices.size(), r.view.walls.size(), r.view.frontiers.size(),
      has_world ? fmt::format("  IoU {:.4f}", j["known_space_iou"].get<double>()) : "", r.mean_observe_ms,
      r.mean_update_ms, ms / 1000, a.out);
  return 0;
}

// What `map` writes to map.json for one drive.
nlohmann::json MapDriveJson(uint64_t seed, const experiments::MapDriveResult& r, double ms) {
  nlohmann::json j;
  j["seed"] = seed;
  j["steps"] = r.steps;
  j["known_space_iou"] = r.known_space_iou;
  if (r.building_iou) j["building_iou"] = *r.building_iou;
  j["map_vertices"] = r.map_vertices;
  j["false_vertices"] = r.false_vertices;
  j["mean_vertex_error"] = r.mean_vertex_error;
  j["rejected_vertices"] = r.view.rejected.size();
  j["map_walls"] = r.map_walls;
  j["false_walls"] = r.false_walls;
  j["walls_across_free_space"] = r.walls_across_free_space;
  j["walls_across_corridor"] = r.walls_across_corridor;
  j["frontiers"] = r.view.frontiers.size();
  j["log_posterior"] = r.log_posterior;
  j["mean_update_ms"] = r.mean_update_ms;
  j["mean_mcmc_ms"] = r.mean_mcmc_ms;
  j["wall_time_ms"] = ms;
  j["map"] = experiments::MapGeometryJson(r.view);
  return j;
}

int RunMap(MapArgs a) {
  if (!a.images.empty()) return RunRecordedMap(a);
  const experiments::Config cfg = LoadOrDefault(a.config);
  if (a.no_mcmc) a.drive.mcmc_every = 0;
  EnsureDir(a.out);
  const std::vector<uint64_t> seeds =
      a.seeds.empty() ? std::vector<uint64_t>{experiments::ParseSeed(a.seed)} : experiments::ParseSeeds(a.seeds);
  double iou_sum = 0, false_sum = 0, vert_sum = 0, wall_false = 0, wall_sum = 0, error_sum = 0, across_sum = 0,
         cut_sum = 0;
  double building_sum = 0;  // over the open worlds
  int open_worlds = 0;
  for (uint64_t seed : seeds) {
    WorldSource src = a;
    src.seed = std::to_string(seed);
    const core::World w = StartAtPose(WorldFromSource(src, cfg), a.pose);
    experiments::MapDriveOptions d = a.drive;
    d.seed = seed;
    const auto t0 = Clock::now();
    const experiments::MapDriveResult r = experiments::RunMapDrive(w, cfg, d);
    const double ms = MsSince(t0);
    const std::string stem = seeds.size() == 1 ? "map" : fmt::format("map_s{}", seed);
    experiments::DrawMapPicture(w, r.view, {r.agent_path}, cfg.picture, (fs::path(a.out) / (stem + ".png")).string());
    WriteTextFile((fs::path(a.out) / (stem + ".json")).string(), MapDriveJson(seed, r, ms).dump(1) + "\n");
    fmt::print(
        "seed {:>6}: {:>4} steps  IoU {:.4f}{}  vertices {:>3} ({} false, {} rejected, error {:.2f})  "
        "walls {:>3} ({} false, {} into free space, {} across a corridor)  update {:.2f} ms  mcmc {:.1f} ms  total "
        "{:.1f} s\n",
        seed, r.steps, r.known_space_iou, r.building_iou ? fmt::format(" (buildings {:.4f})", *r.building_iou) : "",
        r.map_vertices, r.false_vertices, r.view.rejected.size(), r.mean_vertex_error, r.map_walls, r.false_walls,
        r.walls_across_free_space, r.walls_across_corridor, r.mean_update_ms, r.mean_mcmc_ms, ms / 1000);
    iou_sum += r.known_space_iou;
    if (r.building_iou) building_sum += *r.building_iou, ++open_worlds;
    false_sum += r.false_vertices;
    error_sum += r.mean_vertex_error * (r.map_vertices - r.false_vertices);  // pooled over matched vertices
    vert_sum += r.map_vertices;
    wall_false += r.false_walls;
    across_sum += r.walls_across_free_space;
    cut_sum += r.walls_across_corridor;
    wall_sum += r.map_walls;
  }
  if (seeds.size() > 1)
    fmt::print(
        "{} seeds: mean IoU {:.4f}{}, false vertices {:.1f} % ({} of {}), false walls {:.1f} % ({} into free space, "
        "{} across a corridor), vertex error {:.2f}\n",
        seeds.size(), iou_sum / double(seeds.size()),
        open_worlds > 0 ? fmt::format(" (buildings {:.4f})", building_sum / open_worlds) : "",
        100.0 * false_sum / std::max(1.0, vert_sum), false_sum, vert_sum, 100.0 * wall_false / std::max(1.0, wall_sum),
        across_sum, cut_sum, error_sum / std::max(1.0, vert_sum - false_sum));
  return 0;
}

// ---------------------------------------------------------------- command-line options

CLI::App* AddObserveCommand(CLI::App& app, ObserveArgs* a) {
  CLI::App* observe = app.add_subcommand(
      "observe",
      "Print the ground-truth observation from a pose as JSON (with --sensor: what the config sensor detects)");
  AddWorldSourceOptions(observe, a, "YAML config with generator options");
  observe->add_option("--max-range", a->max_range, "Only vertices closer than this (default: unlimited)")
      ->check(CLI::PositiveNumber);
  observe->add_option("--png", a->png, "Also draw the observation to this PNG");
  observe->add_flag("--sensor", a->sensor,
                    "Also report the detections of the config's sensor: (JSON 'detections'; squares in the PNG)");
  observe->add_option("--model", a->model, "... of the learned sensor with this model file (implies --sensor)");
  return observe;
}

CLI::App* AddRenderCommand(CLI::App& app, RenderArgs* a) {
  CLI::App* render =
      app.add_subcommand("render", "Render the robot's 360-degree panorama (PNG) at a pose, or a contact sheet");
  AddWorldSourceOptions(render, a, "YAML config (render: width, height, camera_height, ...)");
  render->add_option("--out", a->out, "Output PNG")->capture_default_str();
  render->add_option("--poses", a->poses, "Instead: a contact sheet of this many panoramas along a path to the goal")
      ->check(CLI::Range(1, 100000));
  render->add_option("--sequence", a->sequence,
                     "Instead: a recording along the path to the goal: DIR/pano_NNNNN.png and DIR/poses.csv "
                     "(--poses of them, or one every --spacing units)");
  render
      ->add_option("--spacing", a->spacing, "With --sequence: world units between panoramas (default: the motion step)")
      ->check(CLI::PositiveNumber);
  render->add_option("--depth", a->depth,
                     "Also write the depth panorama as a grey PNG (bright = near, 100 units = black)");
  render->add_option("--ids", a->ids, "Also write the obstacle-id image as text (one row per line)");
  return render;
}

CLI::App* AddMapCommand(CLI::App& app, MapArgs* a) {
  CLI::App* map = app.add_subcommand("map",
                                     "Drive an agent along a path with the config's sensor and build the probabilistic "
                                     "map, or build it from recorded panoramas");
  AddWorldSourceOptions(map, a, "YAML config (sensor:, mapping:, motion:)");
  map->add_option("--seeds", a->seeds, "Several seeds A-B (files then named map_sSEED)");
  map->add_option("--path", a->drive.path, "Path to drive: tour (whole free space), guide, goal")
      ->capture_default_str();
  map->add_option("--steps", a->drive.max_steps, "At most this many steps")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  map->add_option("--tour-spacing", a->drive.tour_spacing,
                  "Tour: visit the free points of a grid this fine (world units; default 20, 11 in a guided maze)")
      ->check(CLI::Range(1.0, 1000.0));
  map->add_option("--mcmc-every", a->drive.mcmc_every, "MCMC every this many steps")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  map->add_flag("--no-mcmc", a->no_mcmc, "Build the map without the posterior (every potential vertex kept)");
  map->add_option("--out", a->out, "Output directory: map.png and map.json")->capture_default_str();
  map->add_option("--images", a->images,
                  "Instead: build the map from a recording (panoramas + poses.csv, e.g. from render --sequence) "
                  "with the learned sensor; --world/--kind then only draw the true world and score the map");
  map->add_option("--poses", a->poses_csv, "With --images: the poses file (default: DIR/poses.csv)");
  map->add_option("--model", a->model, "With --images: the model file (default: the config's sensor.model)");
  return map;
}

}  // namespace

struct SensingCommands::Impl {
  ObserveArgs observe;
  RenderArgs render;
  MapArgs map;
  CLI::App *observe_cmd = nullptr, *render_cmd = nullptr, *map_cmd = nullptr;
};

SensingCommands::SensingCommands(CLI::App& app) : impl_(std::make_unique<Impl>()) {
  impl_->observe_cmd = AddObserveCommand(app, &impl_->observe);
  impl_->render_cmd = AddRenderCommand(app, &impl_->render);
  impl_->map_cmd = AddMapCommand(app, &impl_->map);
}
SensingCommands::~SensingCommands() = default;

std::optional<int> SensingCommands::Run() {
  if (*impl_->observe_cmd) return RunObserve(impl_->observe);
  if (*impl_->render_cmd) return RunRender(impl_->render);
  if (*impl_->map_cmd) return RunMap(impl_->map);
  return std::nullopt;
}

}  // namespace toponav::cli

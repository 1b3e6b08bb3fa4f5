#include "sim/training_data.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/rng.h"
#include "sim/raycast.h"

namespace toponav::sim {

const core::OptionFields<DatagenOptions>& DatagenOptions::Fields() {
  using O = DatagenOptions;
  static const core::OptionFields<O> fields{
      {"train_first_seed", &O::train_first_seed, 0, 9999},
      {"train_num_seeds", &O::train_num_seeds, 0, 10000},
      {"val_first_seed", &O::val_first_seed, 0, 9999},
      {"val_num_seeds", &O::val_num_seeds, 0, 10000},
      {"samples_per_world", &O::samples_per_world, 1, 100000},
      {"min_clearance", &O::min_clearance, 0.0, 50.0},
      {"near_wall_fraction", &O::near_wall_fraction, 0.0, 1.0},
      {"near_wall_clearance", &O::near_wall_clearance, 0.0, 100.0},
  };
  return fields;
}

void CheckTrainingSeeds(const std::string& prefix, int train_first, int train_num, int val_first, int val_num) {
  auto fail = [&](const char* key, int v, const std::string& why) {
    throw core::ConfigError("<options>", prefix + key, std::to_string(v), why);
  };
  // Tuning data only: benchmark worlds (seeds from 10000) are never trained on.
  if (train_first + train_num > 10000)
    fail("train_num_seeds", train_num, "training worlds must have seeds below 10000");
  if (val_first + val_num > 10000) fail("val_num_seeds", val_num, "validation worlds must have seeds below 10000");
  const bool overlap = val_first < train_first + train_num && train_first < val_first + val_num;
  if (overlap && train_num > 0 && val_num > 0)
    fail("val_first_seed", val_first, "validation seeds must not overlap the training seeds");
}

void DatagenOptions::Validate() const {
  core::CheckRanges(*this, Fields(), "datagen.");
  CheckTrainingSeeds("datagen.", train_first_seed, train_num_seeds, val_first_seed, val_num_seeds);
  if (kinds.empty()) throw core::ConfigError("<options>", "datagen.kinds", "[]", "list at least one world kind");
  if (near_wall_fraction > 0 && near_wall_clearance <= min_clearance)
    throw core::ConfigError("<options>", "datagen.near_wall_clearance", std::to_string(near_wall_clearance),
                            "must exceed datagen.min_clearance when datagen.near_wall_fraction is above 0");
}

nlohmann::json DatagenJson(const DatagenOptions& o) {
  std::vector<std::string> kinds;
  for (auto k : o.kinds) kinds.push_back(core::ToString(k));
  return {{"kinds", kinds},
          {"train_seeds", {o.train_first_seed, o.train_first_seed + o.train_num_seeds - 1}},
          {"val_seeds", {o.val_first_seed, o.val_first_seed + o.val_num_seeds - 1}},
          {"samples_per_world", o.samples_per_world},
          {"min_clearance", o.min_clearance},
          {"near_wall_fraction", o.near_wall_fraction},
          {"near_wall_clearance", o.near_wall_clearance}};
}

const char* ToString(Split split) { return split == Split::kTrain ? "train" : "val"; }

std::vector<SampleId> ListSamples(const DatagenOptions& o, Split split) {
  const int first = split == Split::kTrain ? o.train_first_seed : o.val_first_seed;
  const int count = split == Split::kTrain ? o.train_num_seeds : o.val_num_seeds;
  std::vector<SampleId> out;
  for (int s = 0; s < count; ++s)
    for (const auto kind : o.kinds)
      for (int i = 0; i < o.samples_per_world; ++i) out.push_back({split, kind, uint64_t(first + s), i});
  return out;
}

struct WorldSampler::Impl {
  core::World world;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<RayCaster> caster;
  core::RangeBearingGrid grid;
  DatagenOptions poses;
};

WorldSampler::WorldSampler(core::WorldKind kind, uint64_t world_seed, const WorldOptions& worlds,
                           const RenderOptions& render, const core::RangeBearingGrid& grid, const DatagenOptions& poses)
    : impl_(std::make_unique<Impl>()) {
  impl_->world = GenerateWorld(kind, worlds, world_seed);
  impl_->renderer = std::make_unique<Renderer>(impl_->world, render);
  impl_->caster = std::make_unique<RayCaster>(impl_->world);
  impl_->grid = grid;
  impl_->poses = poses;
}
WorldSampler::~WorldSampler() = default;

core::Pose2 SamplePose(const core::World& w, const SampleId& id, const DatagenOptions& o) {
  // The pose is a pure function of the sample: its own random stream.
  core::Rng rng(core::DeriveSeed(core::DeriveSeed(id.world_seed, uint64_t(id.kind) + 1),
                                 uint64_t(id.index) * 2 + uint64_t(id.split)));
  // Drawn first only when asked for, so the poses of uniform data stay what they were.
  const bool near_wall = o.near_wall_fraction > 0 && rng.Uniform(0.0, 1.0) < o.near_wall_fraction;
  const double max_clearance = near_wall ? o.near_wall_clearance : std::numeric_limits<double>::infinity();
  for (int tries = 0; tries < 100000; ++tries) {
    const core::Vec2 p{rng.Uniform(w.bounds.min.x, w.bounds.max.x), rng.Uniform(w.bounds.min.y, w.bounds.max.y)};
    if (!core::IsFree(w, p, true)) continue;
    const double clearance = core::SignedDistance(w, p, true);
    if (clearance >= o.min_clearance && clearance <= max_clearance)
      return {p.x, p.y, rng.Uniform(-core::kPi, core::kPi)};
  }
  throw core::DataError("<datagen>", std::string(core::ToString(id.kind)) + " seed " + std::to_string(id.world_seed) +
                                         ": no free pose with clearance " + std::to_string(o.min_clearance) +
                                         (near_wall ? " to " + std::to_string(o.near_wall_clearance) : std::string()));
}

Sample WorldSampler::Make(const SampleId& id) const {
  Sample s;
  s.id = id;
  s.pose = SamplePose(impl_->world, id, impl_->poses);
  s.image = impl_->renderer->Render(s.pose);
  s.labels = RasterizeVertexLabels(impl_->caster->VisibleVertices(s.pose, impl_->grid.max_range), impl_->grid);
  return s;
}

}  // namespace toponav::sim

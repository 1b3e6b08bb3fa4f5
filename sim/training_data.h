#pragma once
// Training data for the learned vertex sensor (paper Sec. III-A; vertexnav.md §4.3, §4.6): samples are
// (panorama at a free-space pose with a random heading, vertex labels on the range-bearing grid from the
// ray-cast ground truth).  Every sample is a pure function of (split, world kind, world seed, index), so it
// can be rendered on the fly in training or exported once.  Training and validation worlds come from
// disjoint seed ranges below 10000 (benchmarks use 10000 and up).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/option_fields.h"
#include "core/range_bearing_grid.h"
#include "core/world.h"
#include "sim/render.h"
#include "sim/vertex_labels.h"
#include "sim/worlds.h"

namespace toponav::sim {

// YAML section `datagen:`.
struct DatagenOptions {
  std::vector<core::WorldKind> kinds{core::WorldKind::kLabyrinth, core::WorldKind::kOfficePark};
  int train_first_seed = 0;      // training worlds: seeds train_first_seed .. + train_num_seeds - 1, per kind
  int train_num_seeds = 200;
  int val_first_seed = 5000;     // validation worlds, disjoint from the training ones
  int val_num_seeds = 20;
  int samples_per_world = 25;
  double min_clearance = 2.0;    // poses at least this far from walls and clutter, world units
  // This fraction of the poses lies at most near_wall_clearance from a wall or clutter (where search agents
  // walk: along buildings and walls), the rest anywhere in free space.
  double near_wall_fraction = 0.0;
  double near_wall_clearance = 6.0;  // world units, above min_clearance
  static const core::OptionFields<DatagenOptions>& Fields();
  void Validate() const;         // ranges, seeds below 10000, disjoint splits, at least one kind
};
// The options as JSON: which worlds, splits and poses the data comes from (a dataset's dataset.json and a
// model's metadata both record it).
nlohmann::json DatagenJson(const DatagenOptions& options);

// Throws core::ConfigError (keys prefix + "train_num_seeds", ...) unless both seed ranges lie below 10000 and
// do not overlap.
void CheckTrainingSeeds(const std::string& prefix, int train_first, int train_num, int val_first, int val_num);

enum class Split { kTrain, kVal };
const char* ToString(Split split);

struct SampleId {
  Split split = Split::kTrain;
  core::WorldKind kind = core::WorldKind::kLabyrinth;
  uint64_t world_seed = 0;
  int index = 0;  // within its world
};

// Every sample of a split, world by world (kinds interleaved per seed).
std::vector<SampleId> ListSamples(const DatagenOptions& options, Split split);

struct Sample {
  SampleId id;
  core::Pose2 pose;
  core::Panorama image;
  VertexLabelGrid labels;
};

// The sample's pose in 'world': a free point at least options.min_clearance from walls and clutter (for
// options.near_wall_fraction of the ids also at most options.near_wall_clearance), a random heading; a pure
// function of the id.  Throws core::DataError if none is found.
core::Pose2 SamplePose(const core::World& world, const SampleId& id, const DatagenOptions& options);

// Makes the samples of one world (they share its renderer and ray caster), their poses drawn as 'poses' says.
// Throws core::DataError if no free pose with the clearance can be found.
class WorldSampler {
 public:
  WorldSampler(core::WorldKind kind, uint64_t world_seed, const WorldOptions& worlds, const RenderOptions& render,
               const core::RangeBearingGrid& grid, const DatagenOptions& poses);
  ~WorldSampler();
  Sample Make(const SampleId& id) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace toponav::sim

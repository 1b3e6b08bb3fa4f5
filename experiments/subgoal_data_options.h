#pragma once
// YAML section `subgoal_data:`: the worlds the subgoal network learns from (training and validation ranges
// disjoint, all below 10000), of one kind, and how often a run through them keeps a sample (optimistic runs
// in guided mazes, searches elsewhere: experiments/subgoal_data.h).
#include "core/option_fields.h"
#include "core/world.h"
#include "sim/training_data.h"

namespace toponav::experiments {

struct SubgoalDataOptions {
  core::WorldKind kind = core::WorldKind::kGuidedMaze;  // key `kind`: guided_maze, labyrinth or office_park
  int train_first_seed = 1000;  // training mazes: seeds train_first_seed .. + train_num_seeds - 1
  int train_num_seeds = 100;
  int val_first_seed = 2000;  // validation mazes, disjoint from the training ones
  int val_num_seeds = 10;
  int every = 5;  // steps between samples of a run
  static const core::OptionFields<SubgoalDataOptions>& Fields() {
    using O = SubgoalDataOptions;
    static const core::OptionFields<O> fields{
        {"train_first_seed", &O::train_first_seed, 0, 9999},
        {"train_num_seeds", &O::train_num_seeds, 1, 9999},
        {"val_first_seed", &O::val_first_seed, 0, 9999},
        {"val_num_seeds", &O::val_num_seeds, 1, 9999},
        {"every", &O::every, 1, 1000},
    };
    return fields;
  }
  void Validate() const {
    core::CheckRanges(*this, Fields(), "subgoal_data.");
    sim::CheckTrainingSeeds("subgoal_data.", train_first_seed, train_num_seeds, val_first_seed, val_num_seeds);
  }
};

}  // namespace toponav::experiments

#pragma once
// Small training-data configurations for tests.
#include "sim/training_data.h"

namespace toponav::testing {

// Two training seeds (3, 4) and one validation seed (7000) of the default kinds, 3 samples a world.
inline sim::DatagenOptions TinyDatagen() {
  sim::DatagenOptions o;
  o.train_first_seed = 3;
  o.train_num_seeds = 2;
  o.val_first_seed = 7000;
  o.val_num_seeds = 1;
  o.samples_per_world = 3;
  return o;
}

}  // namespace toponav::testing

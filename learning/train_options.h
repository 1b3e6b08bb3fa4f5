#pragma once
// The options of `toponav train` (YAML section `train:`), header-only so the config reader can hold them
// without linking the learning layer.
#include <cmath>
#include <string>

#include "core/option_fields.h"

namespace toponav::learning {

// YAML section `train:`.
struct TrainOptions {
  double width = 0.25;          // network width multiplier (1.0: the paper's)
  int batch_size = 8;
  int steps = 1000;             // Adam steps in all
  double learning_rate = 1e-3;
  double decay_to = 1.0;  // from step decay_start the learning rate falls along a cosine to learning_rate * decay_to
  int decay_start = 0;          // at the last step (decay_to 1: constant)
  int validate_every = 100;     // steps between validations (and checkpoints)
  int threads = 2;              // CPU threads (0: LibTorch's default)
  bool cuda = false;            // use the GPU if this LibTorch has one
  int seed = 0;                 // initial weights and batch order
  double vertex_weight = 500.0;  // the vertex BCE's weight in the loss (vertexnav.md §4.4: 500); with subgoal,
                                 // the subgoal terms weigh 1 against it
  bool mirror = false;       // mirror each training example in bearing with probability 1/2 (learning::Mirrored)
  bool subgoal = false;      // train the LSP extension (goal input, subgoal outputs) on subgoal examples
  std::string init_from;     // a model file whose weights start a fresh run where names and shapes match
                             // (a vertex model starts a subgoal one: all but the goal's and the finer
                             // block's weights); empty: random weights
  static const core::OptionFields<TrainOptions>& Fields() {
    using O = TrainOptions;
    static const core::OptionFields<O> fields{
        {"width", &O::width, 0.05, 4.0},
        {"batch_size", &O::batch_size, 1, 1024},
        {"steps", &O::steps, 1, 10000000},
        {"learning_rate", &O::learning_rate, 1e-7, 1.0},
        {"decay_to", &O::decay_to, 1e-4, 1.0},
        {"decay_start", &O::decay_start, 0, 10000000},
        {"validate_every", &O::validate_every, 1, 10000000},
        {"threads", &O::threads, 0, 256},
        {"cuda", &O::cuda},
        {"seed", &O::seed, 0, 1000000000},
        {"vertex_weight", &O::vertex_weight, 0.1, 100000.0},
        {"subgoal", &O::subgoal},
        {"mirror", &O::mirror},
    };
    return fields;
  }
  void Validate() const { core::CheckRanges(*this, Fields(), "train."); }
  // The learning rate of step 'step' (0-based) of 'steps'.
  double LearningRate(int step) const {
    if (step <= decay_start) return learning_rate;
    const double t = steps - 1 > decay_start ? double(step - decay_start) / double(steps - 1 - decay_start) : 1.0;
    return learning_rate * (decay_to + (1.0 - decay_to) * 0.5 * (1.0 + std::cos(3.14159265358979323846 * t)));
  }
};

}  // namespace toponav::learning

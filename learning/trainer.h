#pragma once
// Training the vertex network (`toponav train`): examples are kept in memory (the vertex sensor's are rendered
// from the training and validation worlds of sim/training_data.h; the subgoal network's come from the caller,
// with their goals and subgoal labels), batches are drawn in a shuffled order that is a pure function of the
// seed and the step, with a random circular roll in bearing (the image by 4 columns per label column, so labels
// stay exact) and, with train.mirror, a mirror image half of the time.  A rolled example's goal turns with it
// and its subgoal labels by 8 columns (the 64x256 grid).  Progress with loss and ETA; validation every
// validate_every steps.  The best model on validation is DIR/model.pt (with its metadata); DIR/checkpoint.pt
// and DIR/train_state.json let a killed run resume at its last checkpoint (Adam's moments restart there).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "learning/train_options.h"
#include "learning/vertex_model.h"
#include "sim/training_data.h"

namespace toponav::learning {

// One example: a panorama and its vertex labels (32x128); a subgoal network's also have the goal in view and
// the subgoal labels (64x256).
struct TrainingExample {
  core::Panorama image;
  sim::VertexLabelGrid labels;
  GoalInView goal;
  std::optional<core::SubgoalLabelGrid> subgoal;
};

// The example turned by 'cols' label columns: the image by 4 columns each, the subgoal labels by 2, the goal's
// bearing by 'cols' label columns' worth (bearing stays exact).
TrainingExample Rolled(const TrainingExample& example, int cols);

// The example mirrored in bearing (a bearing b goes to -b: the world seen in a mirror along the heading): the
// image's and the grids' columns c to (width - c) % width, right-gap and left-gap labels swapped, the goal's
// bearing negated.  Mirrored twice, an example is itself.
TrainingExample Mirrored(const TrainingExample& example);

// Examples to train on and to validate with, and what they are (JSON: written into the model's notes; a
// resumed run must have the same).
struct TrainingSet {
  std::vector<TrainingExample> train, val;
  std::string identity_json = "{}";
};

// The vertex sensor's examples: rendered from the datagen worlds.
TrainingSet RenderVertexExamples(const sim::DatagenOptions& data, const sim::WorldOptions& worlds,
                                 const sim::RenderOptions& render);

struct TrainProgress {
  int step = 0, steps = 0;
  double train_loss = 0.0;      // mean over the steps since the last report
  double val_loss = -1.0;       // this step's validation loss, or -1
  double best_val_loss = -1.0;
  double seconds = 0.0, eta_seconds = 0.0;
};

struct TrainResult {
  int steps = 0;
  int resumed_from = 0;          // the step a resumed run started at (0: fresh)
  int best_step = 0;
  double best_val_loss = 0.0;
  double seconds = 0.0;          // this run's
  int train_samples = 0, val_samples = 0;
  std::string model_path;
};

// Trains into 'out_dir' (resuming from its checkpoint if one is there and 'fresh' is false).  'report' is
// called after every validation and every 'report_every' steps.  options.subgoal trains the LSP extension
// (every example needs subgoal labels); options.init_from starts a fresh run from a saved model's weights.
TrainResult Train(const TrainingSet& data, const TrainOptions& options, const std::string& out_dir, bool fresh,
                  const std::function<void(const TrainProgress&)>& report, int report_every = 10);
// The vertex sensor's training: Train(RenderVertexExamples(data, worlds, render), ...).
TrainResult Train(const sim::DatagenOptions& data, const sim::WorldOptions& worlds, const sim::RenderOptions& render,
                  const TrainOptions& options, const std::string& out_dir, bool fresh,
                  const std::function<void(const TrainProgress&)>& report, int report_every = 10);

}  // namespace toponav::learning

#pragma once
// Training the vertex network (`toponav train`): samples are rendered from the training and validation
// worlds (sim/training_data.h) once and kept in memory, batches are drawn in a shuffled order that is a pure
// function of the seed and the step, with a random circular roll in bearing (the image by 4 columns per
// label column, so labels stay exact).  Progress with loss and ETA; validation every validate_every steps;
// the best model on validation is DIR/model.pt (with its metadata); DIR/checkpoint.pt and DIR/train_state.json
// let a killed run resume at its last checkpoint (Adam's moments restart there).
#include <cstdint>
#include <functional>
#include <string>

#include "learning/train_options.h"
#include "learning/vertex_model.h"
#include "sim/training_data.h"

namespace toponav::learning {

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
// called after every validation and every 'report_every' steps.
TrainResult Train(const sim::DatagenOptions& data, const sim::WorldOptions& worlds, const sim::RenderOptions& render,
                  const TrainOptions& options, const std::string& out_dir, bool fresh,
                  const std::function<void(const TrainProgress&)>& report, int report_every = 10);

}  // namespace toponav::learning

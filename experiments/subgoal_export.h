#pragma once
// Exporting the subgoal network's training data (experiments/subgoal_data.h) as files a user can open
// elsewhere (README "Training data" documents the layout).
#include <string>

#include "experiments/config.h"
#include "experiments/datagen.h"

namespace toponav::experiments {

// Writes DIR/subgoal_dataset.json, DIR/index.csv (pose, goal in the agent's frame, counts), per split
// DIR/<split>/NNNNNN.png (panorama), NNNNNN_labels.png (vertex labels as `toponav datagen` writes them) and
// NNNNNN_subgoal.csv (the frontier cells of the 64x256 grid: row, col, ps, delta_success, exploration), and
// DIR/contact_sheet.png with the frontier cells drawn on the first panoramas.  Mazes and sampling from
// config.subgoal_data; 'max_samples' > 0 caps each split.
ExportSummary ExportSubgoalDataset(const Config& config, const std::string& out_dir, int max_samples = 0);

}  // namespace toponav::experiments

#pragma once
// The learned vertex sensor as an image detector: the vertex network (a model file written by `toponav
// train`) on each panorama, its output decoded into detections (learning/peaks.h).  Composed with the
// renderer by the sensor factory (`sensor: {kind: learned, model: PATH}`).  A subgoal model given a goal also
// fills the observation's subgoal cells (core::SubgoalCells: Ps a probability, the success and exploration
// costs), which planner 'lsp' averages per frontier.
#include <memory>
#include <string>

#include "core/observation.h"
#include "learning/peaks.h"

namespace toponav::learning {

// Throws core::DataError naming 'model_path' if it is missing or not a vertex-network file.  With
// 'subgoal_path', a second network -- a subgoal model -- fills the cells wherever a goal is given, and the
// vertices still come from the first (its vertex outputs stay the ones it was chosen for); a file that is not
// a subgoal model is a core::DataError naming it.  'mirror_average': each network also runs on the mirrored
// panorama and the two outputs are averaged (learning/mirror_average.h).
std::unique_ptr<core::VertexDetectorInterface> CreateLearnedDetector(const std::string& model_path,
                                                                     const DecodeOptions& decode,
                                                                     const std::string& subgoal_path = "",
                                                                     bool mirror_average = false);

}  // namespace toponav::learning

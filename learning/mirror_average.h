#pragma once
// Test-time mirroring: the network also sees the panorama mirrored in bearing (the goal's bearing negated),
// and its outputs, mirrored back, are averaged with the plain ones.  A mirrored panorama is what the world seen
// in a mirror would give (train.mirror trains on such examples; the maze network was, the search network was
// not); the average is mirror-equivariant and costs a second pass.
#include "core/image.h"
#include "learning/vertex_model.h"

namespace toponav::learning {

// Column c of the panorama moved to column (width - c) mod width: bearing b becomes -b.
core::Panorama MirroredPanorama(const core::Panorama& image);
// An output computed on a mirrored panorama, mirrored back (right and left gap labels swapped).
GridOutput MirroredBack(const GridOutput& out);
SubgoalOutput MirroredBack(const SubgoalOutput& out);
// The cell-by-cell mean of two outputs on the same grid.
GridOutput Mean(const GridOutput& a, const GridOutput& b);
SubgoalOutput Mean(const SubgoalOutput& a, const SubgoalOutput& b);

}  // namespace toponav::learning

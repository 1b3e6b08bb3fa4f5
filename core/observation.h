#pragma once
// What a vertex sensor reports, and the interface every sensor (noisy ground truth, learned CNN) implements,
// so the trial loop does not care which one is behind it.
#include <array>
#include <vector>

#include "core/detection.h"
#include "core/geometry.h"

namespace toponav::core {

// A symmetric 2x2 covariance.
struct Cov2 {
  double xx = 0.0, xy = 0.0, yy = 0.0;
};

// Probabilities of the four labels, index order [right_gap, corner, left_gap, point] (core::VertexLabel).
using LabelProbs = std::array<double, 4>;
LabelProbs OneHot(VertexLabel label);
// Probability that there is no wall on the detection's counter-clockwise side (left gap or point), and on
// its clockwise side (right gap or point) (vertexnav.md §1.2).
inline double NoWallCcw(const LabelProbs& p) { return p[2] + p[3]; }
inline double NoWallCw(const LabelProbs& p) { return p[0] + p[3]; }

struct Detection {
  double range = 0.0;    // from the agent
  double bearing = 0.0;  // relative to the agent's heading, [-pi, pi)
  Cov2 polar;            // covariance of (range, bearing): xx = var(range), yy = var(bearing)
  LabelProbs labels{0.25, 0.25, 0.25, 0.25};
};

struct Observation {
  Pose2 pose;                        // where the agent was (world frame)
  int agent = 0;                     // which agent observed
  std::vector<Detection> detections; // sorted by ascending bearing
};

// World position of a detection seen from 'pose'.
Vec2 DetectionPosition(const Pose2& pose, const Detection& d);
// First-order world covariance of a detection: eigenvalues are var(range) and range^2 * var(bearing).
Cov2 DetectionCovariance(const Pose2& pose, const Detection& d);

class VertexSensorInterface {
 public:
  virtual ~VertexSensorInterface() = default;
  // The observation an agent at 'pose' makes (detections sorted by bearing).
  virtual Observation Observe(const Pose2& pose, int agent) = 0;
};

}  // namespace toponav::core

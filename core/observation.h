#pragma once
// What a vertex sensor reports, and the interfaces behind it: a pose-in sensor (the one the agent loop
// calls: the noisy ground-truth sensor, or a renderer composed with an image detector) and an image detector
// (the learned CNN, a recorded folder's), so the loop does not care which one is behind it.
#include <array>
#include <optional>
#include <vector>

#include "core/detection.h"
#include "core/geometry.h"
#include "core/image.h"

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

// A subgoal network's estimates for one cell of its range-bearing grid (paper Sec. V): the probability that
// the goal can be reached through unknown space there (Ps), the cost of reaching it that way beyond the
// distance to the frontier (delta_success), and the cost of finding out it cannot (exploration); costs in
// world units.
struct SubgoalCell {
  float ps = 0.0f;
  float delta_success = 0.0f;
  float exploration = 0.0f;
};

// A subgoal network's outputs on its range-bearing grid (the convention of core::RangeBearingGrid: row r
// holds the ranges nearest (r + 1) * max_range / rows, column b looks along ColumnToBearing(b, cols)),
// row-major.  Empty for sensors without such outputs.
struct SubgoalCells {
  int rows = 0, cols = 0;
  double max_range = 0.0;
  std::vector<SubgoalCell> values;
  bool empty() const { return values.empty(); }
  // Requires values.size() == rows * cols.
  const SubgoalCell& at(int row, int col) const { return values.at(size_t(row) * size_t(cols) + size_t(col)); }
};

// A range ring's scan from the observation's pose (a short-range sensor a config may declare beside the
// vertex sensor): ray j looks along world direction 2 * pi * j / ranges.size(); ranges[j] is its first hit, or
// max_range where nothing lies within reach.
struct RangeScan {
  double max_range = 0.0;
  std::vector<double> ranges;
  double Angle(size_t j) const;  // the world direction of ray j (radians)
};

// What an agent's motion showed: at 'at' it pressed toward 'toward' and could not pass (contact evidence: a
// wall within 'reach' of 'at' that way is real).
struct Contact {
  Vec2 at;
  Vec2 toward;
  double reach = 0.0;  // world units
};

struct Observation {
  Pose2 pose;                        // where the agent was (world frame)
  int agent = 0;                     // which agent observed
  std::vector<Detection> detections; // sorted by ascending bearing
  SubgoalCells subgoal;              // a subgoal network's estimates (empty unless the sensor gives them)
  std::optional<RangeScan> scan;     // a range ring's scan (only where the config declares one)
};

// World position of a detection seen from 'pose'.
Vec2 DetectionPosition(const Pose2& pose, const Detection& d);
// First-order world covariance of a detection: eigenvalues are var(range) and range^2 * var(bearing).
Cov2 DetectionCovariance(const Pose2& pose, const Detection& d);

// A pose-in sensor: what the agent loop calls every step for every agent.
class VertexSensorInterface {
 public:
  virtual ~VertexSensorInterface() = default;
  // The observation an agent at 'pose' makes (detections sorted by bearing).
  virtual Observation Observe(const Pose2& pose, int agent) = 0;
};

// What an image detector may use beside the image: where the image was taken (to stamp the observation; a
// detector must not use it to look at the world) and, for goal-conditioned networks, the goal relative to
// the agent.
struct DetectionContext {
  Pose2 pose;
  int agent = 0;
  std::optional<Vec2> goal;  // in the agent's frame (x along its heading, y to its left); none: no goal
};
// The goal in the frame of an agent at 'pose'.
Vec2 GoalInAgentFrame(const Pose2& pose, const Vec2& goal);

// Finds vertices in a panorama.  Composed with a renderer (sim::CreateRenderingSensor) it is a pose-in
// sensor; fed from a folder of recorded images it maps a real robot's run.
class VertexDetectorInterface {
 public:
  virtual ~VertexDetectorInterface() = default;
  // The observation in 'image' (detections sorted by bearing), stamped with context.pose and context.agent.
  virtual Observation Detect(const Panorama& image, const DetectionContext& context) = 0;
};

}  // namespace toponav::core

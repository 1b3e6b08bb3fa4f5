#pragma once
// Hand-made observations for mapping tests: exact detections of chosen points, and the square room
// [0,10]^2 whose four corners are seen from inside.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/detection.h"
#include "core/observation.h"
#include "mapping/mapping.h"

namespace toponav::mapping::testing {

using core::Detection;
using core::Observation;
using core::Vec2;

// A detection of world point 'p' seen from 'pose', exact, with the given label and a small covariance.
inline Detection Det(const core::Pose2& pose, Vec2 p, core::VertexLabel label, double sr = 0.3, double st = 0.02) {
  Detection d;
  d.range = core::Distance(pose.position(), p);
  d.bearing = core::WrapAngle(std::atan2(p.y - pose.y, p.x - pose.x) - pose.yaw);
  d.polar = {sr * sr, 0, st * st};
  d.labels = core::OneHot(label);
  return d;
}

inline Observation Obs(const core::Pose2& pose, std::vector<Detection> dets) {
  Observation z;
  z.pose = pose;
  z.detections = std::move(dets);
  std::sort(z.detections.begin(), z.detections.end(), [](auto& a, auto& b) { return a.bearing < b.bearing; });
  return z;
}

// The four corners of the square room [0,10]^2 seen from inside: all corners.
inline std::vector<Detection> SquareCorners(const core::Pose2& pose) {
  std::vector<Detection> d;
  for (Vec2 c : {Vec2{0, 0}, Vec2{10, 0}, Vec2{10, 10}, Vec2{0, 10}})
    d.push_back(Det(pose, c, core::VertexLabel::kCorner));
  return d;
}
inline Observation SquareFromInside(const core::Pose2& pose) { return Obs(pose, SquareCorners(pose)); }

inline MapperOptions SquareOptions() {
  MapperOptions o;
  o.world_bounds = core::Aabb2{{-1, -1}, {11, 11}};
  return o;
}

}  // namespace toponav::mapping::testing

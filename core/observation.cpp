#include "core/observation.h"

#include <algorithm>
#include <cmath>

namespace toponav::core {

double RangeScan::Angle(size_t j) const { return 2.0 * kPi * double(j) / double(ranges.size()); }

LabelProbs OneHot(VertexLabel label) {
  LabelProbs p{0, 0, 0, 0};
  p[static_cast<size_t>(label)] = 1.0;
  return p;
}

Vec2 DetectionPosition(const Pose2& pose, const Detection& d) {
  const double phi = pose.yaw + d.bearing;
  return {pose.x + d.range * std::cos(phi), pose.y + d.range * std::sin(phi)};
}

Cov2 DetectionCovariance(const Pose2& pose, const Detection& d) {
  // J = d(x, y)/d(r, theta) = [[c, -r s], [s, r c]];  Sigma = J diag-or-full(polar) J^T.
  const double phi = pose.yaw + d.bearing, c = std::cos(phi), s = std::sin(phi), r = d.range;
  const double a = d.polar.xx, b = d.polar.xy, t = d.polar.yy;
  const double j00 = c, j01 = -r * s, j10 = s, j11 = r * c;
  Cov2 out;
  out.xx = j00 * j00 * a + 2 * j00 * j01 * b + j01 * j01 * t;
  out.xy = j00 * j10 * a + (j00 * j11 + j01 * j10) * b + j01 * j11 * t;
  out.yy = j10 * j10 * a + 2 * j10 * j11 * b + j11 * j11 * t;
  return out;
}

Vec2 GoalInAgentFrame(const Pose2& pose, const Vec2& goal) {
  const Vec2 d = goal - pose.position();
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return {c * d.x + s * d.y, -s * d.x + c * d.y};
}

}  // namespace toponav::core

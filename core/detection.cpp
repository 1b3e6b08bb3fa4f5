#include "core/detection.h"

#include <cmath>

#include "core/geometry.h"

namespace toponav::core {

const char* ToString(VertexLabel label) {
  switch (label) {
    case VertexLabel::kRightGap: return "right_gap";
    case VertexLabel::kCorner: return "corner";
    case VertexLabel::kLeftGap: return "left_gap";
    case VertexLabel::kPoint: return "point";
  }
  return "?";
}

char ToChar(VertexLabel label) { return "rclp"[static_cast<int>(label)]; }

VertexLabel LabelFromWalls(bool wall_ccw, bool wall_cw) {
  if (wall_ccw && wall_cw) return VertexLabel::kCorner;
  if (wall_cw) return VertexLabel::kLeftGap;
  if (wall_ccw) return VertexLabel::kRightGap;
  return VertexLabel::kPoint;
}

double ColumnToBearing(double column, int width) { return -kPi + 2.0 * kPi * column / width; }

int BearingToColumn(double bearing, int width) {
  const double c = (WrapAngle(bearing) + kPi) * width / (2.0 * kPi);
  int j = static_cast<int>(std::lround(c)) % width;
  return j < 0 ? j + width : j;
}

}  // namespace toponav::core

#pragma once
// Vertex labels and the bearing convention shared by the ray caster, the renderer and the learned sensor.
#include <array>

namespace toponav::core {

// The 4-way vertex label of the paper's sensor (vertexnav.md §1.2), index order [r, c, l, p]:
//  kRightGap: the wall continues on the counter-clockwise (left) side of the vertex only;
//  kCorner:   walls on both sides;
//  kLeftGap:  the wall continues on the clockwise (right) side only;
//  kPoint:    no wall on either side.
enum class VertexLabel { kRightGap = 0, kCorner = 1, kLeftGap = 2, kPoint = 3 };
const char* ToString(VertexLabel label);   // "right_gap", "corner", "left_gap", "point"
char ToChar(VertexLabel label);            // 'r', 'c', 'l', 'p'
VertexLabel LabelFromWalls(bool wall_ccw, bool wall_cw);

// Bearing convention: image column j of a W-wide panorama (and bin j of W bearing bins) looks along bearing
// -pi + 2*pi*j/W relative to the agent's heading.  Bearings are counter-clockwise from the heading.
double ColumnToBearing(double column, int width);
// The nearest column for a bearing, in [0, width).
int BearingToColumn(double bearing, int width);

}  // namespace toponav::core

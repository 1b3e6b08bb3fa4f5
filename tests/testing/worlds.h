#pragma once
// Tiny hand-made worlds for tests.
#include "core/world.h"

namespace toponav::testing {

// An open world with one square obstacle from (x0, y0) to (x1, y1); bounds [-10, 10]^2; start at (-5, -5).
core::World SquareWorld(double x0 = 1, double y0 = 1, double x1 = 2, double y1 = 2);
// The reference's two squares: (1,1)-(2,2) and (3,1.6)-(4,2.5).
core::World TwoSquaresWorld();
// An indoor rectangular room [0, w] x [0, h] with no obstacles, start at its centre.
core::World RoomWorld(double w, double h);
// A hand-built maze where the guiding matters: 14-wide corridors; from the start (7, 7) a stem leads up to a
// corridor along the top and down a right branch to the goal (127, 7); a side corridor along the bottom
// heads straight for the goal but turns up into a dead end (x 36-50, up to y 40).
core::World DeadEndMaze();
// A ring for the rectangle (x0, y0)-(x1, y1), counter-clockwise.
core::Ring Rect(double x0, double y0, double x1, double y1);

}  // namespace toponav::testing

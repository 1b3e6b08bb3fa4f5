#include "tests/testing/worlds.h"

namespace toponav::testing {

core::Ring Rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

core::World SquareWorld(double x0, double y0, double x1, double y1) {
  core::World w;
  w.obstacles.push_back(Rect(x0, y0, x1, y1));
  w.bounds = {{-10, -10}, {10, 10}};
  w.start = {-5, -5, 0};
  w.goal = {5, 5};
  return w;
}

core::World TwoSquaresWorld() {
  core::World w = SquareWorld();
  w.obstacles.push_back(Rect(3, 1.6, 4, 2.5));
  return w;
}

core::World RoomWorld(double wd, double h) {
  core::World w;
  w.boundary = Rect(0, 0, wd, h);
  w.bounds = {{0, 0}, {wd, h}};
  w.start = {wd / 2, h / 2, 0};
  w.goal = {wd / 4, h / 4};
  return w;
}

core::World DeadEndMaze() {
  core::World w;
  w.boundary = {{0, 0},    {50, 0},   {50, 40}, {36, 40}, {36, 14}, {14, 14},
                {14, 60},  {120, 60}, {120, 0}, {134, 0}, {134, 74}, {0, 74}};
  w.bounds = {{0, 0}, {134, 74}};
  w.start = {7, 7, 0};
  w.goal = {127, 7};
  return w;
}

}  // namespace toponav::testing

#pragma once
// The labyrinth generator's rooms on its coarse grid (exposed for tests).

namespace toponav::sim::internal {

struct GridRoom {
  int x0, y0, w, h;  // covers cells x0..x0+w, y0..y0+h (inclusive)
};

// How far apart two rooms are: their rectangles span cell centres x0..x0+w, y0..y0+h; apart on one axis, the
// gap along it; apart on both, the sum of the two gaps (the reference tests a rectangle grown by a one-segment
// round buffer, whose corners are cut straight).  0 where they share cells.  A room set is redrawn while two
// rooms are no farther apart than LabyrinthOptions::room_separation_cells.
double RoomGap(const GridRoom& a, const GridRoom& b);

}  // namespace toponav::sim::internal

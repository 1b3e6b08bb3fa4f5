#pragma once
// Walls the map has held, and for how many updates.  The posterior may later leave out a wall the sensor saw
// well (an end vertex flipped out by MCMC, or its labels outvoted by far views).  Known space then still ends along the
// wall's line -- the observations' own polygons stop there -- and that edge becomes a frontier with nothing
// behind it, which an agent would walk back across the world to look at.  A frontier lying along a wall the
// map held for a while, whose ends turn a corner into the map's walls there, is taken for that wall
// (SearchOptions::dropped_wall_steps).  Where a map wall runs straight on from an end, the held wall may have
// been a false one across a doorway (confident wrong labels at its jambs), so the frontier stays.
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"

namespace toponav::planning {

class DroppedWalls {
 public:
  static constexpr double kTolerance = 1.5;  // world units: a wall is the same wall while both ends stay this close,
                                             // and a frontier point this close to it lies along it
  static constexpr double kSpacing = 1.0;    // world units between the points sampled along a frontier
  static constexpr double kAlongShare = 0.8;  // TakenForWall: at least this share of a frontier lies along held walls,
  static constexpr double kEndReach = 3.0;    // and map walls ending within this of each of its ends (world units)
  static constexpr double kStraight = 0.5;    // all turn from it by more than this (radians)
  // Records the map's walls: each one matching a remembered wall (both ends within kTolerance, either way
  // round) counts one more update for it and moves it to where the map has it now; others are remembered
  // from one update.
  void Update(const std::vector<mapping::MapWall>& walls);
  // The share of 'frontier' (points every kSpacing along it) lying within kTolerance of a remembered wall
  // held for at least 'min_updates' updates.
  double ShareAlong(const mapping::Frontier& frontier, int min_updates) const;
  // True if at least kAlongShare of 'frontier' lies along walls held for 'min_updates' and it ends at corners of
  // 'walls' (the map's now): at each end at least one wall ends within kEndReach and none runs on within
  // kStraight of the frontier's line.
  bool TakenForWall(const mapping::Frontier& frontier, const std::vector<mapping::MapWall>& walls,
                    int min_updates) const;
  size_t size() const { return held_.size(); }

 private:
  struct Held {
    core::Segment2 wall;
    int updates = 0;
  };
  std::vector<Held> held_;
};

}  // namespace toponav::planning

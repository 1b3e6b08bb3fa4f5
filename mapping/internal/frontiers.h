#pragma once
// Frontiers: the pieces of the known-space boundary that are not map walls (nor, in open worlds, the search
// region's edge or open ground far from all structure), split where they turn sharply, with ids that stay
// stable across steps while a frontier stays put.
#include <vector>

#include "mapping/internal/map_core.h"

namespace toponav::mapping::internal {

class FrontierTracker {
 public:
  // The frontiers of 'known' under map state 'ms'; a frontier keeps the id of the previous call's frontier
  // whose midpoint is nearest, if close (so each call advances the ids: call once per map update).
  std::vector<Frontier> Extract(const MapCore& m, const MapState& ms, const std::vector<core::Polygon>& known);

 private:
  void AssignIds(std::vector<Frontier>* frontiers);
  std::vector<Frontier> last_;
  int next_id_ = 0;
};

}  // namespace toponav::mapping::internal

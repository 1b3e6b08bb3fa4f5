#pragma once
// A range ring: a short-range sensor a config may declare beside the vertex sensor (`sensor: {range_ring:
// {rays: N, range: R}}`).  It scans a full turn from the agent's pose on the true world (walls and clutter block
// rays) and reports it in the observation (core::RangeScan); a navigator plans with it only where its options
// say so (navigation.scan_when_held), and the trial record names it among the sensors used.
#include <memory>

#include "core/observation.h"
#include "core/option_fields.h"
#include "core/world.h"

namespace toponav::sim {

struct RangeRingOptions {
  int rays = 0;         // rays a scan, evenly spaced over a full turn (0: no range ring)
  double range = 12.0;  // reach (world units); a ray with no hit within it reads this
  static const core::OptionFields<RangeRingOptions>& Fields();  // YAML keys (under sensor.range_ring:)
  bool enabled() const { return rays > 0; }
};

// 'inner' with each observation's scan added (core::Observation::scan, ray j along world direction
// 2 * pi * j / rays).
std::unique_ptr<core::VertexSensorInterface> WithRangeRing(const core::World& world, const RangeRingOptions& options,
                                                           std::unique_ptr<core::VertexSensorInterface> inner);

}  // namespace toponav::sim

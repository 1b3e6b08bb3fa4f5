#include "sim/range_ring.h"

#include "core/error.h"
#include "sim/raycast.h"

namespace toponav::sim {

const core::OptionFields<RangeRingOptions>& RangeRingOptions::Fields() {
  using O = RangeRingOptions;
  static const core::OptionFields<O> fields{
      {"rays", &O::rays, 0, 100000},
      {"range", &O::range, 0.01, 10000.0},
  };
  return fields;
}

namespace {

class RangeRingSensor : public core::VertexSensorInterface {
 public:
  RangeRingSensor(const core::World& world, const RangeRingOptions& o,
                  std::unique_ptr<core::VertexSensorInterface> inner)
      : rays_(world), options_(o), inner_(std::move(inner)) {
    core::CheckRanges(o, RangeRingOptions::Fields(), "sensor.range_ring.");
    TOPONAV_CHECK(o.enabled() && inner_, "a range ring needs rays and a vertex sensor");
  }

  core::Observation Observe(const core::Pose2& pose, int agent) override {
    core::Observation z = inner_->Observe(pose, agent);
    core::RangeScan scan;
    scan.max_range = options_.range;
    scan.ranges.resize(size_t(options_.rays));
    for (size_t j = 0; j < scan.ranges.size(); ++j)
      scan.ranges[j] = rays_.CastRay(pose.position(), scan.Angle(j), options_.range, /*include_clutter=*/true);
    z.scan = std::move(scan);
    return z;
  }

 private:
  RayCaster rays_;
  RangeRingOptions options_;
  std::unique_ptr<core::VertexSensorInterface> inner_;
};

}  // namespace

std::unique_ptr<core::VertexSensorInterface> WithRangeRing(const core::World& world, const RangeRingOptions& options,
                                                           std::unique_ptr<core::VertexSensorInterface> inner) {
  return std::make_unique<RangeRingSensor>(world, options, std::move(inner));
}

}  // namespace toponav::sim

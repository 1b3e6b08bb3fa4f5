#include "planning/navigator_options.h"

#include "core/error.h"

namespace toponav::planning {

const core::OptionFields<SearchOptions>& SearchOptions::Fields() {
  using O = SearchOptions;
  static const core::OptionFields<O> fields{
      {"success_iou", &O::success_iou, 0.0, 1.0},
      {"give_up_steps", &O::give_up_steps, 1, 100000},
      {"tour", &O::tour},
      {"block_when_stuck", &O::block_when_stuck},
      {"close_buildings", &O::close_buildings},
      {"inspect_bend", &O::inspect_bend, 0.0, 1.5},
      {"inspect_unwalled", &O::inspect_unwalled, 0, 1000000},
      {"dropped_wall_steps", &O::dropped_wall_steps, 0, 100000},
      {"sealed_reach", &O::sealed_reach, 0.0, 1000.0},
  };
  return fields;
}

void SearchOptions::Validate() const { core::CheckRanges(*this, Fields(), "search."); }

const core::OptionFields<NavigationOptions>& NavigationOptions::Fields() {
  using O = NavigationOptions;
  static const core::OptionFields<O> fields{
      {"goal_radius", &O::goal_radius, 0.01, 1000.0},
      {"block_when_stuck", &O::block_when_stuck},
      {"scan_when_held", &O::scan_when_held, 0, 100000},
  };
  return fields;
}

}  // namespace toponav::planning

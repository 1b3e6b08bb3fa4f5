#include "planning/navigator_options.h"

#include "core/error.h"

namespace toponav::planning {

const core::OptionFields<SearchOptions>& SearchOptions::Fields() {
  using O = SearchOptions;
  static const core::OptionFields<O> fields{
      {"stuck_steps", &O::stuck_steps, 1, 1000},
      {"unreachable_steps", &O::unreachable_steps, 1, 100000},
      {"success_iou", &O::success_iou, 0.0, 1.0},
      {"switch_ratio", &O::switch_ratio, 1.0, 100.0},
      {"switch_margin", &O::switch_margin, 0.0, 10000.0},
      {"give_up_distance", &O::give_up_distance, 0.01, 1000.0},
      {"give_up_steps", &O::give_up_steps, 1, 100000},
      {"push_distance", &O::push_distance, 0.0, 1000.0},
      {"give_up_reach", &O::give_up_reach, 0.0, 1000.0},
      {"give_up_probe_radius", &O::give_up_probe_radius, 0.0, 100000.0},
      {"tour", &O::tour},
      {"block_when_stuck", &O::block_when_stuck},
      {"close_buildings", &O::close_buildings},
      {"inspect_bend", &O::inspect_bend, 0.0, 1.5},
      {"inspect_standoff", &O::inspect_standoff, 0.1, 1000.0},
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
      {"stuck_window", &O::stuck_window, 2, 100000},
      {"stuck_span", &O::stuck_span, 0.0, 1000.0},
      {"cut_off_steps", &O::cut_off_steps, 1, 100000},
      {"inspect_reach", &O::inspect_reach, 0.1, 1000.0},
      {"doorway_min_width", &O::doorway_min_width, 0.1, 1000.0},
      {"doorway_max_width", &O::doorway_max_width, 0.1, 1000.0},
      {"scan_when_held", &O::scan_when_held, 0, 100000},
  };
  return fields;
}

}  // namespace toponav::planning

#pragma once
// The options of the navigators (planning/navigator.h), read from a config's `search:` and `navigation:`
// sections at the edge (experiments/config.h); each key's range is declared once, in Fields().  Each task owns
// its section.  Fields below "not YAML keys" keep the reference's values; code (tests, studies) may set them.
#include <string>

#include "core/option_fields.h"

namespace toponav::planning {

// The values both navigators start from (world units and steps).
inline constexpr int kStuckSteps = 6;               // steps without headway before a nudge
inline constexpr double kGiveUpDistance = 4.0;      // an agent this close to where it was heading stands at it
inline constexpr double kGiveUpReach = 3.0;         // a new frontier this close to a given-up one is given up too
inline constexpr double kGiveUpProbeRadius = 20.0;  // ... counting its part within this of where agents stood
inline constexpr double kInspectReach = 8.0;        // a suspected false wall counts as looked at this close

// How agents search (planning::SearchNavigator): YAML section `search:`.
struct SearchOptions {
  double success_iou = 0.95;      // success: explored and IoU above this (the paper's criterion; a stricter or
                                  // looser study sets it)
  int give_up_steps = 20;         // an agent within give_up_distance of its frontier target this many steps
                                  // without the frontier going away gives it up (after half of them its target is
                                  // pushed push_distance into unknown space); a step in which an agent heading
                                  // for it is stuck counts as well
  bool tour = false;              // one agent heads for the first frontier of the shortest tour through all
                                  // of them (false: the nearest frontier, the paper's); teams are assigned
  bool block_when_stuck = false;  // where an agent makes no headway along its path for stuck_steps steps, a
                                  // wall 4 steps long across its way is added for the planners
  bool close_buildings = false;   // open worlds: a straight frontier between two map vertices that walls
                                  // already join the long way round is a building's last side, no target
  double inspect_bend = 0.0;      // > 0: before the search ends, agents look from inspect_standoff at each map
                                  // vertex whose two walls run on within this bend (radians) of straight
                                  // (planning::StraightVertices: a jamb of a walled-over opening); 0: off
  int inspect_unwalled = 0;       // > 0, open worlds: before the search ends, agents also look from
                                  // planning.frontier_setback at each map vertex no map wall reaches, each
                                  // one a single wall reaches with known space all round it, and each
                                  // rejected vertex with at least this many detections off every map wall
                                  // (planning::UnwalledVertices: a hollow building's corners); 0: off
  int dropped_wall_steps = 0;     // > 0: a frontier lying along a wall the map held for this many steps and
                                  // has left out since (planning::DroppedWalls: 80 % of it within 1.5 units)
                                  // is taken for that wall, no target; 0: off
  double sealed_reach = 0.0;      // > 0, closed worlds: a search whose known space stops further than this
                                  // (world units) short of a side of the world's bounds is not over: agents
                                  // look for the map wall that seals the rest off (planning::UnreachedSide,
                                  // planning::SuspectInspector) while there are suspects left; 0: off
  // Not YAML keys.
  int stuck_steps = kStuckSteps;
  int unreachable_steps = 12;     // frontiers left but none reachable this many steps in a row: explored
  double switch_ratio = 1.5;      // an agent keeps its frontier unless a new one is cheaper than cost/ratio ...
  double switch_margin = 10.0;    // ... and by more than this
  double give_up_distance = kGiveUpDistance;
  double push_distance = 6.0;
  double give_up_reach = kGiveUpReach;  // (0: off)
  double give_up_probe_radius = kGiveUpProbeRadius;  // (0: all of it)
  double inspect_standoff = 10.0; // world units from a vertex inspect_bend looks at, square to its walls
  double inspect_reach = kInspectReach;  // sealed_reach's suspects
  static const core::OptionFields<SearchOptions>& Fields();  // YAML keys (under search:) and their ranges
  void Validate() const;          // throws core::ConfigError ("search.give_up_steps", ...)
};

// How a goal-directed navigation trial goes and when it ends (planning::GoalNavigator), YAML section `navigation:`.
struct NavigationOptions {
  double goal_radius = 5.4;       // reached: the agent within this of the goal (the reference's 3 steps of 1.8;
                                  // a task with a larger or smaller goal sets it)
  bool block_when_stuck = false;  // where the agent makes no headway along its way for stuck_steps steps, and
                                  // where a nudge finds no frontier near to block, a wall 4 steps long across
                                  // its way is added for the planner
  // > 0: once the agent's last this many positions lie within stuck_span of each other (held, as stuck_window
  // counts), it plans with the walls a declared range ring's scans show besides the map, every step from then
  // on: the walls of every scan since, merged (planning/internal/scan_walls.h).  Below stuck_window, so a held
  // agent gets this before the trial would end "stuck"; 0: off
  int scan_when_held = 0;
  // Not YAML keys.
  int stuck_window = 100;         // stuck: after this many steps, every position of the last this many ...
  double stuck_span = 9.0;        // ... lies within this of each other (the reference: 100 poses, 5 steps)
  int cut_off_steps = 12;         // the map leaves no way to the goal and the recovery nothing to try this
                                  // many steps in a row
  double inspect_reach = kInspectReach;
  double doorway_min_width = 8.0;  // doorway hypotheses (planning/internal/doorways.h): openings between this
  double doorway_max_width = 24.0;  // wide and this wide (units)
  int stuck_steps = kStuckSteps;
  double give_up_distance = kGiveUpDistance;  // a frontier this close to where the agent is stuck is blocked
  double give_up_reach = kGiveUpReach;
  double give_up_probe_radius = kGiveUpProbeRadius;
  static const core::OptionFields<NavigationOptions>& Fields();
};

}  // namespace toponav::planning

#pragma once
// One search trial (paper Sec. IV): agents start together, every step each observes (sensor interface) and
// the observations join one map, MCMC runs on its cadence, the planner sends each agent towards a frontier
// (a team to distinct frontiers), and agents move one step.  A trial is a pure function of its spec.
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/world.h"
#include "experiments/config.h"
#include "planning/navigation.h"

namespace toponav::experiments {

// One trial's run; how agents search and plan comes from the config (config.search, config.planning).
struct TrialOptions {
  int num_agents = 1;
  int max_steps = 400;          // step cap (the reference's 400 iterations)
  int mcmc_every = 5;           // MCMC cadence in steps (0: never), with mapping.mcmc_samples proposals a call
  // The cadence in open worlds (the office park), at the same proposals per step: a call there proposes
  // mapping.mcmc_samples * open_world_mcmc_every / mcmc_every (at least 1).  Agents step twice as far there
  // (3.6 units), so a building face waits fewer units of travel for MCMC to accept it.  The last call of a
  // trial always proposes mapping.mcmc_samples.
  int open_world_mcmc_every = 2;
  // Called after every step with the map the planners used and the agents' paths so far, and once more
  // with the final map the metrics score (videos).
  std::function<void(const mapping::MapView&, const std::vector<std::vector<core::Vec2>>&)> on_step;
  // Called every step before agents move with the frontier targets on offer and each agent's choice (traces).
  std::function<void(const std::vector<planning::FrontierTarget>&, const std::vector<planning::FrontierChoice>&)> on_plan;
};

struct TrialResult {
  uint64_t seed = 0;
  int num_agents = 0;
  bool explored = false;          // no reachable frontier left (none at all, or none reachable for a while)
  bool success = false;
  int steps = 0;
  double iou = 0.0;               // indoor: known space vs true free space; office park: building placement
  std::vector<double> distance;   // travelled per agent
  int nudges = 0;                 // stuck-agent perturbations
  int give_ups = 0;               // frontiers given up (agents stood next to them, or were stuck on the way)
  std::string end_reason;         // "explored", "unreachable" (frontiers left, none reachable), "step_cap"
  double wall_time_s = 0.0;
  // Where the time went: observations and map updates, MCMC, known space and frontiers, planning and motion.
  double time_map_s = 0.0, time_mcmc_s = 0.0, time_known_s = 0.0, time_plan_s = 0.0;
  std::vector<std::vector<core::Vec2>> paths;  // per agent
};

// Frontiers given up in a trial, by id and by place: the map may re-create the piece of an unmapped wall that
// was given up under a new id, so a frontier whose midpoint and ends lie within 'reach' of where given-up
// ones were probed is given up as well.  Where a frontier was probed: the part of it within 'probe_radius' of
// the point agents stood at (a long frontier along an unmapped wall may hold an opening farther along that
// the agent never looked through), or all of it when no point is given (agents gave it up because they could
// not get to it).  A given-up frontier that grows well past where it lay when it was given up (its middle or
// an end farther than 4 'reach' from it) is another frontier now: it is taken back (once).  Reach 0: by id
// only, and nothing is taken back.
class GivenUpFrontiers {
 public:
  explicit GivenUpFrontiers(double reach, double probe_radius = 0.0) : reach_(reach), probe_radius_(probe_radius) {}
  // Gives up frontier 'id'; its polyline is taken from 'frontiers' if it is there.
  void GiveUp(int id, const std::vector<mapping::Frontier>& frontiers, const core::Vec2* probed_at = nullptr);
  // Gives up the frontiers that lie where given-up ones were probed, and takes back the ones that grew;
  // returns the ids taken back.
  std::vector<int> Update(const std::vector<mapping::Frontier>& frontiers);
  bool Contains(int id) const { return ids_.count(id) > 0; }
  int given_up() const { return given_up_; }  // frontiers given up with GiveUp (not counting re-created ones)
  // Records where frontier 'id' was probed (the part of it within probe_radius of 'probed_at') without giving
  // it up: the rest of a long frontier stays a target.
  void Probe(int id, const std::vector<mapping::Frontier>& frontiers, const core::Vec2& probed_at);
  const std::vector<core::Segment2>& probed() const { return edges_; }  // pieces given up or probed

 private:
  void AddPieces(const mapping::Frontier& f, const core::Vec2* probed_at);
  double reach_, probe_radius_;
  std::set<int> ids_;
  std::vector<core::Segment2> edges_;                 // where given-up frontiers were probed
  std::map<int, std::vector<core::Segment2>> extent_;  // each given-up frontier's polyline when given up
  std::set<int> taken_back_;
  int given_up_ = 0;
  static constexpr double kRegrowth = 4.0;            // taken back when it reaches this many 'reach' past it
};

TrialResult RunSearchTrial(const core::World& world, const Config& config, const TrialOptions& options,
                           uint64_t seed, mapping::MapView* final_view = nullptr);

// Office park metric (paper footnote: buildings detected in the right places, no spurious ones), as the reference
// computes it: IoU of the true buildings and the holes of the known space, i.e. the places the map has enclosed
// without marking them free.  A building not walked all the way around is not enclosed and counts as missed;
// open ground the search never needed to see (far from every building) does not count.
double BuildingPlacementIoU(const core::World& world, const mapping::MapView& map);

}  // namespace toponav::experiments

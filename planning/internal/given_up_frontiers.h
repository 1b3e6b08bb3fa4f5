#pragma once
// Frontiers a search has given up, by id and by place: the map may re-create the piece of an unmapped wall
// that was given up under a new id, so a frontier whose midpoint and ends lie within 'reach' of where given-up
// ones were probed is given up as well.  Where a frontier was probed: the part of it within 'probe_radius' of
// the point agents stood at (a long frontier along an unmapped wall may hold an opening farther along that
// the agent never looked through), or all of it when no point is given (agents gave it up because they could
// not get to it).  Giving a frontier up again where agents stood elsewhere along it adds that part.  A
// given-up frontier that grows well past where it lay when it was given up (its middle or an end farther than
// 4 'reach' from it) is another frontier now: it is taken back (once).  Reach 0: by id only, and nothing is
// taken back.
#include <map>
#include <set>
#include <vector>

#include "core/geometry.h"
#include "mapping/mapping.h"

namespace toponav::planning {

class GivenUpFrontiers {
 public:
  static constexpr double kUnprobedSpacing = 0.5;  // Unprobed's sampling step along a frontier, world units

  explicit GivenUpFrontiers(double reach, double probe_radius = 0.0) : reach_(reach), probe_radius_(probe_radius) {}
  // Gives up frontier 'id' (again: one more probed part); its polyline is taken from 'frontiers' if it is there.
  void GiveUp(int id, const std::vector<mapping::Frontier>& frontiers, const core::Vec2* probed_at = nullptr);
  // Gives up the frontiers that lie where given-up ones were probed, and takes back the ones that grew;
  // returns the ids taken back.
  std::vector<int> Update(const std::vector<mapping::Frontier>& frontiers);
  bool Contains(int id) const { return ids_.count(id) > 0; }
  // 'frontiers' with their parts within 'reach' of where given-up ones were probed cut away: a frontier probed
  // in part keeps its longest other piece (its id; points, midpoint and length those of the piece; a cut end
  // counts as a true end, front_turn / back_turn 0), one with no other piece is dropped, the others are as
  // they were.  Clearance is sampled every kUnprobedSpacing world units along a frontier: a piece's ends lie
  // up to that far inside its clear part, and clear parts shorter than that are dropped.  A target at the
  // piece's middle leads an agent to the part of a long frontier along an unmapped wall that it has not
  // pressed at yet.
  std::vector<mapping::Frontier> Unprobed(const std::vector<mapping::Frontier>& frontiers) const;
  // Takes every frontier back (they were guesses: a goal-directed agent whose map is sealed retries them).
  void Clear() { *this = GivenUpFrontiers(reach_, probe_radius_); }
  int given_up() const { return given_up_; }  // frontiers given up with GiveUp (not counting re-created ones)
  const std::vector<core::Segment2>& probed() const { return edges_; }  // where given-up frontiers were probed

 private:
  void AddPieces(const mapping::Frontier& f, const core::Vec2* probed_at);
  double reach_, probe_radius_;
  std::set<int> ids_;
  std::vector<core::Segment2> edges_;
  std::map<int, std::vector<core::Segment2>> extent_;  // each given-up frontier's polyline when given up
  std::set<int> taken_back_;
  int given_up_ = 0;
  static constexpr double kRegrowth = 4.0;            // taken back when it reaches this many 'reach' past it
};

}  // namespace toponav::planning

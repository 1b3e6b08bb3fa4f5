#pragma once
// The map's posterior (paper Sec. III-B, III-C): the hypothetical observation a map predicts from each real
// observation's pose, and the log likelihood of the real detections given it.
#include <vector>

#include "mapping/internal/map_core.h"

namespace toponav::mapping::internal {

// Which potential vertices with enough detections lie in each observation's star polygon, found once per
// observation; valid while vertex positions and star polygons stay put (during one MCMC call).
class StarMembers {
 public:
  explicit StarMembers(size_t num_observations) : members_(num_observations), ok_(num_observations, 0) {}
  const std::vector<int>& Of(const MapCore& m, size_t k);

 private:
  std::vector<std::vector<int>> members_;
  std::vector<char> ok_;
};

// The hypothetical observation of observation k (paper Sec. III-B; vertexnav.md §2.6): mapped vertices in
// range, inside or on the real observation's star polygon, not hidden by a mapped wall (or one of
// 'extra_walls'); by bearing.  With 'with_candidates' (known space only, never the posterior) also the
// vertices the observation itself detected that have enough detections but are not in the map.
std::vector<int> Hypothetical(const MapCore& m, size_t k, const MapState& ms, const std::vector<Wall>& extra_walls = {},
                              bool with_candidates = false, StarMembers* cache = nullptr);

// log P(z_k | m): false positives and negatives against the hypothetical observation, a truncated position
// term for matches, and edge terms along consecutive hypothetical vertices (none for a pair seen edge-on,
// closer in bearing than wall_min_view_angle: it gives no wall evidence either).
double ObservationLogLikelihood(const MapCore& m, size_t k, const MapState& ms, StarMembers* cache = nullptr);
double LogPrior(const MapperOptions& o, const MapState& ms);
// The log posterior of map state 'ms' over all observations.
double LogPosterior(const MapCore& m, const MapState& ms);

// Observations whose likelihood can change when vertex i flips in 'ms': their star polygon meets the vertex
// or a wall that comes or goes with it (sight lines and hypothetical vertices all lie inside the star).
std::vector<int> Affected(const MapCore& m, int i, const MapState& ms);

}  // namespace toponav::mapping::internal

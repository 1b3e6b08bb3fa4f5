#include "mapping/internal/mcmc.h"

#include <cmath>
#include <limits>

#include "mapping/internal/posterior.h"
#include "mapping/internal/stars.h"

namespace toponav::mapping::internal {

namespace {

// Candidates: vertices with enough detections seen in the recent window of observations.
std::vector<int> Candidates(const MapCore& m) {
  std::vector<char> recent(m.vertices.size(), 0);
  const size_t window = size_t(m.o.mcmc_window);
  const size_t first = m.obs.size() > window ? m.obs.size() - window : 0;
  for (size_t k = first; k < m.obs.size(); ++k)
    for (int id : m.obs[k].vid) recent[size_t(id)] = 1;
  std::vector<int> cand;
  for (size_t i = 0; i < m.vertices.size(); ++i)
    if (recent[i] && m.vertices.Seen(int(i))) cand.push_back(int(i));
  return cand;
}

}  // namespace

double SampleMostLikelyMap(MapCore* mc, core::Rng& rng, int samples, MapperStats* stats) {
  RefreshStars(mc, mc->o.star_rebuild_tolerance);
  MapCore& m = *mc;
  // Positions and star polygons stay put until the call returns: cache which vertices each star holds.
  StarMembers members(m.obs.size());
  const std::vector<int> cand = Candidates(m);
  MapState ms = m.walls.State(m.vertices);
  std::vector<double> ll(m.obs.size(), std::numeric_limits<double>::quiet_NaN());
  stats->last_mcmc_accepted = 0;
  stats->last_mcmc_evaluated_observations = 0;
  auto cached_ll = [&](int k) {
    if (std::isnan(ll[size_t(k)])) ll[size_t(k)] = ObservationLogLikelihood(m, size_t(k), ms, &members);
    return ll[size_t(k)];
  };
  std::vector<char> best_state(m.vertices.size());
  for (size_t i = 0; i < m.vertices.size(); ++i) best_state[i] = m.vertices[i].in_map;
  double delta_total = 0, best_delta = 0;  // relative to the starting state
  // Random-order systematic scan: every candidate is proposed once per pass (in a fresh random order), so a
  // vertex that just gathered enough detections is considered at the next call, whatever the window size.
  std::vector<int> order;
  for (int s = 0; s < samples && !cand.empty(); ++s) {
    if (order.empty()) {
      order = cand;
      rng.Shuffle(order);
    }
    const int i = order.back();
    order.pop_back();
    const bool on = !ms.mapped[size_t(i)];
    const std::vector<int> affected = Affected(m, i, ms);
    double delta = -LogPrior(m.o, ms);
    std::vector<double> old_ll(affected.size());
    for (size_t a = 0; a < affected.size(); ++a) old_ll[a] = cached_ll(affected[a]);
    m.walls.SetMapped(i, on, &ms);
    delta += LogPrior(m.o, ms);
    std::vector<double> new_ll(affected.size());
    for (size_t a = 0; a < affected.size(); ++a) {
      new_ll[a] = ObservationLogLikelihood(m, size_t(affected[a]), ms, &members);
      delta += new_ll[a] - old_ll[a];
    }
    stats->last_mcmc_evaluated_observations += int(affected.size());
    if (delta >= 0 || std::log(rng.Uniform()) < delta) {  // Metropolis (symmetric proposal)
      m.vertices.SetInMap(i, on);
      delta_total += delta;
      for (size_t a = 0; a < affected.size(); ++a) ll[size_t(affected[a])] = new_ll[a];
      ++stats->last_mcmc_accepted;
      if (delta_total > best_delta) {
        best_delta = delta_total;
        for (size_t k = 0; k < m.vertices.size(); ++k) best_state[k] = m.vertices[k].in_map;
      }
    } else {
      m.walls.SetMapped(i, !on, &ms);
    }
  }
  for (size_t k = 0; k < m.vertices.size(); ++k) m.vertices.SetInMap(int(k), best_state[k]);
  return best_delta;  // (the full posterior would cost a hypothetical observation per past observation)
}

}  // namespace toponav::mapping::internal

#include "planning/internal/progress.h"

#include "core/error.h"

namespace toponav::planning {

using core::Vec2;

FrontierCommitment::FrontierCommitment(int num_agents, double switch_ratio, double switch_margin)
    : committed_(size_t(num_agents), -1), ratio_(switch_ratio), margin_(switch_margin) {
  TOPONAV_CHECK(num_agents >= 1 && switch_ratio >= 1 && switch_margin >= 0, "bad commitment parameters");
}

void FrontierCommitment::Apply(const VisibilityGraph& graph, const std::vector<FrontierTarget>& targets,
                               const std::vector<Vec2>& agents, std::vector<FrontierChoice>* choices) {
  auto& cs = *choices;
  TOPONAV_CHECK(cs.size() == committed_.size() && agents.size() == committed_.size(), "one choice per agent");
  for (size_t a = 0; a < cs.size(); ++a) {
    auto& c = cs[a];
    const int prev = committed_[a];
    if (prev == -1 || c.status != PlanStatus::kFound || c.frontier_id == prev) continue;
    for (const auto& t : targets) {
      if (t.frontier_id != prev) continue;
      const Path keep = graph.Plan(agents[a], t.point);
      if (!keep || keep.cost > ratio_ * c.path.cost + margin_) continue;
      bool taken = false;  // a team mate may have been given it meanwhile
      for (size_t b = 0; b < cs.size(); ++b) taken = taken || (b != a && cs[b].frontier_id == prev);
      if (!taken) {
        c.frontier_id = prev;
        c.path = keep;
      }
    }
  }
  for (size_t a = 0; a < cs.size(); ++a) committed_[a] = cs[a].status == PlanStatus::kFound ? cs[a].frontier_id : -1;
}

FrontierDwell::FrontierDwell(int give_up_steps, double give_up_distance)
    : give_up_steps_(give_up_steps), give_up_distance_(give_up_distance) {
  TOPONAV_CHECK(give_up_steps >= 1 && give_up_distance > 0, "bad dwell parameters");
}

bool FrontierDwell::Standing(const std::vector<Vec2>& trail, double step_length) {
  return trail.size() < 2 || core::Distance(trail[trail.size() - 2], trail.back()) < 0.5 * step_length;
}

std::vector<size_t> FrontierDwell::CountStanding(const std::vector<FrontierTarget>& targets,
                                                 const std::vector<FrontierTarget>& original,
                                                 const std::vector<Vec2>& agents, const std::vector<char>& standing) {
  TOPONAV_CHECK(targets.size() == original.size() && agents.size() == standing.size(), "mismatched sizes");
  std::vector<size_t> due;
  for (size_t i = 0; i < targets.size(); ++i) {
    bool near = false;
    for (size_t a = 0; a < agents.size(); ++a)
      near = near || (standing[a] && (core::Distance(agents[a], targets[i].point) < give_up_distance_ ||
                                      core::Distance(agents[a], original[i].point) < give_up_distance_));
    if (near && Count(targets[i].frontier_id)) due.push_back(i);
  }
  return due;
}

bool FrontierDwell::Count(int id) { return ++steps_[id] > give_up_steps_; }

int FrontierDwell::steps(int id) const {
  const auto it = steps_.find(id);
  return it == steps_.end() ? 0 : it->second;
}

void FrontierDwell::PushThrough(std::vector<FrontierTarget>* targets, double distance,
                                const std::optional<core::Aabb2>& region) const {
  for (auto& t : *targets) {
    if (steps(t.frontier_id) <= give_up_steps_ / 2) continue;
    const Vec2 pushed = t.point + t.outward * (t.depth + distance);
    if (!region || region->Contains(pushed)) t.point = pushed;  // never out of the search region
  }
}

StuckMonitor::StuckMonitor(int num_agents, int stuck_steps, double step_length)
    : still_(size_t(num_agents), 0), stuck_steps_(stuck_steps), step_length_(step_length) {
  TOPONAV_CHECK(num_agents >= 1 && stuck_steps >= 1 && step_length > 0, "bad stuck-monitor parameters");
}

bool StuckMonitor::NoHeadway(const std::vector<Vec2>& trail, bool has_path, bool no_way, const Vec2& now,
                             double moved) const {
  const size_t window = size_t(pacing_steps());
  const bool pacing =
      has_path && trail.size() > window && core::Distance(trail[trail.size() - window], now) < step_length_;
  return (has_path && moved < 0.1 * step_length_) || no_way || pacing;
}

bool StuckMonitor::Record(int agent, bool no_headway) {
  int& still = still_[size_t(agent)];
  if (!no_headway) {
    still = 0;
    return false;
  }
  if (++still < stuck_steps_) return false;
  still = 0;
  return true;
}

bool PacedForthAndBack(const std::vector<Vec2>& trail, const Vec2& now, double step_length) {
  if (trail.size() < 2) return false;
  const Vec2& from = trail[trail.size() - 2];
  const Vec2& mid = trail.back();
  const double half = 0.5 * step_length;
  return core::Distance(from, mid) >= half && core::Distance(mid, now) >= half && core::Distance(from, now) < half;
}

bool HeldInPlace(const std::vector<Vec2>& trail, const Vec2& now, int steps, double span) {
  TOPONAV_CHECK(steps >= 1 && span >= 0, "bad held-in-place parameters");
  if (trail.size() < size_t(steps)) return false;
  const size_t first = trail.size() - size_t(steps);
  for (size_t i = first; i < trail.size(); ++i) {
    if (core::Distance(trail[i], now) > span) return false;
    for (size_t j = i + 1; j < trail.size(); ++j)
      if (core::Distance(trail[i], trail[j]) > span) return false;
  }
  return true;
}

bool RepeatedStep(const std::vector<Vec2>& trail, const Vec2& now, int max_period, int laps, double tolerance) {
  TOPONAV_CHECK(max_period >= 1 && laps >= 1 && tolerance >= 0, "bad repeated-step parameters");
  const size_t n = trail.size();
  if (n == 0 || core::Distance(trail.back(), now) <= tolerance) return false;
  // The step (trail[n-1], now) against the step 'back' steps before it, (trail[n-1-back], trail[n-back]).
  auto repeats = [&](size_t back) {
    return core::Distance(trail[n - 1 - back], trail[n - 1]) <= tolerance &&
           core::Distance(trail[n - back], now) <= tolerance;
  };
  for (size_t period = 1; period <= size_t(max_period) && size_t(laps) * period < n; ++period) {
    bool all = true;
    for (size_t lap = 1; lap <= size_t(laps) && all; ++lap) all = repeats(lap * period);
    if (all) return true;
  }
  return false;
}

}  // namespace toponav::planning

#include "planning/internal/map_suspects.h"

#include <cmath>

#include "core/error.h"

namespace toponav::planning {

using core::Vec2;

SuspectInspector::SuspectInspector(double reach, double standoff, double spacing)
    : reach_(reach), standoff_(standoff), spacing_(spacing) {
  TOPONAV_CHECK(reach > 0 && standoff > 0 && spacing > 0,
                "suspect inspection: reach " << reach << ", standoff " << standoff << ", spacing " << spacing);
}

bool SuspectInspector::Inspected(const Vec2& p) const {
  for (const auto& q : inspected_)
    if (core::Distance(p, q) <= reach_) return true;
  return false;
}

void SuspectInspector::AddSamples(const Vec2& a, const Vec2& b, std::vector<Vec2>* out) const {
  const int n = std::max(1, int(std::floor(core::Distance(a, b) / spacing_)));
  for (int k = 0; k < n; ++k) out->push_back(a + (b - a) * ((k + 0.5) / n));
}

std::vector<Vec2> SuspectInspector::Suspects(const mapping::MapView& view) const {
  std::vector<Vec2> all;
  for (const auto& v : view.rejected) all.push_back(v.position);
  for (const auto& w : view.walls) AddSamples(w.pa, w.pb, &all);
  std::vector<Vec2> out;
  for (const auto& p : all)
    if (!Inspected(p)) out.push_back(p);
  return out;
}

FrontierChoice SuspectInspector::Choose(const mapping::MapView& view, const VisibilityGraph& graph, const Vec2& agent,
                                        const Vec2& goal, const std::vector<FrontierTarget>& targets) {
  constexpr int kDirections = 8;
  std::vector<Vec2> suspects;
  for (const auto& s : Suspects(view)) {
    if (core::Distance(s, agent) <= reach_)
      inspected_.push_back(s);
    else
      suspects.push_back(s);
  }
  // Points: the frontier targets, then per suspect its kDirections candidate lookouts and their opposites.
  std::vector<Vec2> points;
  for (const auto& t : targets) points.push_back(t.point);
  for (const auto& s : suspects)
    for (int k = 0; k < kDirections; ++k) {
      const double a = 2 * core::kPi * k / kDirections;
      const Vec2 d{standoff_ * std::cos(a), standoff_ * std::sin(a)};
      points.push_back(s + d);
      points.push_back(s - d);
    }
  FrontierChoice choice;
  if (points.empty()) return choice;
  const std::vector<Path> paths = graph.PlanToMany(agent, points);
  double best = 0.0;
  auto consider = [&](const Path& path, const Vec2& place, int frontier_id) {
    const double cost = path.cost + core::Distance(place, goal);
    if (choice.status == PlanStatus::kFound && cost >= best) return;
    best = cost;
    choice = {PlanStatus::kFound, frontier_id, path};
  };
  for (size_t t = 0; t < targets.size(); ++t)
    if (paths[t]) consider(paths[t], targets[t].point, targets[t].frontier_id);
  for (size_t s = 0; s < suspects.size(); ++s) {
    bool lookout = false;
    for (int k = 0; k < kDirections; ++k) {
      const size_t i = targets.size() + 2 * (s * kDirections + size_t(k));
      if (!paths[i] || paths[i + 1]) continue;
      lookout = true;
      consider(paths[i], suspects[s], -1);
    }
    if (!lookout) inspected_.push_back(suspects[s]);
  }
  return choice;
}

}  // namespace toponav::planning

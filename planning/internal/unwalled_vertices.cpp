#include "planning/internal/unwalled_vertices.h"

#include <cmath>

#include "planning/navigation.h"

namespace toponav::planning {

using core::Vec2;

namespace {

constexpr double kOnWall = 2.0;         // a rejected vertex this close to a map wall is on it (units)
constexpr double kNeighbourhood = 45.0; // the map vertices that say which way is out (units)
constexpr double kRound = 3.0;          // how far round a vertex known space is looked for (units)
constexpr int kRoundSamples = 16, kKnownAllRound = 14;  // directions, and how many must be known

bool OnAWall(const mapping::MapView& view, const Vec2& p) {
  for (const auto& w : view.walls)
    if (core::DistanceToSegment(p, {w.pa, w.pb}) < kOnWall) return true;
  return false;
}

// Whether known space lies all round 'p': a corner has it on one side of its two walls only, a building's
// corner with known space inside as well is hollow.
bool KnownAllRound(const mapping::MapView& view, const Vec2& p) {
  int known = 0;
  for (int k = 0; k < kRoundSamples; ++k)
    known += InKnown(view, p + core::Rotate({kRound, 0}, 2 * core::kPi * k / kRoundSamples)) ? 1 : 0;
  return known >= kKnownAllRound;
}

// The unit vector from the mean of the map vertices near 'v' (other than v) to v; +x when there are none.
Vec2 Outward(const mapping::MapView& view, const mapping::MapVertex& v) {
  Vec2 sum{0, 0};
  int n = 0;
  for (const auto& u : view.vertices)
    if (u.id != v.id && core::Distance(u.position, v.position) < kNeighbourhood) sum = sum + u.position, ++n;
  if (n == 0) return {1, 0};
  const Vec2 away = v.position - sum * (1.0 / n);
  const double length = std::hypot(away.x, away.y);
  return length > 1e-6 ? away * (1.0 / length) : Vec2{1, 0};
}

}  // namespace

std::vector<InspectionSite> UnwalledVertices(const mapping::MapView& view, int min_detections, double standoff) {
  const std::map<int, std::vector<Vec2>> ends = WallEnds(view);
  std::vector<const mapping::MapVertex*> found;
  for (const auto& v : view.vertices) {
    const auto it = ends.find(v.id);
    const size_t walls = it == ends.end() ? 0 : it->second.size();
    if (walls == 0 || (walls == 1 && KnownAllRound(view, v.position))) found.push_back(&v);
  }
  for (const auto& v : view.rejected)
    if (v.num_detections >= min_detections && !OnAWall(view, v.position)) found.push_back(&v);
  std::vector<InspectionSite> out;
  for (const mapping::MapVertex* v : found) {
    const Vec2 out_dir = Outward(view, *v);
    InspectionSite site{v->id, v->position, {}};
    for (const double turn : {-core::kPi / 4, 0.0, core::kPi / 4}) {
      const Vec2 p = v->position + core::Rotate(out_dir, turn) * standoff;
      if (InKnown(view, p)) site.lookouts.push_back(p);
    }
    out.push_back(std::move(site));
  }
  return out;
}

}  // namespace toponav::planning

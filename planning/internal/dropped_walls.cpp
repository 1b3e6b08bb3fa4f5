#include "planning/internal/dropped_walls.h"

#include <cmath>

namespace toponav::planning {

using core::Vec2;

namespace {

bool SameWall(const core::Segment2& s, const Vec2& a, const Vec2& b) {
  const double t = DroppedWalls::kTolerance;
  return (core::Distance(s.a, a) < t && core::Distance(s.b, b) < t) ||
         (core::Distance(s.a, b) < t && core::Distance(s.b, a) < t);
}

// True if map walls end within kEndReach of 'end' and every one turns away from the frontier's chord, which
// leaves 'end' toward 'other', by more than kStraight.
bool CornerAt(const Vec2& end, const Vec2& other, const std::vector<mapping::MapWall>& walls) {
  const Vec2 along = other - end;
  bool any = false;
  for (const mapping::MapWall& w : walls) {
    const bool a_near = core::Distance(w.pa, end) < DroppedWalls::kEndReach;
    if (!a_near && core::Distance(w.pb, end) >= DroppedWalls::kEndReach) continue;
    const Vec2 away = a_near ? w.pb - w.pa : w.pa - w.pb;
    const double angle = std::abs(core::WrapAngle(std::atan2(away.y, away.x) - std::atan2(along.y, along.x)));
    if (angle > M_PI - DroppedWalls::kStraight) return false;  // the wall runs straight on past the end
    any = true;
  }
  return any;
}

}  // namespace

bool DroppedWalls::TakenForWall(const mapping::Frontier& frontier, const std::vector<mapping::MapWall>& walls,
                                int min_updates) const {
  if (frontier.points.size() < 2 || ShareAlong(frontier, min_updates) < kAlongShare) return false;
  const Vec2& front = frontier.points.front();
  const Vec2& back = frontier.points.back();
  return CornerAt(front, back, walls) && CornerAt(back, front, walls);
}

void DroppedWalls::Update(const std::vector<mapping::MapWall>& walls) {
  const size_t before = held_.size();
  std::vector<char> counted(before, 0);  // a remembered wall counts once per update
  for (const mapping::MapWall& w : walls) {
    size_t k = 0;
    while (k < before && (counted[k] || !SameWall(held_[k].wall, w.pa, w.pb))) ++k;
    if (k == before) {
      held_.push_back({core::Segment2{w.pa, w.pb}, 1});
      continue;
    }
    counted[k] = 1;
    held_[k].wall = core::Segment2{w.pa, w.pb};
    ++held_[k].updates;
  }
}

double DroppedWalls::ShareAlong(const mapping::Frontier& frontier, int min_updates) const {
  int along = 0, samples = 0;
  const auto near_held = [&](const Vec2& p) {
    for (const Held& h : held_)
      if (h.updates >= min_updates && core::DistanceToSegment(p, h.wall) < kTolerance) return true;
    return false;
  };
  const std::vector<Vec2>& pts = frontier.points;
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const double length = core::Distance(pts[i], pts[i + 1]);
    for (double t = 0.0; t < length; t += kSpacing) {
      ++samples;
      along += near_held(pts[i] + (pts[i + 1] - pts[i]) * (t / length));
    }
  }
  if (samples == 0 && !pts.empty()) return near_held(pts.front()) ? 1.0 : 0.0;
  return samples ? double(along) / samples : 0.0;
}

}  // namespace toponav::planning

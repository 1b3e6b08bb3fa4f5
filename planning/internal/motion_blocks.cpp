#include "planning/internal/motion_blocks.h"

#include <algorithm>

#include "core/error.h"
#include "planning/navigation.h"

namespace toponav::planning {

using core::Vec2;

MotionBlocks::MotionBlocks(int num_agents, int steps, double step_length, double half_width, double ahead)
    : count_(size_t(num_agents), 0), steps_(steps), step_length_(step_length), half_width_(half_width), ahead_(ahead) {
  TOPONAV_CHECK(num_agents >= 1 && steps >= 1 && step_length > 0 && half_width > 0 && ahead >= 0,
                "bad motion-block parameters");
}

bool MotionBlocks::Record(int agent, const std::vector<Vec2>& path, const Vec2& before, const Vec2& after) {
  TOPONAV_CHECK(agent >= 0 && size_t(agent) < count_.size(), "no agent " << agent);
  int& count = count_[size_t(agent)];
  if (path.size() < 2) {
    count = 0;
    return false;
  }
  const Vec2 to = path[1] - before;
  const double reach = core::Norm(to);
  if (reach < 1e-9) return false;
  const Vec2 dir = to / reach;
  const double progress = core::Dot(after - before, dir);
  if (progress >= 0.5 * std::min(step_length_, reach)) {
    count = 0;
    return false;
  }
  if (++count < steps_) return false;
  count = 0;
  Add(before, dir);
  return true;
}

bool MotionBlocks::Block(const Vec2& at, const Vec2& toward) {
  const double reach = core::Distance(at, toward);
  if (reach < 1e-9) return false;
  Add(at, (toward - at) / reach);
  return true;
}

void MotionBlocks::Add(const Vec2& at, const Vec2& dir) {
  const Vec2 centre = at + dir * ahead_;
  const Vec2 across{-dir.y * half_width_, dir.x * half_width_};
  blocks_.push_back({centre - across, centre + across});
  added_.push_back(blocks_.back());
}

void MotionBlocks::Clear() {
  blocks_.clear();
  std::fill(count_.begin(), count_.end(), 0);
}

mapping::MapView MotionBlocks::With(const mapping::MapView& view) const {
  mapping::MapView out = view;
  AddFreeStandingWalls(&out, blocks_);
  return out;
}

}  // namespace toponav::planning

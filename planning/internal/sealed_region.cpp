#include "planning/internal/sealed_region.h"

#include <algorithm>
#include <limits>

namespace toponav::planning {

std::optional<core::Vec2> UnreachedSide(const std::vector<core::Polygon>& known, const core::Aabb2& region,
                                        double reach, const core::Vec2& agent) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  core::Aabb2 box{{kInf, kInf}, {-kInf, -kInf}};
  for (const auto& poly : known) box = core::Bounds(poly.outer, box);
  if (box.min.x > box.max.x) return std::nullopt;
  const double x = std::clamp(agent.x, region.min.x, region.max.x);
  const double y = std::clamp(agent.y, region.min.y, region.max.y);
  std::optional<core::Vec2> best;
  const auto consider = [&](bool unreached, const core::Vec2& p) {
    if (unreached && (!best || core::Distance(agent, p) < core::Distance(agent, *best))) best = p;
  };
  consider(box.min.x > region.min.x + reach, {region.min.x, y});
  consider(box.max.x < region.max.x - reach, {region.max.x, y});
  consider(box.min.y > region.min.y + reach, {x, region.min.y});
  consider(box.max.y < region.max.y - reach, {x, region.max.y});
  return best;
}

}  // namespace toponav::planning

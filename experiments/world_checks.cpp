#include "experiments/world_checks.h"

#include <algorithm>
#include <limits>
#include <sstream>

#include "mapping/polygon_set.h"

namespace toponav::experiments {

WorldStats ComputeWorldStats(const core::World& w) {
  WorldStats s;
  s.num_vertices = int(core::MapVertices(w).size());
  s.num_obstacles = int(w.obstacles.size());
  s.num_clutter = int(w.clutter.size());
  const auto free = mapping::PolygonSet::FromPolygon(core::FreeSpacePolygon(w));
  s.free_area = free.Area();
  s.free_components = int(free.Polygons().size());
  if (w.kind == core::WorldKind::kOfficePark && w.obstacles.size() > 1) {
    s.min_building_gap = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < w.obstacles.size(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < w.obstacles.size(); ++j)
        if (i != j) nearest = std::min(nearest, core::RingDistance(w.obstacles[i], w.obstacles[j]));
      s.min_building_gap = std::min(s.min_building_gap, nearest);
      s.max_nearest_building_gap = std::max(s.max_nearest_building_gap, nearest);
    }
  }
  return s;
}

std::vector<std::string> CheckWorld(const core::World& w, const sim::WorldOptions& options) {
  std::vector<std::string> problems;
  const WorldStats s = ComputeWorldStats(w);
  auto add = [&](const std::string& p) { problems.push_back(p); };
  if (s.free_components != 1) add("free space has " + std::to_string(s.free_components) + " pieces");
  if (!core::IsFree(w, w.start.position())) add("start is not in free space");
  if (w.kind == core::WorldKind::kOfficePark) {
    const sim::OfficeParkOptions& defaults = options.office_park;
    std::ostringstream os;
    if (s.min_building_gap <= defaults.min_building_gap) {
      os << "two buildings are only " << s.min_building_gap << " apart";
      add(os.str());
    }
    if (s.max_nearest_building_gap >= defaults.max_building_gap) {
      os.str("");
      os << "a building is " << s.max_nearest_building_gap << " from its nearest neighbour";
      add(os.str());
    }
  }
  if (w.kind == core::WorldKind::kGuidedMaze) {
    if (w.guide_path.empty()) add("the maze has no guiding path");
    for (size_t i = 0; i + 1 < w.guide_path.size(); ++i)
      for (int k = 0; k <= 10; ++k) {  // the path must stay in the corridors
        const core::Vec2 p = w.guide_path[i] + (w.guide_path[i + 1] - w.guide_path[i]) * (k / 10.0);
        if (core::SignedDistance(w, p, false) < w.guide_path_width / 2) {
          add("the guiding path leaves the corridor near (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
          i = w.guide_path.size();
          break;
        }
      }
  }
  return problems;
}

}  // namespace toponav::experiments

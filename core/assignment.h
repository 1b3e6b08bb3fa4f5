#pragma once
// Minimum-cost one-to-one assignment (the Hungarian algorithm), used by the map's data association and by
// the team planner.
#include <vector>

namespace toponav::core {

// Minimum-cost one-to-one assignment of rows to columns (rows <= columns); returns the column of each row.
std::vector<int> SolveAssignment(const std::vector<std::vector<double>>& cost);

}  // namespace toponav::core

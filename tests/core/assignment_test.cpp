#include "core/assignment.h"

#include <gtest/gtest.h>

namespace toponav::core {
namespace {

TEST(SolveAssignment, FindsTheMinimumCostOneToOneAssignment) {
  const std::vector<std::vector<double>> cost{{4, 1, 3}, {2, 0, 5}, {3, 2, 2}};
  const auto col = SolveAssignment(cost);
  EXPECT_EQ(col, (std::vector<int>{1, 0, 2}));
  const auto rect = SolveAssignment({{5, 1, 9, 9}, {1, 9, 9, 9}});
  EXPECT_EQ(rect, (std::vector<int>{1, 0}));
  // Large sentinel costs for forbidden pairs, as the association uses them.
  const double big = 1e9;
  const auto gated = SolveAssignment({{2.0, big, 9.21, big}, {1.0, big, big, 9.21}});
  EXPECT_EQ(gated, (std::vector<int>{2, 0}));
}

}  // namespace
}  // namespace toponav::core

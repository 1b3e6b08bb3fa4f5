#pragma once
// The expected cost of trying frontiers (subgoals) in order, and the order that minimizes it (Learned
// Subgoal Planning, paper Sec. V; lsp.md §1).  Each frontier f has a probability Ps(f) that the goal is
// reached through it, a success cost Rs(f) = d_goal(f) + delta_success(f) (the optimistic distance from f to
// the goal plus what the real way costs beyond it) and an exploration cost Re(f) (going in, finding a dead
// end and coming back).  Trying f1, f2, ... costs
//   Q = sum_i [prod_{j<i} (1 - P_j)] * (t_i + P_i Rs_i + (1 - P_i) Re_i),  t_1 = d_robot(f1), t_i = D(f_{i-1}, f_i)
// (no term for "every frontier fails", as in the reference).  The prefix weight depends only on the set
// already tried, so the best order is found exactly by dynamic programming over (tried set, last frontier)
// in O(2^n n^2) instead of the reference's factorial branch and bound.
#include <vector>

namespace toponav::planning {

// What is known or estimated about one frontier.
struct SubgoalProperties {
  double ps = 1.0;             // probability the goal is reachable through it, [0, 1]
  double delta_success = 0.0;  // success cost beyond the optimistic goal distance, >= 0
  double exploration = 0.0;    // exploration cost if it fails, >= 0
};

// The same properties inside their valid ranges: Ps in [0, 1], costs >= 0 (NaN becomes the default: Ps 1, cost
// 0, the optimistic assumption).  Network outputs go through this before planning.
SubgoalProperties Clamped(const SubgoalProperties& p);

// One ordering problem: n frontiers, their properties, and the distances (infinity: unreachable).
struct OrderingProblem {
  std::vector<SubgoalProperties> properties;
  std::vector<double> robot_cost;                 // d_robot(f): from the robot to f
  std::vector<double> goal_cost;                  // d_goal(f): optimistic, from f to the goal
  std::vector<std::vector<double>> between;       // D(f, g), symmetric
  int size() const { return int(properties.size()); }
};

struct Ordering {
  std::vector<int> order;  // frontier indices, first = the subgoal to pursue now; empty: no finite ordering
  double cost = 0.0;       // expected cost Q of the order
};

// Q of a given order (any subset of the frontiers, each at most once).
double OrderingCost(const OrderingProblem& problem, const std::vector<int>& order);

// The order of all frontiers with the least Q, exactly (dynamic programming).  At most kMaxExactFrontiers
// frontiers (the table has 2^n n entries, 8 MB at 16): pick them first with SelectFrontiers.  Frontiers with an
// infinite robot or goal cost must have been left out.  Ties go to the lower index.
constexpr int kMaxExactFrontiers = 16;
Ordering BestOrdering(const OrderingProblem& problem);
// The same by trying every permutation (tests; n <= 10).
Ordering BestOrderingByEnumeration(const OrderingProblem& problem);

// Which frontiers the planner orders, by index: the reachable ones (finite robot and goal cost) with Ps > 0;
// when there are more than 'max_frontiers', the half (rounded up) with the least optimistic cost through them
// (d_robot + d_goal + delta_success), then the rest by Ps, highest first (ties: lower cost).  The result is
// sorted ascending.
std::vector<int> SelectFrontiers(const OrderingProblem& problem, int max_frontiers);

// The problem restricted to 'indices' (in that order).
OrderingProblem Restrict(const OrderingProblem& problem, const std::vector<int>& indices);

}  // namespace toponav::planning

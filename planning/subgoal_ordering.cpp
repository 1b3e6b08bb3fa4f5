#include "planning/subgoal_ordering.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "core/error.h"

namespace toponav::planning {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double NonNegative(double v) { return std::isnan(v) ? 0.0 : std::max(0.0, v); }

// The cost of trying f once the robot is there: success or exploration, weighted by Ps.
double Attempt(const OrderingProblem& p, int f) {
  const SubgoalProperties& s = p.properties[size_t(f)];
  return s.ps * (p.goal_cost[size_t(f)] + s.delta_success) + (1.0 - s.ps) * s.exploration;
}

void CheckSizes(const OrderingProblem& p) {
  const size_t n = p.properties.size();
  TOPONAV_CHECK(p.robot_cost.size() == n && p.goal_cost.size() == n && p.between.size() == n,
                "ordering problem with " << n << " frontiers but " << p.robot_cost.size() << " robot, "
                                         << p.goal_cost.size() << " goal and " << p.between.size() << " pair costs");
  for (const auto& row : p.between) TOPONAV_CHECK(row.size() == n, "pair cost row of " << row.size() << " for " << n);
}

}  // namespace

SubgoalProperties Clamped(const SubgoalProperties& p) {
  SubgoalProperties c;
  c.ps = std::isnan(p.ps) ? 1.0 : std::clamp(p.ps, 0.0, 1.0);
  c.delta_success = NonNegative(p.delta_success);
  c.exploration = NonNegative(p.exploration);
  return c;
}

double OrderingCost(const OrderingProblem& p, const std::vector<int>& order) {
  CheckSizes(p);
  double cost = 0.0, weight = 1.0;
  for (size_t i = 0; i < order.size(); ++i) {
    const int f = order[i];
    TOPONAV_CHECK(f >= 0 && f < p.size(), "frontier " << f << " of " << p.size());
    const double travel = i == 0 ? p.robot_cost[size_t(f)] : p.between[size_t(order[i - 1])][size_t(f)];
    cost += weight * (travel + Attempt(p, f));
    weight *= 1.0 - p.properties[size_t(f)].ps;
  }
  return cost;
}

Ordering BestOrdering(const OrderingProblem& p) {
  CheckSizes(p);
  const int n = p.size();
  TOPONAV_CHECK(n <= kMaxExactFrontiers, n << " frontiers to order exactly (at most " << kMaxExactFrontiers << ")");
  if (n == 0) return {};
  std::vector<double> attempt(static_cast<size_t>(n)), fail(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    attempt[size_t(f)] = Attempt(p, f);
    fail[size_t(f)] = 1.0 - p.properties[size_t(f)].ps;
  }
  // value[S * n + last]: the least expected cost of trying the frontiers outside S, starting at 'last' (in S),
  // per unit of probability that every frontier of S failed.  next: the frontier tried after 'last'.
  const uint32_t full = (1u << n) - 1;
  std::vector<double> value(size_t(full + 1) * size_t(n), 0.0);
  std::vector<int8_t> next(value.size(), -1);
  for (uint32_t s = full - 1; s >= 1; --s) {
    for (int last = 0; last < n; ++last) {
      if (!(s >> last & 1u)) continue;
      double best = kInf;
      int8_t arg = -1;
      const std::vector<double>& from = p.between[size_t(last)];
      for (uint32_t rest = full & ~s; rest; rest &= rest - 1) {
        const int g = __builtin_ctz(rest);
        const double c =
            from[size_t(g)] + attempt[size_t(g)] + fail[size_t(g)] * value[size_t(s | 1u << g) * size_t(n) + size_t(g)];
        if (c < best) best = c, arg = int8_t(g);
      }
      value[size_t(s) * size_t(n) + size_t(last)] = best;
      next[size_t(s) * size_t(n) + size_t(last)] = arg;
    }
  }
  Ordering out;
  out.cost = kInf;
  int first = -1;
  for (int f = 0; f < n; ++f) {
    const double c = p.robot_cost[size_t(f)] + attempt[size_t(f)] +
                     fail[size_t(f)] * value[(size_t(1) << f) * size_t(n) + size_t(f)];
    if (c < out.cost) out.cost = c, first = f;
  }
  if (first < 0) return {};
  uint32_t s = 1u << first;
  for (int f = first; f >= 0; f = next[size_t(s) * size_t(n) + size_t(f)], s |= f >= 0 ? 1u << f : 0u)
    out.order.push_back(f);
  return out;
}

Ordering BestOrderingByEnumeration(const OrderingProblem& p) {
  CheckSizes(p);
  TOPONAV_CHECK(p.size() <= 10, p.size() << " frontiers to enumerate (at most 10)");
  std::vector<int> order(size_t(p.size()));
  std::iota(order.begin(), order.end(), 0);
  Ordering best;
  best.cost = kInf;
  do {
    const double c = OrderingCost(p, order);
    if (c < best.cost) best = {order, c};
  } while (std::next_permutation(order.begin(), order.end()));
  if (!std::isfinite(best.cost)) return {};
  return best;
}

std::vector<int> SelectFrontiers(const OrderingProblem& p, int max_frontiers) {
  CheckSizes(p);
  TOPONAV_CHECK(max_frontiers >= 1, "max_frontiers " << max_frontiers);
  std::vector<int> usable;
  for (int f = 0; f < p.size(); ++f)
    if (std::isfinite(p.robot_cost[size_t(f)]) && std::isfinite(p.goal_cost[size_t(f)]) &&
        p.properties[size_t(f)].ps > 0)
      usable.push_back(f);
  if (int(usable.size()) <= max_frontiers) return usable;
  const auto optimistic = [&](int f) {
    return p.robot_cost[size_t(f)] + p.goal_cost[size_t(f)] + p.properties[size_t(f)].delta_success;
  };
  std::stable_sort(usable.begin(), usable.end(), [&](int a, int b) { return optimistic(a) < optimistic(b); });
  const auto cheapest_end = usable.begin() + (max_frontiers + 1) / 2;
  std::stable_sort(cheapest_end, usable.end(),
                   [&](int a, int b) { return p.properties[size_t(a)].ps > p.properties[size_t(b)].ps; });
  usable.resize(size_t(max_frontiers));
  std::sort(usable.begin(), usable.end());
  return usable;
}

OrderingProblem Restrict(const OrderingProblem& p, const std::vector<int>& indices) {
  CheckSizes(p);
  OrderingProblem r;
  for (int i : indices) {
    r.properties.push_back(p.properties[size_t(i)]);
    r.robot_cost.push_back(p.robot_cost[size_t(i)]);
    r.goal_cost.push_back(p.goal_cost[size_t(i)]);
    std::vector<double> row;
    for (int j : indices) row.push_back(p.between[size_t(i)][size_t(j)]);
    r.between.push_back(std::move(row));
  }
  return r;
}

}  // namespace toponav::planning

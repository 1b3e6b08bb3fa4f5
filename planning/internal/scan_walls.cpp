#include "planning/internal/scan_walls.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace toponav::planning {

using core::Vec2;

namespace {

// Douglas-Peucker: the indices of chain[first..last] to keep, 'first' and 'last' included, so that no point lies
// farther than 'tolerance' from the segment between the kept points round it.
void Simplify(const std::vector<Vec2>& chain, size_t first, size_t last, double tolerance, std::vector<size_t>* kept) {
  double worst = -1.0;
  size_t at = first;
  for (size_t i = first + 1; i < last; ++i) {
    const double d = core::DistanceToSegment(chain[i], {chain[first], chain[last]});
    if (d > worst) worst = d, at = i;
  }
  if (worst > tolerance) {
    Simplify(chain, first, at, tolerance, kept);
    Simplify(chain, at, last, tolerance, kept);
    return;
  }
  if (kept->empty() || kept->back() != first) kept->push_back(first);
  kept->push_back(last);
}

void AddChain(const std::vector<Vec2>& chain, double tolerance, std::vector<core::Segment2>* walls) {
  if (chain.size() < 2) return;
  std::vector<size_t> kept;
  Simplify(chain, 0, chain.size() - 1, tolerance, &kept);
  for (size_t k = 1; k < kept.size(); ++k) {
    const Vec2 &a = chain[kept[k - 1]], &b = chain[kept[k]];
    if (core::Distance(a, b) > 1e-6) walls->push_back({a, b});  // no wall of zero length
  }
}

}  // namespace

std::vector<core::Segment2> ScanWalls(const Vec2& origin, const std::vector<ScanRay>& rays, double max_range,
                                      double link, double tolerance) {
  const size_t n = rays.size();
  std::vector<std::optional<Vec2>> hits(n);
  for (size_t i = 0; i < n; ++i)
    if (rays[i].range < max_range)
      hits[i] = origin + Vec2{std::cos(rays[i].angle), std::sin(rays[i].angle)} * rays[i].range;
  const auto linked = [&](size_t i, size_t j) {  // j follows i
    return hits[i] && hits[j] && core::Distance(*hits[i], *hits[j]) <= link;
  };
  // Start the walk round at a ray whose link to the one before it is broken (any ray when none is).
  size_t start = 0;
  for (size_t i = 0; i < n; ++i)
    if (!linked((i + n - 1) % n, i)) {
      start = i;
      break;
    }
  std::vector<core::Segment2> walls;
  std::vector<Vec2> chain;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = (start + k) % n;
    if (k > 0 && !linked((i + n - 1) % n, i)) AddChain(chain, tolerance, &walls), chain.clear();
    if (hits[i]) chain.push_back(*hits[i]);
  }
  if (n > 2 && linked((start + n - 1) % n, start) && hits[start]) chain.push_back(*hits[start]);  // a full ring
  AddChain(chain, tolerance, &walls);
  return walls;
}

void ScanWallSet::Add(const std::vector<core::Segment2>& walls) {
  for (const auto& w : walls)
    if (!Merge(w)) walls_.push_back(w);
}

// Lengthens the first kept segment 's' lies along (both ends within tolerance of its line, its span along the
// line overlapping or within link of the kept one's); false if none.
bool ScanWallSet::Merge(const core::Segment2& s) {
  for (auto& k : walls_) {
    const Vec2 d = k.b - k.a;
    const double len = core::Norm(d);
    if (len < 1e-9) continue;
    const Vec2 u = d / len;
    const auto off = [&](const Vec2& p) { return std::abs(core::Cross(u, p - k.a)); };
    if (off(s.a) > tolerance_ || off(s.b) > tolerance_) continue;
    const double ta = core::Dot(s.a - k.a, u), tb = core::Dot(s.b - k.a, u);
    const double lo = std::min(ta, tb), hi = std::max(ta, tb);
    if (hi < -link_ || lo > len + link_) continue;
    const double from = std::min(0.0, lo), to = std::max(len, hi);
    k = {k.a + u * from, k.a + u * to};
    return true;
  }
  return false;
}

}  // namespace toponav::planning

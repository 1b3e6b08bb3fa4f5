#include "sim/render.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "core/detection.h"
#include "core/error.h"
#include "sim/raycast.h"
#include "sim/worlds.h"
#include "tests/testing/worlds.h"

namespace toponav::sim {
namespace {

const int kHorizonRow = 63;  // just above the horizon (rows 63/64 straddle elevation 0)

int WallPixels(const Panorama& p, int32_t id) {
  int n = 0;
  for (int32_t v : p.ids) n += v == id;
  return n;
}

// The column boundary (continuous, circular) nearest to 'expected' where the horizon row switches between
// the two walls of vertex 'v', or from one of them to anything else (a wall seen edge-on can be thinner than
// a pixel, so the other side may show what lies behind it).
double TransitionColumn(const Panorama& p, const VisibleVertex& v, int ring_size, double expected) {
  const int32_t a = WallId(v.ref.ring, (v.ref.index + ring_size - 1) % ring_size), b = WallId(v.ref.ring, v.ref.index);
  double best = -1, best_diff = 1e9;
  for (int c = 0; c < p.width; ++c) {
    const int32_t x = p.ids[size_t(kHorizonRow) * p.width + c],
                  y = p.ids[size_t(kHorizonRow) * p.width + (c + 1) % p.width];
    const bool xa = x == a || x == b, ya = y == a || y == b;
    if (x == y || (!xa && !ya)) continue;
    double diff = std::abs(c + 0.5 - expected);
    diff = std::min(diff, p.width - diff);
    if (diff < best_diff) {
      best_diff = diff;
      best = c + 0.5;
    }
  }
  return best;
}

TEST(Renderer, WallCornerColumnMatchesRayCastBearing) {
  int checked = 0;
  for (auto kind : {core::WorldKind::kLabyrinth, core::WorldKind::kGuidedMaze})
    for (uint64_t seed = 0; seed < 4; ++seed) {
      const core::World w = GenerateWorld(kind, {}, seed);
      const Renderer renderer(w, {});
      const RayCaster caster(w);
      const auto rings = core::MapRings(w);
      for (double yaw : {0.0, 1.0, -2.5}) {
        const core::Pose2 pose{w.start.x, w.start.y, yaw};
        const Panorama p = renderer.Render(pose, kRenderIds);
        for (const auto& v : caster.VisibleVertices(pose, 80.0)) {
          if (v.label != core::VertexLabel::kCorner) continue;
          const double expected = (core::WrapAngle(v.bearing) + core::kPi) * p.width / (2 * core::kPi);
          const double col = TransitionColumn(p, v, int(rings[size_t(v.ref.ring)]->size()), expected);
          ASSERT_GE(col, 0) << "corner not found in the image, " << core::ToString(kind) << " seed " << seed;
          double diff = std::abs(col - expected);
          diff = std::min(diff, p.width - diff);
          EXPECT_LE(diff, 1.0) << core::ToString(kind) << " seed " << seed << " yaw " << yaw;
          ++checked;
        }
      }
    }
  EXPECT_GT(checked, 20);
}

TEST(Renderer, HorizonDepthMatchesRayCaster) {
  const core::World w = GenerateLabyrinth({}, 2);
  const Renderer renderer(w, {});
  const RayCaster caster(w);
  const core::Pose2 pose = w.start;
  const Panorama p = renderer.Render(pose, kRenderDepth);
  const auto scan = caster.DepthScan(pose, p.width, 1e4, /*include_clutter=*/false);
  const double el = (kHorizonRow + 0.5 - p.height / 2.0) * (core::kPi / 2) / p.height;  // magnitude
  int good = 0;
  for (int c = 0; c < p.width; ++c) {
    const double rendered = p.depth[size_t(kHorizonRow) * p.width + c] * std::cos(el);
    good += std::abs(rendered - scan[size_t(c)]) < 0.02 * scan[size_t(c)] + 0.05;
  }
  EXPECT_GE(good, p.width - 8) << "only a few columns right at corners may differ";
}

TEST(Renderer, SameSeedGivesIdenticalBytes) {
  const core::World w = GenerateOfficePark({}, 5);
  const Renderer a(w, {}), b(w, {});
  const core::Pose2 pose = w.start;
  const Panorama pa = a.Render(pose), pb = b.Render(pose), pa2 = a.Render(pose);
  EXPECT_EQ(pa.rgb, pb.rgb);
  EXPECT_EQ(pa.rgb, pa2.rgb);
  const Renderer other(GenerateOfficePark({}, 6), {});
  EXPECT_NE(other.Render(pose).rgb, pa.rgb);
}

TEST(Renderer, NearbyWallFillsMoreOfTheImageThanAFarOne) {
  const core::World room = testing::RoomWorld(100, 100);
  const Renderer renderer(room, {});
  // Edge 1 of the boundary is the wall x = 100.
  const Panorama near = renderer.Render({95, 50, 0}, kRenderIds), far = renderer.Render({40, 50, 0}, kRenderIds);
  EXPECT_GT(WallPixels(near, WallId(0, 1)), 2 * WallPixels(far, WallId(0, 1)));
}

TEST(Renderer, GuidingPathIsVisibleFromAPoseOnIt) {
  const core::World maze = GenerateGuidedMaze({}, 3);
  const Renderer renderer(maze, {});
  const Panorama p = renderer.Render(maze.start);
  int green = 0;
  for (int r = p.height / 2; r < p.height; ++r)
    for (int c = 0; c < p.width; ++c) green += p.g(r, c) > p.r(r, c) + 50 && p.g(r, c) > p.b(r, c) + 50;
  EXPECT_GT(green, 200);
  // ... and nothing else in a labyrinth is that green.
  const core::World lab = GenerateLabyrinth({}, 3);
  const Panorama q = Renderer(lab, {}).Render(lab.start);
  int lab_green = 0;
  for (int r = 0; r < q.height; ++r)
    for (int c = 0; c < q.width; ++c) lab_green += q.g(r, c) > q.r(r, c) + 50 && q.g(r, c) > q.b(r, c) + 50;
  EXPECT_EQ(lab_green, 0);
}

TEST(Renderer, ClutterHasItsOwnIds) {
  core::World w = testing::RoomWorld(60, 60);
  w.clutter.push_back({core::ClutterShape::kBox, {40, 30}, 2.0, 0.3, 12.0});
  const Panorama p = Renderer(w, {}).Render({30, 30, 0}, kRenderIds | kRenderDepth);
  EXPECT_GT(WallPixels(p, ClutterId(0)), 50);
  EXPECT_LT(p.depth[size_t(kHorizonRow) * p.width + p.width / 2], 10.0);  // straight ahead: the box at ~8
}

TEST(Renderer, RendersFromSeveralThreadsWithIdenticalResults) {
  const core::World w = GenerateLabyrinth({}, 8);
  const Renderer renderer(w, {});
  const Panorama reference = renderer.Render(w.start);
  std::vector<Panorama> results(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) threads.emplace_back([&, t] { results[size_t(t)] = renderer.Render(w.start); });
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r.rgb, reference.rgb);
}

TEST(Renderer, BadResolutionIsAClearError) {
  RenderOptions o;
  o.width = 510;
  try {
    Renderer r(testing::RoomWorld(10, 10), o);
    FAIL();
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(e.key(), "render.width");
  }
  o = {};
  o.camera_height = 40;  // above the ceiling
  EXPECT_THROW(Renderer(testing::RoomWorld(10, 10), o), core::ConfigError);
}

}  // namespace
}  // namespace toponav::sim

#include "sim/training_data.h"

#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "tests/testing/training_data.h"
#include "sim/raycast.h"

namespace toponav::sim {
namespace {

DatagenOptions Tiny() { return testing::TinyDatagen(); }

TEST(TrainingData, SplitsComeFromDisjointTuningSeedsAndBenchmarkSeedsAreRefused) {
  const DatagenOptions o = Tiny();
  const auto train = ListSamples(o, Split::kTrain), val = ListSamples(o, Split::kVal);
  EXPECT_EQ(train.size(), 2u * 2u * 3u) << "seeds x kinds x samples";
  EXPECT_EQ(val.size(), 1u * 2u * 3u);
  std::set<uint64_t> train_seeds;
  for (const auto& s : train) train_seeds.insert(s.world_seed);
  for (const auto& s : val) EXPECT_FALSE(train_seeds.count(s.world_seed));
  DatagenOptions overlap = o;
  overlap.val_first_seed = 4;
  EXPECT_THROW(overlap.Validate(), core::ConfigError);
  DatagenOptions benchmark = o;
  benchmark.val_first_seed = 9999;
  benchmark.val_num_seeds = 2;  // 9999 and 10000
  EXPECT_THROW(benchmark.Validate(), core::ConfigError);
}

TEST(TrainingData, ASampleIsAPureFunctionOfItsIdWithLabelsFromTheRayCaster) {
  const SampleId id{Split::kTrain, core::WorldKind::kLabyrinth, 3, 1};
  const core::RangeBearingGrid grid;
  const WorldSampler a(id.kind, id.world_seed, {}, {}, grid, Tiny()), b(id.kind, id.world_seed, {}, {}, grid, Tiny());
  const Sample s = a.Make(id), t = b.Make(id);
  EXPECT_EQ(s.pose.x, t.pose.x);
  EXPECT_EQ(s.pose.yaw, t.pose.yaw);
  EXPECT_EQ(s.image.rgb, t.image.rgb);
  EXPECT_EQ(s.labels.cells, t.labels.cells);
  EXPECT_NE(a.Make({Split::kTrain, id.kind, 3, 2}).pose.x, s.pose.x) << "another index, another pose";
  const core::World w = GenerateWorld(id.kind, {}, id.world_seed);
  EXPECT_GE(core::SignedDistance(w, s.pose.position()), 2.0);
  const RayCaster caster(w);
  EXPECT_EQ(s.labels.cells, RasterizeVertexLabels(caster.VisibleVertices(s.pose, grid.max_range), grid).cells);
  EXPECT_GT(s.labels.num_vertices(), 0);
  EXPECT_EQ(s.image.width, 512);
}

TEST(TrainingData, ANearWallFractionDrawsAboutThatShareOfPosesNextToBuildings) {
  const core::World w = GenerateWorld(core::WorldKind::kOfficePark, {}, 7);
  DatagenOptions uniform = Tiny(), near = Tiny();
  near.near_wall_fraction = 0.5;
  near.near_wall_clearance = 6.0;
  int close_uniform = 0, close_near = 0;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    const SampleId id{Split::kTrain, core::WorldKind::kOfficePark, 7, i};
    const double du = core::SignedDistance(w, SamplePose(w, id, uniform).position(), true);
    const double dn = core::SignedDistance(w, SamplePose(w, id, near).position(), true);
    EXPECT_GE(dn, near.min_clearance);
    close_uniform += du <= 6.0;
    close_near += dn <= 6.0;
  }
  EXPECT_LT(close_uniform, n / 5) << "open ground: few uniform poses lie next to a building";
  EXPECT_GT(close_near, n / 2 - 25) << "about half the poses are drawn next to one";
  near.near_wall_clearance = near.min_clearance;
  EXPECT_THROW(near.Validate(), core::ConfigError);
}

}  // namespace
}  // namespace toponav::sim

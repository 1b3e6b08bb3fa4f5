#include "learning/trainer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/detection.h"
#include "core/error.h"
#include "sim/render.h"
#include "sim/worlds.h"
#include "tests/learning/rendered_examples.h"

namespace toponav::learning {
namespace {

namespace fs = std::filesystem;

sim::DatagenOptions TinyData() {
  sim::DatagenOptions d;
  d.kinds = {core::WorldKind::kLabyrinth};
  d.train_first_seed = 1;
  d.train_num_seeds = 1;
  d.val_first_seed = 6000;
  d.val_num_seeds = 1;
  d.samples_per_world = 2;
  return d;
}

TrainOptions TinyTraining(int steps) {
  TrainOptions o;
  o.width = 0.125;
  o.batch_size = 2;
  o.steps = steps;
  o.validate_every = 2;
  return o;
}

TEST(Trainer, AKilledRunResumesFromItsCheckpointAndKeepsTheBestModel) {
  const std::string dir = (fs::temp_directory_path() / ("toponav_train_" + std::to_string(::getpid()))).string();
  fs::remove_all(dir);
  int reports = 0;
  const TrainResult first = Train(
      TinyData(), {}, {}, TinyTraining(4), dir, false, [&](const TrainProgress&) { ++reports; }, 1);
  EXPECT_EQ(first.resumed_from, 0);
  EXPECT_EQ(reports, 4);
  EXPECT_EQ(first.train_samples, 2);
  EXPECT_TRUE(fs::exists(fs::path(dir) / "model.pt"));
  // "Killed" after step 4: the same command with more steps goes on from there.
  const TrainResult second = Train(TinyData(), {}, {}, TinyTraining(6), dir, false, nullptr);
  EXPECT_EQ(second.resumed_from, 4);
  EXPECT_GE(second.best_step, 2);
  const VertexModel best = VertexModel::Load(second.model_path);
  EXPECT_NE(best.notes().find("\"val_loss\""), std::string::npos) << "the model carries its data and metrics";
  EXPECT_NE(best.notes().find("\"train_seeds\""), std::string::npos);
  // Other options in the same directory: refused, unless fresh.
  TrainOptions wider = TinyTraining(6);
  wider.width = 0.25;
  EXPECT_THROW(Train(TinyData(), {}, {}, wider, dir, false, nullptr), core::DataError);
  EXPECT_EQ(Train(TinyData(), {}, {}, TinyTraining(2), dir, true, nullptr).resumed_from, 0);
  fs::remove_all(dir);
}

// A black panorama with one white pixel (row 5, column 40: label column 10), a vertex labelled 'cell' in label
// row 3, column 10, the goal 50 away along that column, and the subgoal band.
TrainingExample OneVertexExample(uint8_t cell) {
  TrainingExample e;
  e.image.width = 512;
  e.image.height = 128;
  e.image.rgb.assign(size_t(3 * 512 * 128), 0);
  e.image.rgb[3 * (5 * 512 + 40)] = 255;
  e.labels.cells.assign(e.labels.grid.size(), 0);
  e.labels.cells[e.labels.grid.Index(3, 10)] = cell;
  e.goal = {50.0, e.labels.grid.ColBearing(10)};
  e.subgoal = testing::SubgoalBand();
  return e;
}

TEST(Trainer, ARolledExampleTurnsItsImageVertexLabelsGoalAndSubgoalLabelsTogether) {
  TrainingExample e = OneVertexExample(2);
  e.subgoal->mask.assign(e.subgoal->grid.size(), 0);
  e.subgoal->mask[e.subgoal->grid.Index(7, 20)] = 1;
  e.subgoal->ps[e.subgoal->grid.Index(7, 20)] = 0.5f;
  for (int k : {7, 120}) {
    const TrainingExample r = Rolled(e, k);
    const int col = (10 + k) % 128;
    EXPECT_EQ(r.image.rgb[3 * (5 * 512 + 4 * col)], 255) << k;
    EXPECT_EQ(r.labels.cells[r.labels.grid.Index(3, col)], 2) << k;
    EXPECT_EQ(r.labels.grid.BearingCol(r.goal.bearing), col) << "the goal turns with the image";
    EXPECT_DOUBLE_EQ(r.goal.range, 50.0);
    EXPECT_EQ(r.subgoal->mask[r.subgoal->grid.Index(7, 2 * col)], 1) << k;
    EXPECT_EQ(r.subgoal->ps[r.subgoal->grid.Index(7, 2 * col)], 0.5f) << k;
    EXPECT_EQ(r.subgoal->mask[r.subgoal->grid.Index(7, 20)], 0) << k;
  }
}

TEST(Trainer, AMirroredExampleNegatesBearingsSwapsGapLabelsAndMirroredTwiceIsItself) {
  TrainingExample e = OneVertexExample(1 + uint8_t(core::VertexLabel::kRightGap));
  e.labels.cells[e.labels.grid.Index(4, 0)] = 1 + uint8_t(core::VertexLabel::kCorner);
  for (int col = 100; col < 256; ++col) e.subgoal->mask[e.subgoal->grid.Index(10, col)] = 0;
  const TrainingExample m = Mirrored(e);
  EXPECT_EQ(m.image.rgb[3 * (5 * 512 + 512 - 40)], 255);
  EXPECT_EQ(m.image.rgb[3 * (5 * 512 + 40)], 0);
  EXPECT_EQ(m.labels.cells[m.labels.grid.Index(3, 128 - 10)], 1 + uint8_t(core::VertexLabel::kLeftGap));
  EXPECT_EQ(m.labels.cells[m.labels.grid.Index(4, 0)], 1 + uint8_t(core::VertexLabel::kCorner))
      << "the column behind the agent (bearing pi) stays";
  EXPECT_NEAR(m.goal.bearing, -e.goal.bearing, 1e-12);
  EXPECT_EQ(m.labels.grid.BearingCol(m.goal.bearing), 128 - 10) << "the goal turns with the image";
  // The band's left half (columns below 128 lead to the goal) is now the right half, column 0 staying.
  EXPECT_EQ(m.subgoal->ps[m.subgoal->grid.Index(10, 0)], 1.0f);
  EXPECT_EQ(m.subgoal->ps[m.subgoal->grid.Index(10, 1)], 0.0f);
  EXPECT_EQ(m.subgoal->ps[m.subgoal->grid.Index(10, 255)], 1.0f);
  EXPECT_EQ(m.subgoal->exploration[m.subgoal->grid.Index(10, 200)], 0.0f);
  EXPECT_EQ(m.subgoal->delta_success[m.subgoal->grid.Index(10, 200)], 30.0f);
  EXPECT_EQ(m.subgoal->delta_success[m.subgoal->grid.Index(10, 100)], 0.0f);
  EXPECT_EQ(m.subgoal->mask[m.subgoal->grid.Index(10, 200)], 1) << "the mask covered columns 0-99";
  EXPECT_EQ(m.subgoal->mask[m.subgoal->grid.Index(10, 100)], 0);
  const TrainingExample back = Mirrored(m);
  EXPECT_EQ(back.image.rgb, e.image.rgb);
  EXPECT_EQ(back.labels.cells, e.labels.cells);
  EXPECT_EQ(back.subgoal->ps, e.subgoal->ps);
  EXPECT_EQ(back.subgoal->exploration, e.subgoal->exploration);
  EXPECT_EQ(back.subgoal->mask, e.subgoal->mask);
  EXPECT_EQ(back.subgoal->delta_success, e.subgoal->delta_success);
  EXPECT_NEAR(back.goal.bearing, e.goal.bearing, 1e-12);
}

// The world seen in a mirror: y -> -y (rings reversed to keep their orientation), the start's heading negated.
core::World Reflected(core::World w) {
  const auto flip = [](core::Ring* ring) {
    for (auto& p : *ring) p.y = -p.y;
    std::reverse(ring->begin(), ring->end());
  };
  flip(&w.boundary);
  for (auto& o : w.obstacles) flip(&o);
  for (auto& c : w.clutter) {
    c.center.y = -c.center.y;
    c.yaw = -c.yaw;
  }
  w.bounds = {{w.bounds.min.x, -w.bounds.max.y}, {w.bounds.max.x, -w.bounds.min.y}};
  w.start = {w.start.x, -w.start.y, -w.start.yaw};
  w.goal.y = -w.goal.y;
  return w;
}

// A panorama whose pixels hold the depth the renderer saw there (in whole units, at most 255): the scene's
// layout without its textures, which run the other way in a mirror.
core::Panorama DepthPicture(const core::World& w, const core::Pose2& pose) {
  core::Panorama p = sim::Renderer(w, {}).Render(pose, sim::kRenderDepth);
  p.rgb.assign(p.depth.size() * 3, 0);
  for (size_t i = 0; i < p.depth.size(); ++i) p.rgb[3 * i] = uint8_t(std::min(255.0f, p.depth[i]));
  return p;
}

TEST(Trainer, AMirroredExampleHasTheLabelsAndThePanoramaOfTheWorldInAMirror) {
  const core::World world = sim::GenerateWorld(core::WorldKind::kLabyrinth, {}, 3);
  const core::World reflected = Reflected(world);
  const testing::Rendered seen = testing::RenderAtStart(world, {0.7});
  const testing::Rendered mirror = testing::RenderAtStart(reflected, {-0.7});
  const TrainingExample e{DepthPicture(world, seen.poses[0]), seen.labels[0], {}, std::nullopt};
  const TrainingExample m = Mirrored(e);
  ASSERT_GT(e.labels.num_vertices(), 3);
  EXPECT_EQ(m.labels.cells, mirror.labels[0].cells);
  const core::Panorama want = DepthPicture(reflected, mirror.poses[0]);
  int off = 0, changed = 0;
  for (size_t i = 0; i < want.rgb.size(); i += 3) {
    off += std::abs(int(m.image.rgb[i]) - int(want.rgb[i])) > 2;
    changed += std::abs(int(e.image.rgb[i]) - int(want.rgb[i])) > 2;
  }
  EXPECT_LT(off, int(want.rgb.size() / 3 / 1000)) << "pixels more than 2 units off in depth";
  EXPECT_GT(changed, 20 * off) << "the unmirrored panorama is not the mirror world's";
}

TEST(Trainer, TrainsTheSubgoalNetworkFromAVertexModelOnExamplesGivenInMemoryWithTheVertexWeightAsked) {
  const std::string dir = (fs::temp_directory_path() / ("toponav_train_sub_" + std::to_string(::getpid()))).string();
  fs::remove_all(dir);
  const std::string vertex_path = dir + "_vertex.pt";
  VertexModel(VertexNetOptions{0.125}, 3).Save(vertex_path);
  testing::Rendered r = testing::RenderAtStart(sim::GenerateGuidedMaze({}, 4));
  TrainingSet set;
  for (size_t i = 0; i < r.images.size(); ++i)
    (i == 0 ? set.train : set.val).push_back({r.images[i], r.labels[i], {40.0, 0.3}, testing::SubgoalBand()});
  set.identity_json = R"({"mazes": "test"})";
  TrainOptions o = TinyTraining(2);
  o.subgoal = true;
  o.init_from = vertex_path;
  o.vertex_weight = 100.0;
  const TrainResult result = Train(set, o, dir, false, nullptr);
  EXPECT_EQ(result.train_samples, 1);
  const VertexModel m = VertexModel::Load(result.model_path);
  EXPECT_TRUE(m.options().subgoal);
  EXPECT_EQ(m.options().vertex_weight, 100.0) << "the loss weight travels with the model";
  EXPECT_NE(m.notes().find("\"mazes\""), std::string::npos) << "the caller's data identity is in the notes";
  EXPECT_NE(m.notes().find("init_from"), std::string::npos);
  set.val[0].subgoal.reset();
  EXPECT_THROW(Train(set, o, dir, true, nullptr), core::ConfigError) << "a subgoal run needs subgoal labels everywhere";
  o.init_from = dir + "/missing.pt";
  set.val[0].subgoal = testing::SubgoalBand();
  EXPECT_THROW(Train(set, o, dir, true, nullptr), core::DataError);
  fs::remove_all(dir);
  fs::remove(vertex_path);
}

}  // namespace
}  // namespace toponav::learning

namespace toponav::learning {
namespace {

TEST(TrainOptions, TheLearningRateIsConstantUntilDecayStartThenFallsAlongACosineToDecayTo) {
  TrainOptions o;
  o.learning_rate = 1e-3;
  o.steps = 101;
  EXPECT_DOUBLE_EQ(o.LearningRate(0), 1e-3);
  EXPECT_DOUBLE_EQ(o.LearningRate(100), 1e-3) << "decay_to 1: constant";
  o.decay_to = 0.1;
  o.decay_start = 50;
  EXPECT_DOUBLE_EQ(o.LearningRate(30), 1e-3);
  EXPECT_DOUBLE_EQ(o.LearningRate(50), 1e-3);
  EXPECT_NEAR(o.LearningRate(75), 1e-3 * (0.1 + 0.9 * 0.5), 1e-12) << "half way down the cosine";
  EXPECT_NEAR(o.LearningRate(100), 1e-4, 1e-12);
  for (int s = 51; s <= 100; ++s) EXPECT_LT(o.LearningRate(s), o.LearningRate(s - 1));
}

}  // namespace
}  // namespace toponav::learning

#include "learning/trainer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/error.h"
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

TEST(Trainer, ARolledExampleTurnsItsImageVertexLabelsGoalAndSubgoalLabelsTogether) {
  TrainingExample e;
  e.image.width = 512;
  e.image.height = 128;
  e.image.rgb.assign(size_t(3 * 512 * 128), 0);
  e.image.rgb[3 * (5 * 512 + 40)] = 255;  // row 5, column 40 (label column 10)
  e.labels.cells.assign(e.labels.grid.size(), 0);
  e.labels.cells[e.labels.grid.Index(3, 10)] = 2;
  e.goal = {50.0, e.labels.grid.ColBearing(10)};
  e.subgoal = testing::SubgoalBand();
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

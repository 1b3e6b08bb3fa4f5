#include "learning/trainer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/error.h"

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
  const TrainResult first = Train(TinyData(), {}, {}, TinyTraining(4), dir, false, [&](const TrainProgress&) { ++reports; }, 1);
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

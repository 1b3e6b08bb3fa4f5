#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "learning/learned_detector.h"
#include "learning/vertex_model.h"
#include "sim/worlds.h"
#include "tests/learning/rendered_examples.h"

namespace toponav::learning {
namespace {

namespace fs = std::filesystem;

VertexNetOptions TinySubgoal() {
  VertexNetOptions o;
  o.width = 0.125;
  o.subgoal = true;
  return o;
}

// Two maze panoramas with their vertex labels, and made-up subgoal labels (testing::SubgoalBand).
struct Examples {
  std::vector<core::Panorama> images;
  std::vector<sim::VertexLabelGrid> labels;
  std::vector<core::SubgoalLabelGrid> subgoal;
  std::vector<LabelledImage> batch() const {
    std::vector<LabelledImage> b;
    for (size_t i = 0; i < images.size(); ++i)
      b.push_back({&images[i], &labels[i], {40.0, 0.5 * double(i)}, &subgoal[i]});
    return b;
  }
};
Examples MakeExamples() {
  testing::Rendered r = testing::RenderAtStart(sim::GenerateGuidedMaze({}, 4));
  Examples e;
  e.images = std::move(r.images);
  e.labels = std::move(r.labels);
  for (size_t k = 0; k < e.images.size(); ++k) e.subgoal.push_back(testing::SubgoalBand());
  return e;
}

TEST(SubgoalModel, PredictsTheVertexGridAndTheFinerSubgoalGrid) {
  const VertexModel m(TinySubgoal(), 1);
  const Examples e = MakeExamples();
  const auto [vertex, subgoal] = m.PredictWithGoal(e.images[0], {40.0, 0.5});
  EXPECT_EQ(vertex.vertex.size(), 32u * 128u);
  EXPECT_EQ(subgoal.ps.size(), 64u * 256u);
  EXPECT_EQ(subgoal.exploration.size(), 64u * 256u);
  for (float p : subgoal.ps) ASSERT_TRUE(p >= 0.0f && p <= 1.0f);
  EXPECT_EQ(m.Predict(e.images[0]).vertex, m.PredictWithGoal(e.images[0], {}).first.vertex);
  EXPECT_THROW(VertexModel(VertexNetOptions{0.125}, 1).PredictWithGoal(e.images[0], {}), core::InternalError);
}

TEST(SubgoalModel, ATinyTrainingRunLowersTheLossAndLearnsTheLabelledSide) {
  VertexNetOptions o = TinySubgoal();
  o.vertex_weight = 1.0;  // (500 makes the vertex term swamp the subgoal terms in a run this short)
  VertexModel m(o, 2);
  const Examples e = MakeExamples();
  const double first = m.TrainStep(e.batch(), 3e-3);
  double last = first;
  for (int step = 0; step < 60; ++step) last = m.TrainStep(e.batch(), 3e-3);
  EXPECT_LT(last, 0.7 * first) << "first " << first << ", after 60 steps " << last;
  const SubgoalOutput out = m.PredictWithGoal(e.images[0], {40.0, 0.0}).second;
  EXPECT_GT(out.ps[out.grid.Index(10, 40)], out.ps[out.grid.Index(10, 200)]) << "the left half leads to the goal";
}

TEST(SubgoalModel, SaveAndLoadKeepTheExtensionAndGiveIdenticalOutputs) {
  VertexModel m(TinySubgoal(), 3);
  const Examples e = MakeExamples();
  m.TrainStep(e.batch(), 1e-3);
  const std::string path =
      (fs::temp_directory_path() / ("toponav_subgoal_" + std::to_string(::getpid()) + ".pt")).string();
  m.Save(path);
  const VertexModel loaded = VertexModel::Load(path);
  EXPECT_TRUE(loaded.options().subgoal);
  EXPECT_EQ(loaded.PredictWithGoal(e.images[1], {20.0, -1.0}).second.ps,
            m.PredictWithGoal(e.images[1], {20.0, -1.0}).second.ps);
  fs::remove(path);
}

TEST(SubgoalModel, StartedFromAVertexModelItGivesThatModelsVertexGridForAGoalAtRangeZero) {
  VertexModel vertex(VertexNetOptions{0.125}, 4);
  const Examples e = MakeExamples();
  vertex.TrainStep({{&e.images[0], &e.labels[0], {}, nullptr}}, 1e-3);  // BatchNorm statistics away from their defaults
  VertexModel sub(TinySubgoal(), 5);
  EXPECT_EQ(sub.InitFrom(VertexModel(VertexNetOptions{0.25}, 4)), 0) << "another width: nothing fits";
  const int copied = sub.InitFrom(vertex);
  EXPECT_GT(copied, 40);
  const GridOutput want = vertex.Predict(e.images[1]), got = sub.PredictWithGoal(e.images[1], {0.0, 0.0}).first;
  ASSERT_EQ(want.vertex.size(), got.vertex.size());
  for (size_t i = 0; i < want.vertex.size(); ++i) ASSERT_NEAR(want.vertex[i], got.vertex[i], 1e-5) << i;
  EXPECT_GT(std::abs(sub.PredictWithGoal(e.images[1], {60.0, 1.0}).first.vertex[100] - want.vertex[100]), 0.0)
      << "the goal's channels are its own";
}

TEST(LearnedDetector, ASubgoalModelGivenAGoalFillsTheCellsWithPsAndTheTwoCosts) {
  const VertexModel m(TinySubgoal(), 6);
  const std::string path =
      (fs::temp_directory_path() / ("toponav_subgoal_det_" + std::to_string(::getpid()) + ".pt")).string();
  m.Save(path);
  const auto detector = CreateLearnedDetector(path, {});
  const Examples e = MakeExamples();
  core::DetectionContext context{{1.0, 2.0, 0.3}, 0, core::Vec2{30.0, 40.0}};
  const core::Observation z = detector->Detect(e.images[0], context);
  EXPECT_EQ(z.subgoal.rows, 64);
  EXPECT_EQ(z.subgoal.cols, 256);
  EXPECT_EQ(z.subgoal.max_range, 100.0);
  const SubgoalOutput want = m.PredictWithGoal(e.images[0], {50.0, std::atan2(40.0, 30.0)}).second;
  for (int row : {0, 10, 63})
    for (int col : {0, 77, 255}) {
      const size_t i = want.grid.Index(row, col);
      EXPECT_FLOAT_EQ(z.subgoal.at(row, col).ps, want.ps[i]);
      EXPECT_FLOAT_EQ(z.subgoal.at(row, col).delta_success, want.delta_success[i]);
      EXPECT_FLOAT_EQ(z.subgoal.at(row, col).exploration, want.exploration[i]);
    }
  context.goal.reset();
  EXPECT_TRUE(detector->Detect(e.images[0], context).subgoal.empty()) << "no goal, no subgoal outputs";
  fs::remove(path);
}

}  // namespace
}  // namespace toponav::learning

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/error.h"
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

// Two maze panoramas with their vertex labels, and made-up subgoal labels: a band of frontier cells, the
// left half leading to the goal (Ps 1, success cost 30), the right half not (exploration cost 120).
struct Examples {
  std::vector<core::Panorama> images;
  std::vector<sim::VertexLabelGrid> labels;
  std::vector<core::SubgoalLabelGrid> subgoal;
  std::vector<LabelledImage> batch() const {
    std::vector<LabelledImage> b;
    for (size_t i = 0; i < images.size(); ++i) b.push_back({&images[i], &labels[i], {40.0, 0.5 * double(i)}, &subgoal[i]});
    return b;
  }
};
Examples MakeExamples() {
  testing::Rendered r = testing::RenderAtStart(sim::GenerateGuidedMaze({}, 4));
  Examples e;
  e.images = std::move(r.images);
  e.labels = std::move(r.labels);
  for (size_t k = 0; k < e.images.size(); ++k) {
    core::SubgoalLabelGrid s;
    s.grid = {64, 256, 100.0};
    s.mask.assign(s.grid.size(), 0);
    s.ps.assign(s.grid.size(), 0.0f);
    s.delta_success.assign(s.grid.size(), 0.0f);
    s.exploration.assign(s.grid.size(), 0.0f);
    for (int col = 0; col < 256; ++col) {
      const size_t i = s.grid.Index(10, col);
      s.mask[i] = 1;
      const bool left = col < 128;
      s.ps[i] = left ? 1.0f : 0.0f;
      s.delta_success[i] = left ? 30.0f : 0.0f;
      s.exploration[i] = left ? 0.0f : 120.0f;
    }
    e.subgoal.push_back(s);
  }
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
  const std::string path = (fs::temp_directory_path() / ("toponav_subgoal_" + std::to_string(::getpid()) + ".pt")).string();
  m.Save(path);
  const VertexModel loaded = VertexModel::Load(path);
  EXPECT_TRUE(loaded.options().subgoal);
  EXPECT_EQ(loaded.PredictWithGoal(e.images[1], {20.0, -1.0}).second.ps, m.PredictWithGoal(e.images[1], {20.0, -1.0}).second.ps);
  fs::remove(path);
}

}  // namespace
}  // namespace toponav::learning

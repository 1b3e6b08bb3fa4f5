#include "learning/vertex_model.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "learning/internal/vertex_net.h"
#include "tests/learning/rendered_examples.h"
#include "sim/raycast.h"
#include "sim/render.h"
#include "sim/worlds.h"

namespace toponav::learning {
namespace {

namespace fs = std::filesystem;

VertexNetOptions Tiny() {
  VertexNetOptions o;
  o.width = 0.125;
  return o;
}

// Two panoramas of a labyrinth with their ray-cast labels.
struct Examples {
  std::vector<core::Panorama> images;
  std::vector<sim::VertexLabelGrid> labels;
  std::vector<LabelledImage> batch() const {
    std::vector<LabelledImage> b;
    for (size_t i = 0; i < images.size(); ++i) b.push_back({&images[i], &labels[i], {}, nullptr});
    return b;
  }
};
Examples MakeExamples() {
  testing::Rendered r = testing::RenderAtStart(sim::GenerateLabyrinth({}, 4));
  Examples e;
  e.images = std::move(r.images);
  e.labels = std::move(r.labels);
  return e;
}

std::string TempFile(const std::string& name) {
  return (fs::temp_directory_path() / ("toponav_model_" + std::to_string(::getpid()) + "_" + name)).string();
}

TEST(VertexModel, PredictsAProbabilityGridOfTheSensorsShape) {
  const VertexModel m(Tiny(), 1);
  const Examples e = MakeExamples();
  const GridOutput out = m.Predict(e.images[0]);
  ASSERT_EQ(out.vertex.size(), 32u * 128u);
  ASSERT_EQ(out.labels.size(), 4u * 32u * 128u);
  for (float v : out.vertex) ASSERT_TRUE(v > 0.0f && v < 1.0f);
  for (size_t i = 0; i < out.vertex.size(); ++i)
    ASSERT_NEAR(out.labels[4 * i] + out.labels[4 * i + 1] + out.labels[4 * i + 2] + out.labels[4 * i + 3], 1.0f, 1e-5);
  core::Panorama small = e.images[0];
  small.width = 256;
  EXPECT_THROW(m.Predict(small), core::DataError);
  EXPECT_GT(VertexModel({}, 1).num_parameters(), 2'000'000) << "the paper-size net (~2.1 M parameters)";
}

TEST(VertexModel, ATinyTrainingRunLowersTheLoss) {
  VertexModel m(Tiny(), 2);
  const Examples e = MakeExamples();
  const double first = m.TrainStep(e.batch(), 3e-3);
  double last = first;
  for (int step = 0; step < 40; ++step) last = m.TrainStep(e.batch(), 3e-3);
  EXPECT_LT(last, 0.7 * first) << "first " << first << ", after 40 steps " << last;
}

TEST(VertexModel, ANewLearningRateKeepsAdamsMoments) {
  // A decaying rate changes every step; restarting Adam each time (its first step moves every weight by the
  // full rate) would make a rate lower by a hair train very differently from the constant one.
  const Examples e = MakeExamples();
  VertexModel constant(Tiny(), 4), decaying(Tiny(), 4);
  const auto both = e.batch();
  for (int step = 0; step < 12; ++step) {  // alternating batches: gradients that Adam's moments average
    const std::vector<LabelledImage> one{both[size_t(step % 2)]};
    constant.TrainStep(one, 1e-3);
    decaying.TrainStep(one, 1e-3 * (1.0 - 1e-6 * step));
  }
  const auto a = constant.Predict(e.images[1]).vertex, b = decaying.Predict(e.images[1]).vertex;
  float worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  EXPECT_LT(worst, 1e-3f);
}

TEST(VertexModel, SaveAndLoadGiveIdenticalOutputs) {
  VertexModel m(Tiny(), 3);
  const Examples e = MakeExamples();
  m.TrainStep(e.batch(), 1e-3);  // running statistics and weights away from their initial values
  const std::string path = TempFile("saved.pt");
  m.Save(path, "trained on two panoramas");
  const VertexModel loaded = VertexModel::Load(path);
  EXPECT_EQ(loaded.options(), m.options());
  EXPECT_EQ(loaded.notes(), "trained on two panoramas");
  EXPECT_EQ(loaded.Predict(e.images[1]).vertex, m.Predict(e.images[1]).vertex);
  fs::remove(path);
}

TEST(VertexModel, AMissingTruncatedForeignMismatchedOrNewerFileIsADataErrorNamingIt) {
  const std::string good = TempFile("good.pt"), cut = TempFile("cut.pt"), text = TempFile("text.pt"),
                    lying = TempFile("lying.pt"), newer = TempFile("newer.pt");
  VertexModel(Tiny(), 4).Save(good);
  fs::copy_file(good, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, fs::file_size(good) / 2);
  std::ofstream(text) << "not a model\n";
  {  // weights of a width-0.125 net in a file that says width 0.25
    internal::VertexNet net(0.125);
    torch::serialize::OutputArchive archive;
    net->save(archive);
    archive.write("toponav_metadata", c10::IValue(std::string(R"({"format": "toponav-vertex-net-1", "width": 0.25})")));
    archive.save_to(lying);
  }
  {  // a key a later build may write to change what the outputs mean
    internal::VertexNet net(0.25);
    torch::serialize::OutputArchive archive;
    net->save(archive);
    archive.write("toponav_metadata",
                  c10::IValue(std::string(R"({"format": "toponav-vertex-net-1", "width": 0.25, "log_costs": true})")));
    archive.save_to(newer);
  }
  for (const auto& [path, words] : std::vector<std::pair<std::string, std::string>>{
           {TempFile("missing.pt"), "no such model file"}, {cut, "not a readable model file"},
           {text, "not a readable model file"}, {lying, "do not fit the architecture"},
           {newer, "the key 'log_costs', unknown to this toponav build"}}) {
    try {
      VertexModel::Load(path);
      ADD_FAILURE() << path << " loaded";
    } catch (const core::DataError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
  for (const auto& p : {good, cut, text, lying, newer}) fs::remove(p);
}

}  // namespace
}  // namespace toponav::learning

#include "learning/mirror_average.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "learning/learned_detector.h"
#include "learning/trainer.h"
#include "sim/worlds.h"
#include "tests/learning/rendered_examples.h"

namespace toponav::learning {
namespace {

TEST(MirrorAverage, TheMirroredPanoramaIsTheTrainingMirrorsAndMirroredTwiceIsItself) {
  const testing::Rendered r = testing::RenderAtStart(sim::GenerateGuidedMaze({}, 4), {0.4});
  const TrainingExample e{r.images[0], r.labels[0], {}, std::nullopt};
  const core::Panorama m = MirroredPanorama(r.images[0]);
  EXPECT_EQ(m.rgb, Mirrored(e).image.rgb) << "the network sees the mirror it was trained on";
  EXPECT_NE(m.rgb, r.images[0].rgb);
  EXPECT_EQ(MirroredPanorama(m).rgb, r.images[0].rgb);
}

TEST(MirrorAverage, AnOutputMirroredBackFlipsItsColumnsAndSwapsTheGapLabels) {
  GridOutput out;
  out.vertex.assign(out.grid.size(), 0.0f);
  out.labels.assign(4 * out.grid.size(), 0.0f);
  const size_t at = out.grid.Index(5, 10), mirror = out.grid.Index(5, out.grid.cols - 10);
  out.vertex[at] = 0.9f;
  for (size_t k = 0; k < 4; ++k) out.labels[4 * at + k] = 0.1f * float(k + 1);  // right gap 0.1 ... point 0.4
  const GridOutput back = MirroredBack(out);
  EXPECT_EQ(back.vertex[mirror], 0.9f);
  EXPECT_EQ(back.vertex[at], 0.0f);
  EXPECT_EQ(back.labels[4 * mirror], 0.3f) << "the left gap became a right gap";
  EXPECT_EQ(back.labels[4 * mirror + 1], 0.2f);
  EXPECT_EQ(back.labels[4 * mirror + 2], 0.1f);
  EXPECT_EQ(back.labels[4 * mirror + 3], 0.4f);
  const GridOutput mean = Mean(out, back);
  EXPECT_FLOAT_EQ(mean.vertex[at], 0.45f);
  EXPECT_FLOAT_EQ(mean.vertex[mirror], 0.45f);
}

TEST(LearnedDetector, WithMirrorAveragingTheMirroredPanoramaGivesTheMirroredDetectionsAndCells) {
  const std::string path = TOPONAV_SOURCE_DIR "/models/lsp_net_cpu.pt";  // the maze benchmark's network
  const auto detector = CreateLearnedDetector(path, {}, "", true);
  const core::Panorama image = testing::RenderAtStart(sim::GenerateGuidedMaze({}, 4)).images[0];
  const core::Observation z = detector->Detect(image, {{}, 0, core::Vec2{30.0, 40.0}});
  const core::Observation m = detector->Detect(MirroredPanorama(image), {{}, 0, core::Vec2{30.0, -40.0}});
  ASSERT_GT(z.detections.size(), 2u);
  ASSERT_EQ(z.detections.size(), m.detections.size());
  for (const core::Detection& d : z.detections) {
    const auto twin = std::find_if(m.detections.begin(), m.detections.end(), [&](const core::Detection& t) {
      return std::abs(std::remainder(t.bearing + d.bearing, 2 * M_PI)) < 1e-6 && std::abs(t.range - d.range) < 1e-6;
    });
    ASSERT_NE(twin, m.detections.end()) << "no detection at bearing " << -d.bearing;
    EXPECT_NEAR(twin->labels[0], d.labels[2], 1e-5) << "right and left gaps trade places";
    EXPECT_NEAR(twin->labels[1], d.labels[1], 1e-5);
  }
  constexpr float core::SubgoalCell::*kOutputs[] = {&core::SubgoalCell::ps, &core::SubgoalCell::delta_success,
                                                    &core::SubgoalCell::exploration};  // Ps and the two costs
  for (int col : {0, 3, 77, 128})
    for (size_t k = 0; k < 3; ++k) {
      const float want = z.subgoal.at(20, col).*kOutputs[k];
      EXPECT_NEAR(m.subgoal.at(20, (256 - col) % 256).*kOutputs[k], want, 1e-5 * std::max(1.0f, std::abs(want)))
          << col << " " << k;
    }
  const auto plain = CreateLearnedDetector(path, {})->Detect(image, {{}, 0, core::Vec2{30.0, 40.0}});
  EXPECT_GT(std::abs(plain.subgoal.at(20, 3).ps - z.subgoal.at(20, 3).ps), 1e-6) << "the mirrored pass counts";
}

}  // namespace
}  // namespace toponav::learning

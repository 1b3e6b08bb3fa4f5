#include "experiments/subgoal_eval.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace toponav::experiments {
namespace {

TEST(RocAuc, RanksPositivesAboveNegatives) {
  EXPECT_DOUBLE_EQ(RocAuc({0.1f, 0.2f, 0.8f, 0.9f}, {false, false, true, true}), 1.0);
  EXPECT_DOUBLE_EQ(RocAuc({0.1f, 0.2f, 0.8f, 0.9f}, {true, true, false, false}), 0.0);
  EXPECT_DOUBLE_EQ(RocAuc({0.1f, 0.4f, 0.35f, 0.8f}, {false, false, true, true}), 0.75);
  EXPECT_DOUBLE_EQ(RocAuc({0.5f, 0.5f, 0.5f}, {true, false, false}), 0.5) << "ties count half";
  EXPECT_DOUBLE_EQ(RocAuc({0.3f, 0.7f}, {true, true}), 0.5) << "one class only";
}

TEST(CountOrderedPairs, CountsOnlyPairsFarApartAndWhetherTheEstimatesOrderThemAlike) {
  double agree = 0.0;
  size_t pairs = 0;
  // 100 vs 120: too close to count; 100 and 120 vs 400: two pairs, one ordered right, one wrong.
  CountOrderedPairs({{100, 50}, {120, 500}, {400, 300}}, &agree, &pairs);
  EXPECT_EQ(pairs, 2u);
  EXPECT_DOUBLE_EQ(agree, 1.0);
  CountOrderedPairs({{400, 7}, {50, 7}}, &agree, &pairs);  // a tie counts half, whichever comes first
  EXPECT_EQ(pairs, 3u);
  EXPECT_DOUBLE_EQ(agree, 1.5);
  CountOrderedPairs({{30, 1}}, &agree, &pairs);
  EXPECT_EQ(pairs, 3u) << "one frontier makes no pair";
}

// The committed LSP network's scores along one run through world 'seed' of 'kind', a sample every 'every' steps.
SubgoalEval ScoreCommittedNetwork(const Config& config, core::WorldKind kind, uint64_t seed, int every) {
  LearnedSensorOptions model;
  model.model = TOPONAV_SOURCE_DIR "/models/lsp_net_cpu.pt";
  SubgoalEvalOptions o;
  o.kind = kind;
  o.seeds = {seed};
  o.every = every;
  const SubgoalEval e = EvaluateSubgoalEstimates(config, model, o);
  EXPECT_EQ(e.worlds, 1);
  EXPECT_GT(e.examples, 0);
  EXPECT_GT(e.cells, 0u);
  return e;
}

TEST(SubgoalEval, ScoresExplorationCostsAlongASearchThroughALabyrinth) {
  const SubgoalEval e = ScoreCommittedNetwork(Config{}, core::WorldKind::kLabyrinth, 4001, 25);
  EXPECT_EQ(e.positives, 0u) << "the goal is where the agent stands: no frontier leads to it";
  EXPECT_GT(e.exploration_truth, 0.0);
  EXPECT_GT(e.exploration_mae, 0.0);
  EXPECT_GE(e.exploration_order, 0.0);
  EXPECT_LE(e.exploration_order, 1.0);
}

TEST(SubgoalEval, ScoresTheCommittedNetworkOnAMaze) {
  Config config;
  config.planning.frontier_row_gap = 10;
  const SubgoalEval e = ScoreCommittedNetwork(config, core::WorldKind::kGuidedMaze, 7003, 10);
  EXPECT_LE(e.positives, e.cells);
  EXPECT_GE(e.auc, 0.0);
  EXPECT_LE(e.auc, 1.0);
  EXPECT_GT(e.cross_entropy, 0.0);
  EXPECT_EQ(e.band_cells[0] + e.band_cells[1] + e.band_cells[2], e.cells) << "every cell in one range band";
  for (double auc : e.band_auc) {
    EXPECT_GE(auc, 0.0);
    EXPECT_LE(auc, 1.0);
  }
  for (double p : {e.mean_ps_positive, e.mean_ps_negative}) {
    EXPECT_GE(p, 0.0);
    EXPECT_LE(p, 1.0);
  }
  LearnedSensorOptions vertex_model;
  vertex_model.model = TOPONAV_SOURCE_DIR "/models/vertex_net_cpu.pt";
  SubgoalEvalOptions o;
  o.seeds = {7003};
  EXPECT_THROW(EvaluateSubgoalEstimates(config, vertex_model, o), core::ConfigError)
      << "a vertex model has no subgoal cells";
}

}  // namespace
}  // namespace toponav::experiments
